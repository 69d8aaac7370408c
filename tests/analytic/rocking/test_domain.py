"""Failure domains (analytic/rocking/domain.py): bands, bisection convergence, parallel = serial."""
from __future__ import annotations

import pytest

from analytic.rocking.domain import domain_column, failure_domain, make_input
from analytic.rocking.dynamics import simulate
from analytic.rocking.linkage import arch_four_bar, oppenheim_hinges
from analytic.rocking.rocking_block import RockingBlock
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError


@pytest.fixture(scope="module")
def fb():
    arch = get_specimen("Sh06-Sd015").arch
    return arch_four_bar(arch, oppenheim_hinges(arch))


@pytest.mark.slow
def test_boundary_converges_when_tolerance_halved(fb):
    a0 = abs(fb.onset)
    prev = None
    for tol in (4e-3, 2e-3, 1e-3, 5e-4):
        col = domain_column(fb, "sine", 3.0, a0 * (1 + 1e-9), 6 * a0, n_scan=16, tol=tol)
        a = col.thresholds[0][0]
        if prev is not None:
            # each bisected boundary lies within its bracket (relative width tol): successive values
            # differ by at most the coarser tolerance
            assert abs(a - prev[0]) <= prev[1] * prev[0]
        prev = (a, tol)


def test_bands_are_contiguous_and_classified(fb):
    a0 = abs(fb.onset)
    col = domain_column(fb, "sine", 2.0, a0 * (1 + 1e-9), 10 * a0, n_scan=24, tol=1e-3)
    assert col.bands[0].lo == pytest.approx(a0 * (1 + 1e-9)) and col.bands[-1].hi == pytest.approx(10 * a0)
    for b1, b2 in zip(col.bands[:-1], col.bands[1:]):
        assert b1.hi == b2.lo and b1.outcome != b2.outcome
    # every band's interior has the class it reports (independent re-run at the band centre)
    for b in col.bands:
        mid = (b.lo * b.hi) ** 0.5
        r = simulate(fb, make_input("sine", mid, 2.0, a0), record=False)
        assert (r.mode if r.collapsed else "survival") == b.outcome


def test_regression_pin_temporary_recovery_is_reported(fb):
    """At 3.5 Hz this arch collapses after an impact, survives a band above, then collapses in the
    first half-cycle: both thresholds are reported (docs/physics/dynamics.md#10-failure-domains).
    Regression pin: that 3.5 Hz has such a band is this code's own earlier output, not physics."""
    a0 = abs(fb.onset)
    col = domain_column(fb, "sine", 3.5, a0 * (1 + 1e-9), 10 * a0, n_scan=24, tol=1e-3)
    outcomes = [b.outcome for b in col.bands]
    assert outcomes == ["survival", "after-impact", "survival", "first-half-cycle"]
    assert [m for _, m in col.thresholds] == ["after-impact", "first-half-cycle"]
    # the survival band above the first threshold is one: a re-run inside it survives
    inner = col.bands[2]
    assert not simulate(fb, make_input("sine", (inner.lo * inner.hi) ** 0.5, 3.5, a0), record=False).collapsed


@pytest.mark.slow
def test_parallel_equals_serial(fb):
    xs = [1.5, 3.0, 6.0]
    d1 = failure_domain(fb, "sine", xs, a_max_ratio=5, n_scan=10, tol=1e-2, workers=1)
    d2 = failure_domain(fb, "sine", xs, a_max_ratio=5, n_scan=10, tol=1e-2, workers=2)
    assert d1.points() == d2.points() and d1.bands() == d2.bands()  # same deterministic computation
    assert [p["x"] for p in d1.points()] == xs  # a collapse found at every frequency
    assert d1.lam == pytest.approx(fb.lam) and all(p["amplitude_g"] >= fb.lam for p in d1.points())


def test_pulse_domain_and_normalised_axes():
    blk = RockingBlock(0.1, 0.5)
    d = failure_domain(blk, "A", [0.2, 0.4], a_max_ratio=20, n_scan=12, tol=1e-3, workers=1)
    pts = d.points()
    assert [p["x"] for p in pts] == [0.2, 0.4]
    assert pts[0]["amplitude_g"] > pts[1]["amplitude_g"]  # a longer pulse overturns with less
    n = d.normalised()
    assert n[0]["a"] == pytest.approx(pts[0]["amplitude_g"] / d.lam)


def test_bad_domain_input(fb):
    with pytest.raises(ArchdemInputError):
        failure_domain(fb, "square", [1.0])
    with pytest.raises(ArchdemInputError):
        failure_domain(fb, "sine", [-1.0])
    with pytest.raises(ArchdemInputError):
        failure_domain(fb, "sine", [1.0], a_max_ratio=0.5)
