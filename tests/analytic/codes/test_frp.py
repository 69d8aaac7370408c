"""FRP strips: the static LP with the strips' tension against the kinematic work of the same mechanism."""
import math
import re

import pytest

from analytic.codes.frp import BondFactors, Masonry, Strips, masonry_type, strengthened_collapse
from analytic.rocking.linkage import RigidRotation, minimised_four_bar
from specimens import get_specimen
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.piers import Piers


def _kinematic_alpha0(sc):
    """Virtual work of the LP's mechanism: (V'(0) + strip work) / horizontal work of the weights."""
    fb = sc.mechanism
    _, _, dV, S = fb.terms(0.0)
    return (dV + sc.strip_force(0.0)) / (G * -fb.direction * S)


@pytest.mark.parametrize("face", ["extrados", "intrados"])
@pytest.mark.parametrize("piers", [None, Piers(0.4, 0.144, courses=2)])
def test_static_lp_equals_the_strips_work(face, piers):
    """Static and kinematic theorems meet: the LP's multiplier with the strips equals the work balance
    of its own mechanism (strip force T at a distance c from each hinge opening on the strips' side)."""
    arch = get_specimen("Sh06-Sd015").arch
    s = Strips(100e6, 0.01e-3, 0.02, face, design_strength=10e6)  # T = 2 N (the arch weighs ~17 N)
    sc = strengthened_collapse(arch, s, piers=piers)
    assert len(sc.hinges) == 4
    assert sc.lam == pytest.approx(_kinematic_alpha0(sc), rel=1e-8)
    assert sc.strip_force(0.0) > 0  # at least one hinge opens on the strips' side


def test_weak_strips_leave_the_bare_arch_and_strong_ones_hold_it_whole():
    arch = get_specimen("Sh06-Sd015").arch
    bare = minimised_four_bar(arch).lam
    weak = strengthened_collapse(arch, Strips(1e6, 1e-6, 1e-3, design_strength=1e3))  # T = 1e-6 N
    assert weak.lam == pytest.approx(bare, rel=2e-3)  # the fine cut of 96 voussoirs per side
    strong = strengthened_collapse(arch, Strips(2000e6, 0.05e-3, 0.05))
    # the ring no longer opens; it turns whole on a springing (a joint the strips do not cross)
    assert isinstance(strong.mechanism, RigidRotation) and strong.hinges[0][0] in ("L0", "R0")
    assert strong.lam == pytest.approx(_kinematic_alpha0(strong), rel=1e-8) and strong.lam > 3 * bare


def test_bad_strips_are_refused_in_one_line():
    with pytest.raises(ArchdemInputError, match="FRP thickness must be a positive number"):
        Strips(1964e6, -1.0, 0.68)
    with pytest.raises(ArchdemInputError, match="FRP face must be extrados or intrados"):
        Strips(1964e6, 0.047e-3, 0.68, face="inside")
    with pytest.raises(ArchdemInputError, match="FRP design strength"):
        Strips(1964e6, 0.047e-3, 0.68, design_strength=math.inf)
    # rupture: carbon outdoors eta_a = 0.85, gamma_f = 1.10
    assert Strips(1964e6, 0.047e-3, 0.68).force == pytest.approx(0.85 * 1964e6 / 1.1 * 0.047e-3 * 0.68)
    with pytest.raises(ArchdemInputError, match="needs the strips' modulus"):
        Strips(1964e6, 0.047e-3, 0.68, masonry=Masonry(3e6, 0.3e6))
    with pytest.raises(ArchdemInputError, match="masonry compressive strength fm must be from"):
        Masonry(100e6, 1e6)
    with pytest.raises(ArchdemInputError, match="masonry tensile strength fmt"):
        Masonry(3e6, 2e6)
    with pytest.raises(ArchdemInputError, match="unknown masonry type"):
        masonry_type("adobe", 1.35)


def test_the_guideline_by_hand():
    """A worked example in the guideline's units (N, mm, MPa), written from its formulas: carbon
    indoors (eta_a 0.95), application B (gamma_f 1.25, gamma_fd 1.5), b_f = 100 mm on b = 250 mm,
    E_f = 200 GPa, t_f = 0.1 mm, f_fk = 2000 MPa on masonry f_mm = 5, f_mtm = 0.5 MPa at FC 1.2."""
    fk, t, bf, b, E, fm, fmt, FC = 2000.0, 0.1, 100.0, 250.0, 200000.0, 5.0, 0.5, 1.2
    rupture = 0.95 * fk / 1.25
    kb = math.sqrt((3 - bf / b) / (1 + bf / b))
    G1 = kb * 0.031 / FC * math.sqrt(fm * fmt)  # N/mm
    G2 = kb * 0.093 / FC * math.sqrt(fm * fmt)
    end = math.sqrt(2 * E * G1 / t) / 1.5
    inter = 1.0 * math.sqrt(2 * E * G2 / t) / 1.5
    l_ed = max(math.sqrt(math.pi ** 2 * E * t * G1 / 2) / (1.5 * 2 * G1 / 0.4), 150.0)
    s = Strips(fk * 1e6, t * 1e-3, bf * 1e-3, modulus=E * 1e6, fibre="carbon", exposure="internal", application="B",
               masonry=Masonry(fm * 1e6, fmt * 1e6), FC=FC)
    d = s.design(b * 1e-3)
    assert d.f_rupture == pytest.approx(rupture * 1e6, rel=1e-12) and d.k_b == pytest.approx(kb, rel=1e-12)
    assert d.Gamma_Fd == pytest.approx(G1 * 1e3, rel=1e-12) and d.Gamma_Fd2 == pytest.approx(G2 * 1e3, rel=1e-12)
    assert d.f_end == pytest.approx(end * 1e6, rel=1e-12) and d.f_intermediate == pytest.approx(inter * 1e6, rel=1e-12)
    assert d.l_ed == pytest.approx(l_ed * 1e-3, rel=1e-12) and l_ed > 150
    # away from the ends intermediate debonding governs; within l_ed the end's anchorage (s / l_ed)(2 - s / l_ed)
    assert d.governing == "intermediate debonding" and d.governing_stress == pytest.approx(inter * 1e6)
    f, mode = d.at(0.5 * l_ed * 1e-3)
    assert mode == "end debonding" and f == pytest.approx(end * 1e6 * 0.75)
    assert d.at(2 * l_ed * 1e-3) == (pytest.approx(inter * 1e6), "intermediate debonding")
    # a designer's strength wins; a wide strip (b_f > b) takes k_b = 1
    assert Strips(fk * 1e6, t * 1e-3, bf * 1e-3, design_strength=100e6, modulus=E * 1e6,
                  masonry=Masonry(fm * 1e6, fmt * 1e6)).design(0.25).at(0.0) == (100e6, "given")
    assert s.design(0.05).k_b == 1.0


def test_debonding_strips_in_the_lp_and_the_mechanism():
    """Per-joint design forces (end debonding near the springings, intermediate elsewhere): the LP's
    multiplier still equals the virtual work of its own mechanism, and lies between the bare arch's and
    the rupture-designed strips'; the ring's hinges are checked for crushing."""
    arch = get_specimen("Sh06-Sd015").arch
    m = Masonry(3e6, 0.3e6)
    # a narrow strip on the laboratory arch (17 N): forces of a few newtons, the ring still opens
    deb = Strips(2000e6, 0.05e-3, 0.05e-3, modulus=230e9, masonry=m)
    rup = Strips(2000e6, 0.05e-3, 0.05e-3)
    sc = strengthened_collapse(arch, deb)
    modes = {v["mode"] for v in sc.forces.values()}
    assert modes == {"end debonding", "intermediate debonding"}
    assert sc.lam == pytest.approx(_kinematic_alpha0(sc), rel=1e-8)
    assert minimised_four_bar(arch).lam < sc.lam < strengthened_collapse(arch, rup).lam
    crush = sc.crushing(m, 1.35)
    assert len(crush) == len(sc.hinges) and all(c["C_kN"] > 0 and c["verified"] for c in crush)


# ---- the guideline's bond factors as inputs (BondFactors: unverified defaults, overridable) ----

def _noh_design(bond=None):
    from analytic.codes.assessment import monument_strips
    from specimens.monuments import MONUMENTS

    return monument_strips(bond=bond).design(float(MONUMENTS["noh-gumbad"].arch.width))


def test_the_default_bond_factors_give_todays_numbers():
    """No override: the module constants, marked unverified, and Noh Gumbad's strips as before
    (k_b 1.3237, Gamma_Fd 0.02499 N/mm, intermediate debonding 713.9 MPa, l_ed 194.8 mm, T 22.815 kN)."""
    from analytic.codes import frp

    b = BondFactors()
    assert (b.k_G, b.k_G2, b.s_u, b.gamma_Rd, b.l_ed_min, b.fmt_ratio) == (
        frp.K_G_END, frp.K_G_INTERMEDIATE, frp.SLIP_U, frp.GAMMA_RD, frp.L_ED_MIN, frp.MASONRY_TENSILE_RATIO)
    assert b.all_default and all(v["source"] == "unverified default" for v in b.describe().values())
    assert b.describe()["k_G"]["value"] == pytest.approx(0.031) and b.describe()["l_ed_min"]["unit"] == "mm"
    assert "(set by the user)" not in b.text() and b.text().count("(unverified default)") == 6
    d = _noh_design()
    assert d.strips.bond == b and d == _noh_design(BondFactors())
    assert round(d.k_b, 4) == 1.3237 and round(d.Gamma_Fd / 1e3, 5) == 0.02499
    assert round(d.f_intermediate / 1e6, 1) == 713.9 and round(d.l_ed * 1e3, 1) == 194.8
    assert round(d.force / 1e3, 3) == 22.815 and d.governing == "intermediate debonding"
    # the trail names each factor's source
    steps = d.describe()
    assert all("unverified default" in steps[k]["formula"] for k in ("k_G", "k_G2", "s_u", "gamma_Rd", "l_ed_min"))
    assert "unverified default" in steps["f_mtm"]["formula"]


def test_an_override_moves_its_quantities_by_the_closed_form_amount():
    base = _noh_design()
    # Gamma_Fd = k_b k_G / FC sqrt(f_mm f_mtm): doubling k_G doubles it, f_end by sqrt(2), f_bd = 2 Gamma_Fd / s_u
    # doubles too and l_ed ~ sqrt(Gamma_Fd) / f_bd falls by sqrt(2) (here to the 150 mm floor)
    d = _noh_design(BondFactors.given(k_G=2 * 0.031e-3))
    assert d.Gamma_Fd == pytest.approx(2 * base.Gamma_Fd, rel=1e-12)
    assert d.f_end == pytest.approx(math.sqrt(2) * base.f_end, rel=1e-12)
    assert d.l_ed == pytest.approx(max(base.l_ed / math.sqrt(2), 0.150), rel=1e-12)
    assert d.Gamma_Fd2 == base.Gamma_Fd2 and d.force == base.force  # intermediate debonding is k_G2's
    d2 = _noh_design(BondFactors.given(k_G2=2 * 0.093e-3))
    assert d2.f_intermediate == pytest.approx(math.sqrt(2) * base.f_intermediate, rel=1e-12)
    assert d2.force == pytest.approx(math.sqrt(2) * base.force, rel=1e-12)  # still below rupture
    # l_ed = s_u pi sqrt(E_f t_f / (2 Gamma_Fd)) / (2 gamma_Rd) above its floor: proportional to s_u, 1 / gamma_Rd
    assert _noh_design(BondFactors.given(s_u=0.8e-3)).l_ed == pytest.approx(2 * base.l_ed, rel=1e-12)
    assert _noh_design(BondFactors.given(gamma_Rd=1.2)).l_ed == pytest.approx(base.l_ed * 1.5 / 1.2, rel=1e-12)
    # the floor: the least optimal bond length given wins above the formula's value, and below it does nothing
    assert _noh_design(BondFactors.given(l_ed_min=0.300)).l_ed == 0.300
    assert _noh_design(BondFactors.given(l_ed_min=0.100)).l_ed == base.l_ed
    # f_mtm = ratio f_mm of the named masonry: Gamma_Fd ~ sqrt(f_mtm)
    d5 = _noh_design(BondFactors.given(fmt_ratio=0.2))
    assert d5.strips.masonry.fmt == pytest.approx(2 * base.strips.masonry.fmt, rel=1e-12)
    assert d5.Gamma_Fd == pytest.approx(math.sqrt(2) * base.Gamma_Fd, rel=1e-12)
    # recorded as set by the user, the others as the unverified defaults
    b = BondFactors.given(k_G=0.031e-3, s_u=None)  # set by hand to the default value: still the user's
    assert b.describe()["k_G"]["source"] == "set by the user" and b.describe()["s_u"]["source"] == "unverified default"
    assert BondFactors(gamma_Rd=1.2).source("gamma_Rd") == "set by the user"  # a changed value counts as set
    steps = d.describe()
    assert "set by the user" in steps["k_G"]["formula"] and "unverified default" in steps["k_G2"]["formula"]


@pytest.mark.parametrize("kw, what", [({"k_G": 0.0}, "k_G"), ({"k_G2": -1e-4}, "k_G2"), ({"k_G": 0.031}, "k_G"),
                                      ({"s_u": math.nan}, "s_u"), ({"gamma_Rd": 0.5}, "gamma_Rd"),
                                      ({"l_ed_min": 5.0}, "l_ed_min"), ({"fmt_ratio": 0.5}, "f_mtm/f_mm"),
                                      ({"l_ed_min": True}, "l_ed_min"), ({"s_u": "0.4"}, "s_u")])
def test_a_bad_bond_factor_is_refused_in_one_line(kw, what):
    with pytest.raises(ArchdemInputError, match=f"FRP bond factor {re.escape(what)} ") as e:
        BondFactors(**kw)
    assert "\n" not in str(e.value)
