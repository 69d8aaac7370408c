"""Tilt test against the discrete limit analysis (docs/validation.md#4-no-sliding-tilt-against-the-lp) on a representative specimen;
the 11 specimens x 2 configurations run in benchmarks/validate_dem.py."""
import pytest

import analytic.limit.limit_discrete as lim
from dem.core.model import from_assembly
from dem.core.settings import Settings
from dem.experiments.tilt.run import TiltProtocol, tilt
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from specimens.constants import NO_SLIDING_MU

SID = "Sh02-Sd020"


@pytest.fixture(scope="module")
def case():
    asm = discretise(get_specimen(SID).arch, config="glued")
    m = from_assembly(asm, name=SID)
    ns = tilt(m, Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU), assembly=asm)  # the default protocol
    return asm, m, ns


# Measured on this specimen with the default protocol: no sliding 0.3480 on pads (-0.90 % from the LP,
# the LP's hinges and L7; 0.3513, +0.05 %, before them), reference friction 0.3497 (from the former first bracket (0.95, 1.01) x LP: 0.3494,
# -0.50 %, and 0.3507). Which catalogue case misses is a matter of the last
# bits (docs/validation.md#7-non-monotonic-outcomes-near-the-threshold): with levels
# ramped 1 s instead of 0.5 s this specimen collapsed spuriously at 0.3441 (-2.0 %) in a disordered
# mechanism and failed the last two checks below, while the catalogue as a whole scored the same
# (benchmarks/validate_dem.py; the defaults' figures: docs/validation.md#4-no-sliding-tilt-against-the-lp).


@pytest.mark.slow
def test_no_sliding_lambda_matches_lp(case):
    asm, m, ns = case
    lp = lim.solve_lp(asm, float("inf"), float("inf"))
    # the tolerance: 3 % (PyBullet's measured bias with the defaults: mean 0.63 %, 22 of 22
    # catalogue cases within 3 %, 19-22 over seven runs: docs/validation.md#4-no-sliding-tilt-against-the-lp)
    assert abs(ns.lam - lp.lam) / lp.lam <= 0.03


@pytest.mark.slow
def test_no_sliding_lambda_of_this_specimen(case):
    # this case's own reading beside the 3 % rule: measured -0.90 % (0.34800 against 0.35115).
    # 1 %: thresholds near the bracket are reproducible to +-1 % (twice the 0.5 % bisection bracket;
    # docs/validation.md#7-non-monotonic-outcomes-near-the-threshold); a regression moves it further
    asm, m, ns = case
    lp = lim.solve_lp(asm, float("inf"), float("inf"))
    assert ns.lam == pytest.approx(lp.lam, rel=0.01)


@pytest.mark.slow
def test_no_sliding_hinges_match_lp(case):
    asm, m, ns = case
    lp = lim.solve_lp(asm, float("inf"), float("inf"))
    hinges = tuple((j.joint, j.face) for j in ns.joints if j.state in ("hinge", "hinge+slide"))
    # the LP layout, or another four-hinge mechanism within 0.5 % of the LP lambda (the rule:
    # near-optimal mechanisms are indistinguishable at the DEM's +-1 % threshold reproducibility), or the
    # LP's four and one joint beside one of them whose mechanism in its place is within 0.5 %: the arch
    # moves as a mix of the two (on pads this specimen opens L7 beside L6, +0.40 %; docs/validation.md#5)
    if hinges != lp.hinges:
        if len(hinges) == 4:
            assert abs(lim.mechanism_lambda(asm, hinges) - lp.lam) <= 0.005 * lp.lam
        else:
            extra = [h for h in hinges if h not in lp.hinges]
            assert set(lp.hinges) <= set(hinges) and len(extra) == 1
            names = [j.name for j in asm.joints]
            k = names.index(extra[0][0])
            beside = [h for h in lp.hinges if abs(names.index(h[0]) - k) == 1 and h[1] == extra[0][1]]
            assert beside
            swapped = tuple(extra[0] if h == beside[0] else h for h in lp.hinges)
            assert abs(lim.mechanism_lambda(asm, swapped) - lp.lam) <= 0.005 * lp.lam
    assert ns.mode == "rocking"


@pytest.mark.slow
def test_reference_friction_not_above_no_sliding(case):
    # docs/validation.md#6-reference-friction; 1 % = the reproducibility of thresholds measured near the bracket
    asm, m, ns = case
    ref = tilt(m, Settings(), assembly=asm)
    assert ref.lam <= 1.01 * ns.lam


@pytest.mark.slow
def test_halving_dt(case):
    # docs/validation.md#8-insensitivity-to-time-step-and-rate: halving dt changes lambda by < 2 %
    asm, m, ns = case
    s = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU)
    half = tilt(m, s.with_(dt=s.dt / 2), assembly=asm)
    assert abs(half.lam - ns.lam) / ns.lam < 0.02


@pytest.mark.slow
def test_halving_the_hold_ramp_rate(case):
    # docs/validation.md#8-insensitivity-to-time-step-and-rate / the issue: halving the hold
    # protocol's rate (TiltProtocol.slowed(2): ramp, hold and the rest rule's start and window
    # twice as long) changes lambda by < 2 %. Measured with the
    # defaults (benchmarks/validate_dem.py --sensitivity): -0.47 % here and on Sh06-Sd015 (the same
    # with the rest rule's times left at 0.5 s and 0.1 s); from the former first bracket (0.95, 1.01),
    # -1.5 % here (0.3441 against 0.3494: the spurious collapse described above), +0.8 % on Sh06-Sd015
    asm, m, ns = case
    slow = tilt(m, Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU),
                TiltProtocol().slowed(2.0), assembly=asm)
    assert abs(slow.lam - ns.lam) / ns.lam < 0.02


# ------------------------------------------------------------------ every tilt's own check (LpCheck)
def _chk(lam, lp=0.5, **kw):
    from dem.experiments.tilt.check import LpCheck

    base = {"label": "arch", "lam": lam, "lp_lam": lp, "lp_hinges": (("L0", "intrados"),), "lp_slides": False,
            "no_sliding": False}
    return LpCheck(**(base | kw))


def test_lp_check_agrees_within_3pct_and_says_nothing():
    c = _chk(0.49)
    assert c.agrees and c.rel_err == pytest.approx(-0.02) and c.warning == "" and c.cause == ""
    assert c.to_dict()["error_pct"] == pytest.approx(-2.0) and c.to_dict()["agrees"] is True


def test_lp_check_names_the_arch_both_values_and_the_likely_cause():
    low = _chk(0.45)
    assert low.agrees is False
    assert low.warning.startswith("arch: tilt lambda 0.4500 is 10.0 % below the LP of the same blocks (0.5000)")
    assert "tipped early" in low.cause
    assert "held above" in _chk(0.55).cause and "above the LP" in _chk(0.55).warning
    assert "associative LP overestimates" in _chk(0.45, lp_slides=True).cause
    assert "compliant joints" in _chk(0.45, law="compliant").cause
    other = _chk(0.45, dem_hinges=(("L1", "extrados"),))
    assert "the DEM hinges (L1 extrados) are not the LP's (L0 intrados)" in other.cause


def test_lp_check_without_an_lp_is_unchecked():
    c = _chk(0.45, lp=float("nan"))
    assert c.agrees is None and c.warning == "" and c.to_dict()["error_pct"] is None
