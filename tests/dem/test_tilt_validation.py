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


def four_hinge_mechanism_lambda(assembly, hinges) -> float:
    """Lambda of the given four-hinge mechanism ((joint, face) left to right) by the virtual-work
    kernel of the limit analysis (inf if inadmissible) - the "second model" for hinge layouts."""
    names = [j.name for j in assembly.joints]
    J = np.array([names.index(h) for h, _ in hinges])
    F = np.array([lim.FACES.index(f) for _, f in hinges])
    L = assembly.arch.Rp
    corners = np.array([[j.p_i, j.p_e] for j in assembly.joints]) / L
    normals = np.array([j.normal for j in assembly.joints])
    m = np.array([b.mass for b in assembly.bodies])
    c = np.array([b.centroid for b in assembly.bodies]) / L
    m = m / m.sum()
    P = np.concatenate([[[0.0, 0.0, 0.0]], np.cumsum(np.column_stack([m, m * c[:, 0], m * c[:, 1]]), axis=0)])
    a = np.array([j.a for j in assembly.joints])
    b = np.array([j.b for j in assembly.joints])
    lo, hi = b[J[:3]], a[J[1:]]
    if np.any(lo < 0) or np.any(hi < lo):
        return float("inf")
    s = P[hi + 1] - P[lo]
    w = lim.four_hinge_lambda(corners[J, F][None], corners[J, 1 - F][None], normals[J][None],
                              s[None, :, 0], s[None, :, 1], s[None, :, 2])
    return float(w.lam[0]) if bool(w.admissible[0]) else float("inf")


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
    # the tolerance: 3 % (PyBullet's measured bias is low by 0.7-4 %, spec 04 §4.1)
    assert abs(ns.lam - lp.lam) / lp.lam <= 0.03
    hinges = tuple((j.joint, j.face) for j in ns.joints if j.state in ("hinge", "hinge+slide"))
    # the LP layout, or another four-hinge mechanism within 0.5 % of the LP lambda (the rule:
    # near-optimal mechanisms are indistinguishable at the DEM's +-1 % threshold reproducibility)
    if hinges != lp.hinges:
        assert len(hinges) == 4
        assert abs(four_hinge_mechanism_lambda(asm, hinges) - lp.lam) <= 0.005 * lp.lam
    assert ns.mode == "rocking"


@pytest.mark.slow
def test_reference_friction_not_above_no_sliding(case):
    # spec §3.4.4; 1 % = the reproducibility of thresholds measured near the bracket
    asm, m, ns = case
    ref = tilt(m, Settings())
    assert ref.lam <= 1.01 * ns.lam


@pytest.mark.slow
def test_halving_dt(case):
    # spec §3.2: halving dt changes lambda by < 2 %
    asm, m, ns = case
    half = tilt(m, Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, dt=5e-4))
    assert abs(half.lam - ns.lam) / ns.lam < 0.02
