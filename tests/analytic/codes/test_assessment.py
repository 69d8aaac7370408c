"""The assessment's limit states side by side (activation at SLD, linear and displacement at SLV) on a
rocking block by hand, and the calculation trail."""
import math

import pytest

from analytic.codes.assessment import assess
from analytic.codes.frp import strengthened_collapse
from analytic.motions.spectra import ec8
from analytic.rocking.rocking_block import RockingBlock
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.monuments import NOH_GUMBAD

FC = 1.35


def _by(res, ls, kind):
    return next(c for c in res.checks if c["limit_state"] == ls and c["kind"] == kind)


def test_sld_and_slv_side_by_side_on_a_rocking_block():
    """b/h = 0.25: alpha0 = 0.25, e* = 1, a0* = 0.25 g / FC. On ground C (S = 1.15 for any ag in EC8) the
    activation ag is a0* / S; SLD: a0* / S against the SLD hazard's ag (no q); SLV linear: q a0* / S
    against the SLV ag; SLV displacement: d_u = 0.4 b against SDe(T) at 8 % (the hand computation of
    test_kinematic's block, here on ground C)."""
    blk = RockingBlock(0.05, 0.2)
    slv, sld = ec8(0.3 * G, "C"), ec8(0.08 * G, "C")
    r = assess(blk, slv, FC, 2.0, "SLV", sld_site=sld)
    a0 = 0.25 * G / FC
    assert r.linear.a0_star == pytest.approx(a0, rel=1e-12)
    act, lin, dis = _by(r, "SLD", "activation"), _by(r, "SLV", "linear"), _by(r, "SLV", "non-linear")
    assert act["capacity_ag"] == pytest.approx(a0 / 1.15, rel=1e-8)
    assert act["safety_index"] == pytest.approx(a0 / 1.15 / (0.08 * G), rel=1e-8)
    assert lin["safety_index"] == pytest.approx(2 * a0 / 1.15 / (0.3 * G), rel=1e-8)
    # displacement: T in the TC-TD branch of ground C (0.6-2 s): SDe = ag S eta 2.5 TC / T (T / 2 pi)^2
    d_u = 0.4 * 0.05
    a_u = math.tan(math.asin((0.05 - d_u) / blk.R)) * G / FC
    T = 1.68 * math.pi * math.sqrt(d_u / a_u)
    assert 0.6 < T < 2.0
    demand = 0.3 * G * 1.15 * math.sqrt(10 / 13) * 2.5 * 0.6 / T * (T / (2 * math.pi)) ** 2
    assert dis["period"] == pytest.approx(T, rel=1e-4) and dis["demand_displacement"] == pytest.approx(demand, rel=1e-4)
    assert dis["safety_index"] == pytest.approx(d_u / demand, rel=1e-4)
    # each limit state's governing check, and the least over both
    ls = r.by_limit_state()
    assert ls["SLD"]["safety_index"] == act["safety_index"] and ls["SLD"]["governing"] == "activation"
    assert ls["SLV"]["safety_index"] == min(lin["safety_index"], dis["safety_index"])
    assert r.safety_index == min(act["safety_index"], lin["safety_index"], dis["safety_index"])
    # --limit-state SLD: the spectrum is the SLD hazard, the activation check alone
    only = assess(blk, sld, FC, 2.0, "SLD")
    assert [c["kind"] for c in only.checks] == ["activation"] and only.safety_index == pytest.approx(act["safety_index"])


def test_the_a0_over_pga_convention():
    """Without an SLD hazard a life-safety assessment reports the activation against its own hazard
    (no q): on rock (S = 1) its index is a0* / PGA, the published tables' convention; it is not a code
    check and does not govern."""
    blk = RockingBlock(0.05, 0.2)
    site = ec8(0.3 * G, "A")
    r = assess(blk, site, FC, 2.0, "SLV")
    conv = _by(r, "SLV", "activation")
    assert conv["code_check"] is False and conv["safety_index"] == pytest.approx(r.linear.a0_star / site.pga, rel=1e-8)
    # with q = 2 the linear check's index is twice the convention's
    assert _by(r, "SLV", "linear")["safety_index"] == pytest.approx(2 * conv["safety_index"], rel=1e-8)
    assert "SLV activation" not in r.describe()["governing_check"]
    with pytest.raises(ArchdemInputError, match="limit state must be SLD, SLV or SLC"):
        assess(blk, site, FC, 2.0, "SLO")


def test_the_trail_carries_every_step():
    """The trail's quantities are those of the checks (M* = m for a block; its centroid, h above the
    pivot and b beside it, moves h along the load and b up per unit rotation), each with a unit and a formula."""
    blk = RockingBlock(0.05, 0.2)
    r = assess(blk, ec8(0.3 * G, "A"), FC, 2.0, "SLV", sld_site=ec8(0.1 * G, "A"))
    tr = {s["symbol"]: s for s in r.describe()["trail"]}
    assert all(s["unit"] and s["formula"] and s["clause"].startswith("C8.") for s in tr.values())
    assert tr["M*"]["value"] == pytest.approx(blk.m) and tr["e*"]["value"] == pytest.approx(1.0)
    assert tr["M*"]["formula"] == "(sum m dx)^2 / sum m dx^2" and tr["a0*"]["value"] == r.linear.a0_star
    m, dx, dy, dth = tr["body 0: m, dx, dy, dtheta"]["value"]
    assert m == pytest.approx(blk.m) and dx == pytest.approx(0.2) and dy == pytest.approx(0.05) and abs(dth) == 1
    for ls, kind in (("SLD", "activation"), ("SLV", "linear"), ("SLV", "non-linear")):
        assert tr[f"{ls} {kind}: safety index"]["value"] == _by(r, ls, kind)["safety_index"]
    assert tr["SLV non-linear: T_s"]["value"] == _by(r, "SLV", "non-linear")["period"]
    assert tr["SLV non-linear: Se(T_s)"]["value"] > 0 and tr["d0*"]["value"] == pytest.approx(0.05)


# the published limit analyses of the Noh Gumbad vaults: hinge polar angles about O [rad], load along +x
# (as in benchmarks/fit_noh_gumbad.py, which fits the geometry to their multipliers)
NOH_PUBLISHED = {"ring alone": (0.009, 0.787, 2.096, 3.138),
                 "half-height piers": (-0.698, 0.865, 1.655, 4.127),
                 "full-height piers": (-0.987, 0.654, 1.633, 4.361)}


def _noh_hinges(name):
    sc = strengthened_collapse(NOH_GUMBAD.arch, None, NOH_GUMBAD.density, NOH_GUMBAD.configurations[name], load_sign=1)
    got = [h["angle_rad"] for h in sc.mechanism.summary()["hinges"]]
    return got, sorted(NOH_PUBLISHED[name], reverse=True)  # archdem lists hinges left to right: decreasing angle


def test_the_noh_gumbad_ring_hinges_against_the_published_ones():
    """The fit forces the multiplier and chose the ring's pointedness by its two interior hinges (least
    squared error 0.025 rad^2, docs/physics/assessment.md §7); the springing hinges are not fitted: they
    must fall within the interior hinges' RMS error, sqrt(0.025 / 2) = 0.11 rad, of the published ones."""
    got, pub = _noh_hinges("ring alone")
    res = [g - p for g, p in zip(got, pub)]
    assert res[1] ** 2 + res[2] ** 2 <= 0.025
    tol = math.sqrt(0.025 / 2)
    assert abs(res[0]) <= tol and abs(res[3]) <= tol


def test_the_noh_gumbad_pier_hinges_against_the_published_ones():
    """On piers the fit forces the heights by the multipliers and the width by the inner hinges; the
    documented errors: the right-pier hinge within 0.035 rad, the ring's within 0.27 rad, and the study's
    left hinge in the left pier (beta > pi) where archdem's least mechanism keeps it in the ring."""
    for name in ("half-height piers", "full-height piers"):
        got, pub = _noh_hinges(name)
        # 0.035 as documented to three decimals (the residual is 0.0350)
        assert abs(got[3] - pub[3]) <= 0.0355 and got[3] < 0  # the right pier's outer foot
        assert all(abs(g - p) <= 0.27 for g, p in zip(got[1:3], pub[1:3]))
        assert pub[0] > math.pi > got[0]  # the known difference, kept visible


def test_index_text_keeps_three_decimals_and_never_crosses_one():
    """0.995 is not 1.00; an index just below 1 prints more digits rather than "1.000"."""
    from analytic.codes.assessment import index_text

    assert index_text(0.995) == "0.995" and index_text(1.8511) == "1.851" and index_text(1.0) == "1.000"
    assert index_text(0.99996) == "0.99996" and float(index_text(0.99996)) < 1
    assert index_text(math.inf) == "inf"


def test_quantities_in_one_unit_with_the_other_in_brackets():
    from analytic.codes.assessment import quantity_text

    assert quantity_text(2 * G, "m/s^2") == f"2.000 g ({2 * G:#.4g} m/s^2)" and quantity_text(0.127, "m") == "127.0 mm"


def test_check_rows_state_the_clause_on_a_soil_whose_factor_follows_ag():
    """NTC 2018 soil C at a height: each row's index is capacity / demand of its own pair (q a0* against the
    floor's a_Z, a0* against it, d_u* against the demand displacement), the verdict index >= 1."""
    from analytic.codes.assessment import check_rows, site_table
    from analytic.codes.kinematic import Height
    from analytic.motions.spectra import ntc2018

    site = ntc2018(0.3 * G, 2.4, 0.3, "C")
    r = assess(RockingBlock(0.05, 0.2), site,
               height=Height(0.5, 0.3, 2), sld_site=ntc2018(0.1 * G, 2.4, 0.3, "C"))
    rows = check_rows(r)
    assert [(x["limit_state"], x["kind"]) for x in rows] == [("SLD", "activation"), ("SLV", "linear"),
                                                              ("SLV", "non-linear")]
    act, lin, dis = rows
    assert lin["capacity"] == pytest.approx(2 * r.linear.a0_star) and act["capacity"] == r.linear.a0_star
    assert lin["demand_symbol"] == "a_Z" and lin["unit"] == "m/s^2" and dis["unit"] == "m"
    assert dis["capacity"] == r.checks[2]["d_u_star"] and dis["demand"] == r.checks[2]["demand_displacement"]
    for x in rows:
        assert x["safety_index"] == pytest.approx(x["capacity"] / x["demand"], rel=1e-12)
        assert x["verdict"] == ("verified" if x["capacity"] >= x["demand"] else "not verified")
        assert x["clause"].startswith("C8.7.1.2")
    assert r.safety_index == min(x["safety_index"] for x in rows)
    table = dict(site_table(site))
    assert table["soil category"] == "C" and table["ag (on rock)"].startswith("0.3000 g (")
