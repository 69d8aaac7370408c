"""Tilt test against the discrete limit analysis (spec §3.4.3-4) on a representative specimen;
the 11 specimens x 2 configurations run in benchmarks/validate_dem.py."""
import numpy as np
import pytest

from dem.model import from_assembly
from dem.protocols import tilt
from dem.settings import NO_SLIDING_MU, Settings
from specimens.blocks import discretise
from specimens.catalogue import get_specimen

lim = pytest.importorskip("analytic.limit_discrete", reason="discrete limit analysis not available")

SID = "Sh02-Sd020"


@pytest.fixture(scope="module")
def case():
    asm = discretise(get_specimen(SID).arch, config="glued")
    m = from_assembly(asm, name=SID)
    ns = tilt(m, Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU))
    return asm, m, ns


@pytest.mark.slow
def test_no_sliding_lambda_and_hinges_match_lp(case):
    asm, m, ns = case
    lp = lim.solve_lp(asm, float("inf"), float("inf"))
    # the tolerance: 3 % (PyBullet's measured bias: 2.4 % low to 0.1 % high with the defaults,
    # 21 of 22 catalogue cases within 3 %, see dem/settings.py)
    assert abs(ns.lam - lp.lam) / lp.lam <= 0.03
    hinges = tuple((j.joint, j.face) for j in ns.joints if j.state in ("hinge", "hinge+slide"))
    # the LP layout, or another four-hinge mechanism within 0.5 % of the LP lambda (the rule:
    # near-optimal mechanisms are indistinguishable at the DEM's +-1 % threshold reproducibility)
    if hinges != lp.hinges:
        assert len(hinges) == 4
        assert abs(lim.mechanism_lambda(asm, hinges) - lp.lam) <= 0.005 * lp.lam
    assert ns.mode == "rocking"


@pytest.mark.slow
def test_reference_friction_not_above_no_sliding(case):
    # spec §3.4.4; 1 % = the reproducibility of thresholds measured near the bracket. This specimen
    # failed it with levels held 2 s (reference 0.3498 vs no-sliding 0.3456, a spurious collapse at
    # rest 1.6 % below the LP after more than 1 s of hold); held 1 s (the default, measured in
    # dem/protocols.py) it reads 0.3498 vs 0.3493, and 22 of 22 catalogue cases pass.
    asm, m, ns = case
    ref = tilt(m, Settings())
    assert ref.lam <= 1.01 * ns.lam


@pytest.mark.slow
def test_halving_dt(case):
    # spec §3.2: halving dt changes lambda by < 2 %
    asm, m, ns = case
    s = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU)
    half = tilt(m, s.with_(dt=s.dt / 2))
    assert abs(half.lam - ns.lam) / ns.lam < 0.02
