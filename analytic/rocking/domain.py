"""Failure domains (docs/physics/dynamics.md#10-failure-domains): collapse amplitudes over a grid of frequencies or durations.

For every grid value ``x`` (frequency [Hz] of a sine pulse, or duration ``t_i`` [s] of pulse A/B)
the amplitude axis ``[a_min, a_max]`` is scanned (``n_scan`` amplitudes, geometric spacing) and
every bracket where the outcome class changes (survival / collapse in the first half-cycle /
collapse after an impact) is bisected to a relative tolerance ``tol``. The result keeps all the
bands, not only the lowest threshold: temporary recovery (a survival band above a collapse band)
is reported. The grid is processed in parallel (``concurrent.futures.ProcessPoolExecutor``, all
cores by default). Amplitudes in m/s^2 inside; the CLI reports them in g.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from analytic.motions.inputs import GroundMotion, PulseA, PulseB, SinePulse
from analytic.rocking.mechanism import Mechanism
from analytic.search import midpoint, search
from specimens.constants import G
from foundation.errors import ArchdemInputError
from foundation.processes import worker_pool

INPUTS = ("sine", "sine0", "A", "B")


def make_input(kind: str, amplitude: float, x: float, onset: float) -> GroundMotion:
    """Input ``kind`` of amplitude [m/s^2] at grid value ``x`` (Hz for sines, ``t_i`` [s] for pulses);
    ``onset`` [m/s^2] sets the phase of the phased sine."""
    if kind == "sine":
        return SinePulse.phased(amplitude, x, onset)
    if kind == "sine0":
        return SinePulse(amplitude, x)
    if kind == "A":
        return PulseA(amplitude, x)
    if kind == "B":
        return PulseB(amplitude, x)
    raise ArchdemInputError(f"unknown input {kind!r}; choose one of {', '.join(INPUTS)}")


@dataclass(frozen=True)
class Band:
    """Amplitudes ``[lo, hi]`` [m/s^2] of one outcome class: ``"survival"``, ``"first-half-cycle"`` or
    ``"after-impact"`` (the two collapse modes)."""

    lo: float
    hi: float
    outcome: str

    @property
    def collapse(self) -> bool:
        return self.outcome != "survival"


@dataclass(frozen=True)
class DomainColumn:
    """All bands at one grid value ``x``; ``thresholds``: amplitudes where survival turns into collapse
    (with the mode above); ``linearised``: quick-estimate collapse amplitude (None if above a_max)."""

    x: float
    bands: tuple[Band, ...]
    thresholds: tuple[tuple[float, str], ...]
    linearised: float | None
    n_runs: int


@dataclass(frozen=True)
class FailureDomain:
    """Failure domain of ``mechanism`` under ``input_kind``: one column per grid value."""

    input_kind: str
    columns: tuple[DomainColumn, ...]
    lam: float
    omega0: float
    phi_cr: float
    restitution: float | None
    a_range: tuple[float, float]
    tol: float
    axis: str = "frequency"

    def points(self) -> list[dict]:
        """Every survival-to-collapse boundary: ``x``, amplitude [g] and the collapse mode above it."""
        return [{"x": c.x, "amplitude_g": a / G, "mode": mode} for c in self.columns for a, mode in c.thresholds]

    def bands(self) -> list[dict]:
        return [{"x": c.x, "from_g": b.lo / G, "to_g": b.hi / G, "outcome": b.outcome,
                 "collapse": b.collapse} for c in self.columns for b in c.bands]

    def normalised(self) -> list[dict]:
        """Points on normalised axes: ``a / (lambda g)`` and ``f / (omega0 / 2 pi)`` (or ``t_i omega0``)."""
        f0 = self.omega0 / (2 * math.pi)
        out = []
        for p in self.points():
            xn = p["x"] / f0 if self.axis == "frequency" else p["x"] * self.omega0
            out.append({"x": xn, "a": p["amplitude_g"] / self.lam, "mode": p["mode"]})
        return out


def _classify(mech: Mechanism, kind: str, a: float, x: float, restitution: float | None) -> str:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.dynamics import (
        simulate,  # scipy's integrators: imported when a domain is computed
    )

    r = simulate(mech, make_input(kind, a, x, abs(mech.onset)), restitution=restitution, record=False)
    if not r.collapsed:
        return "survival"
    return r.mode  # type: ignore[return-value]


def domain_column(mech: Mechanism, kind: str, x: float, a_min: float, a_max: float, n_scan: int = 24,
                  tol: float = 1e-3, restitution: float | None = None) -> DomainColumn:
    """Scan the amplitudes at ``x`` and bisect every bracket to relative tolerance ``tol``."""
    amps = np.geomspace(a_min, a_max, n_scan)
    cls = [_classify(mech, kind, float(a), x, restitution) for a in amps]
    runs = n_scan
    edges: list[tuple[float, str, str]] = []  # (amplitude, class below, class above)
    for k in range(n_scan - 1):
        if cls[k] == cls[k + 1]:
            continue
        clo = cls[k]
        # bisect; a third class found inside splits the bracket (keep the lower change)
        res = search(lambda a: _classify(mech, kind, a, x, restitution), float(amps[k]), float(amps[k + 1]), tol,
                     rule="width/lo", geometric=True, is_upper=lambda c: c != clo, lo_run=clo, hi_run=cls[k + 1])
        runs += res.runs
        edges.append((midpoint(res.lo, res.hi, geometric=True), clo, res.hi_run))
    bands = []
    start = float(amps[0])
    for a, clo, _ in edges:
        bands.append(Band(start, a, clo))
        start = a
    bands.append(Band(start, float(amps[-1]), cls[-1]))
    # merge neighbours of the same class (from nested changes)
    merged: list[Band] = []
    for b in bands:
        if merged and merged[-1].outcome == b.outcome:
            merged[-1] = Band(merged[-1].lo, b.hi, b.outcome)
        else:
            merged.append(b)
    thresholds = tuple((b.lo, b.outcome) for prev, b in zip(merged[:-1], merged[1:])
                       if prev.outcome == "survival" and b.outcome != "survival")
    if merged[0].outcome != "survival":
        thresholds = ((merged[0].lo, merged[0].outcome),) + thresholds
    lin = _linearised_threshold(mech, kind, x, a_min, a_max, tol)
    return DomainColumn(float(x), tuple(merged), thresholds, lin, runs)


def _linearised_threshold(mech: Mechanism, kind: str, x: float, a_min: float, a_max: float, tol: float):
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.dynamics import linearised_collapse

    f = lambda a: linearised_collapse(mech, make_input(kind, a, x, abs(mech.onset)))  # noqa: E731
    if not f(a_max):
        return None
    if f(a_min):
        return a_min
    res = search(f, a_min, a_max, tol, rule="width/lo", geometric=True, lo_run=False, hi_run=True)
    return midpoint(res.lo, res.hi, geometric=True)


def warm_up(mech: Mechanism, restitution: float | None = None, depth: int = 8) -> None:
    """Compute the chain of post-impact mechanisms once (cached on the objects, so the worker
    processes receive it with the mechanism instead of searching it again)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.impact import post_impact

    m = mech
    for _ in range(depth):
        nxt = post_impact(m, restitution).after
        post_impact(nxt, restitution)
        if nxt is mech or nxt is m:
            break
        m = nxt
    for m2 in (mech, post_impact(mech, restitution).after):
        _ = (m2.phi_cr, m2.phi_limit, m2.barrier, m2.omega0, m2.M0)


def _column_job(args):
    return domain_column(*args)


def failure_domain(mech: Mechanism, kind: str, xs: Sequence[float], a_max_ratio: float = 10.0,
                   n_scan: int = 24, tol: float = 1e-3, restitution: float | None = None,
                   workers: int | None = None) -> FailureDomain:
    """Failure domain over grid ``xs`` (Hz for sines, s for pulses); amplitudes from the onset
    ``lambda g`` to ``a_max_ratio lambda g``; ``workers``: processes (default all cores, 1 = serial)."""
    if kind not in INPUTS:
        raise ArchdemInputError(f"unknown input {kind!r}; choose one of {', '.join(INPUTS)}")
    xs = [float(x) for x in xs]
    if not xs or not all(math.isfinite(x) and x > 0 for x in xs):
        raise ArchdemInputError("the frequency/duration grid must contain positive numbers")
    if not (a_max_ratio > 1):
        raise ArchdemInputError(f"the amplitude range must extend above the onset (a_max / lambda g = {a_max_ratio})")
    if n_scan < 2:
        raise ArchdemInputError("the amplitude scan needs at least 2 amplitudes")
    if mech.direction != 1:
        raise ArchdemInputError("the mechanism must be opened by a positive ground acceleration")
    a0 = abs(mech.onset)
    a_min = a0 * (1 + 1e-9)
    a_max = a0 * a_max_ratio
    warm_up(mech, restitution)
    jobs = [(mech, kind, x, a_min, a_max, n_scan, tol, restitution) for x in xs]
    workers = (os.cpu_count() or 1) if workers is None else int(workers)
    if workers <= 1 or len(xs) == 1:
        cols = [_column_job(j) for j in jobs]
    else:
        with worker_pool(min(workers, len(xs))) as ex:
            cols = list(ex.map(_column_job, jobs, chunksize=max(1, len(xs) // (4 * workers))))
    return FailureDomain(kind, tuple(cols), mech.lam, mech.omega0, mech.phi_cr, restitution, (a_min, a_max), tol,
                         "frequency" if kind.startswith("sine") else "duration")
