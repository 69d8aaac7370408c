"""FRP strips: the static LP with the strips' tension against the kinematic work of the same mechanism."""
import math

import pytest

from analytic.codes.frp import Masonry, Strips, masonry_type, strengthened_collapse
from analytic.rocking.linkage import RigidRotation, minimised_four_bar
from specimens import get_specimen
from specimens.constants import G
from specimens.errors import ArchdemInputError
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
