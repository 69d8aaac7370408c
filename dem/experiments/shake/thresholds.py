"""Shake thresholds: the least collapsing amplitude of a one-cycle sine pulse, and DEM failure
domains over frequency.

Collapse is not monotonic in the amplitude (Sh02-Sd020 at 4 Hz collapses from ~0.45 g but survives
again around 0.78-0.9 g; docs/physics/dem.md#10-shake-thresholds-and-dem-failure-domains), so plain
bisection may return either edge of a survival window. :func:`threshold` therefore

1. **scans** amplitudes ``a_min .. a_max`` with geometric spacing (ratio ``scan_ratio``), in
   parallel (local processes, all cores by default, or a Dask cluster: :func:`dem.studies.sweep.executor`);
2. **bisects** (geometric midpoints) the lowest bracket survival -> collapse until
   ``hi / lo - 1 <= tol`` (1 % by default); the answer is the upper end ``hi`` (a simulated
   amplitude that collapsed), as for the tilt test. With several processes the bisection runs
   alongside the rest of the scan as soon as the amplitudes below its bracket are known
   (:func:`_scan_and_bisect`); the runs, and so the answer, are those of the serial order;
3. reports every band found by the scan (survival / collapse), its edges at the geometric middle
   of the scan bracket (resolution ``scan_ratio``) except the bisected first threshold.

How far a threshold is a number of the arch and not of the engine's numerics: the default engine
(MuJoCo) holds its thresholds under halving the time step and meets LMGC90's, but where the joints
can slide at 6-8 Hz (docs/validation.md#19-three-engine-shake-study). :func:`check_threshold` says it
of each threshold: settled, or a range holding every reading (``threshold(..., check=True)``).

A one-cycle sine here is the plain shake-table pulse ``a sin(2 pi f t)``, ``t in [0, 1/f]``
(:class:`analytic.motions.inputs.SinePulse` with zero phase; the analytic ``sine0`` input). Amplitudes
in m/s^2 inside; results are reported in g.

A search is :func:`run` of a :class:`ThresholdSpec`; its :class:`ThresholdResult` declares its summary's
columns once (:class:`dem.experiments.contract.Result`). :func:`threshold` is the same call with the spec's
fields as arguments.
"""
from __future__ import annotations

import math
import os
import time
from concurrent.futures import FIRST_COMPLETED, wait
from dataclasses import dataclass, field, replace
from typing import Any, Callable, ClassVar, Sequence

import numpy as np

from analytic.motions.inputs import GroundMotion, SinePulse
from analytic.search import Bracket, search
from dem.core.model import Model, as_model
from dem.core.progress import Progress
from dem.core.settings import Settings, dynamics_settings
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.shake.run import ShakeProtocol, collapses, shake
from specimens.constants import NO_SLIDING_MU, G
from foundation.errors import ArchdemInputError

SCAN_TOP = 5.0  # default top of the amplitude scan, as a multiple of its start


def sine_motion(amplitude: float, freq: float) -> GroundMotion:
    """Plain one-cycle sine of ``amplitude`` [m/s^2] and ``freq`` [Hz]."""
    return SinePulse(float(amplitude), float(freq))


@dataclass(frozen=True)
class Outcome:
    """One simulated amplitude [g]: collapsed, mode and collapse phase (see :mod:`dem.experiments.shake.run`)."""

    amplitude_g: float
    collapsed: bool
    mode: str
    phase: str | None

    def to_dict(self) -> dict:
        return {"amplitude_g": self.amplitude_g, "collapsed": self.collapsed, "mode": self.mode, "phase": self.phase}


@dataclass(frozen=True)
class ThresholdResult(Result):
    """Least collapsing amplitude at one frequency, with all scan bands: its summary row declared once.

    ``amplitude_g`` is None when nothing up to ``a_max`` collapsed; ``bracket_g`` the final
    (survival, collapse) bisection bracket; ``bands``: dicts ``from_g``, ``to_g``, ``outcome``
    (``survival``/``collapse``), ``collapse``; ``runs``: every simulation in order.
    """

    SCHEMA: ClassVar[Schema] = Schema((
        Column("freq", "float", "Hz"), Column("amplitude_g", "float", "g"), Column("bracket_g", "json", "g"),
        Column("mode", "str"), Column("collapse_phase", "str"), Column("bands", "json", "g"),
        Column("survival_bands_above", "json", "g"), Column("n_sims", "int"), Column("scan_ratio", "float"),
        Column("tol", "float"), Column("wall_s", "float", "s"), Column("runs", "json"), Column("verdict", "json"),
    ))

    freq: float
    amplitude_g: float | None
    bracket_g: tuple[float, float] | None
    bands: tuple[dict, ...]
    runs: tuple[Outcome, ...]
    scan_ratio: float
    tol: float
    wall_s: float
    mode: str = ""
    phase: str | None = None
    extra: dict = field(default_factory=dict)
    a_range_g: tuple[float, float] | None = None  # the scanned amplitudes [g]
    verdict: "Verdict | None" = None  # settled or a range (check_threshold); None: not checked

    @property
    def n_sims(self) -> int:
        return len(self.runs)

    @property
    def survival_bands_above(self) -> list[dict]:
        """Survival bands above the first threshold (temporary recovery)."""
        if self.amplitude_g is None:
            return []
        return [b for b in self.bands if not b["collapse"] and b["from_g"] >= self.amplitude_g * (1 - 1e-9)]

    def rows(self) -> list[dict]:
        return [{"freq": self.freq, "amplitude_g": self.amplitude_g,
                 "bracket_g": list(self.bracket_g) if self.bracket_g else None, "mode": self.mode,
                 "collapse_phase": self.phase, "bands": list(self.bands),
                 "survival_bands_above": self.survival_bands_above, "n_sims": self.n_sims,
                 "scan_ratio": self.scan_ratio, "tol": self.tol, "wall_s": self.wall_s,
                 "runs": [r.to_dict() for r in self.runs], "verdict": (self.verdict or NOT_CHECKED).to_dict()}]

    def summary(self) -> dict:
        """Its row as JSON, and ``extra``."""
        return {**self.to_json()[0], **self.extra}

    def describe(self, label: str, lam: float, config: str, model: Model, settings: Settings) -> dict:
        """The JSON of ``archdem threshold``: the search on ``label`` (static multiplier ``lam``, blocks cut in
        ``config``), its blocks' contact fraction and the frictions of ``settings``, then :meth:`summary`."""
        return {"id": label, "lambda": lam, "config": config, "contact": model.source.get("contact", 1.0),
                "mu_joint": settings.mu_joint, "mu_base": settings.mu_base, **self.summary()}

    def text(self, label: str, lam: float) -> str:
        """What ``archdem threshold`` prints of the search on ``label`` of static multiplier ``lam``: the threshold,
        its bracket, the survival bands above it, the cost, and the verdict with its readings if checked."""
        checked = "" if self.verdict is None else "\n" + "\n".join(self.verdict.lines())
        if self.amplitude_g is None:
            return (f"{label} {self.freq:g} Hz: no collapse up to {self.a_range_g[1]:.3f} g ({self.n_sims} runs, "
                    f"{self.wall_s:.1f} s)" + checked)
        above = ", ".join(f"{b['from_g']:.3f}-{b['to_g']:.3f} g" for b in self.survival_bands_above)
        return (f"{label} {self.freq:g} Hz: least collapsing amplitude {self.amplitude_g:.4f} g (bracket "
                f"{self.bracket_g[0]:.4f}-{self.bracket_g[1]:.4f}, {self.mode}, {self.phase}); static lambda {lam:.4f}"
                + (f"; survives again {above}" if above else "") + f"; {self.n_sims} runs, {self.wall_s:.1f} s" + checked)


#: Where the engines are known to split (docs/decisions/011-dynamics-engine.md#settled-or-a-range): a pulse
#: strictly between these frequencies [Hz] with some friction below NO_SLIDING_MU gets the LMGC90 check; the
#: study found every split at 6 and 8 Hz with the joints free to slide, none at 4 or 10 Hz.
SPLIT_BAND_HZ = (4.0, 10.0)
REFERENCE_ENGINE = "lmgc90"
#: A check reads the bracket alike when it stands at its survival end / CHECK_MARGIN and collapses at its
#: collapse end x CHECK_MARGIN: thresholds within 5 %, the engines' scatter where they agree (up to 4.3 %).
CHECK_MARGIN = 1.05


@dataclass(frozen=True)
class Reading:
    """One run of a threshold's check: ``engine`` at protocol step ``dt`` [s], amplitude [g], outcome,
    mode and the joints that slid (state ``slide`` or ``hinge+slide`` over the mode window);
    ``check``: ``search`` (the search's own run), ``half step`` or the reference engine's name."""

    check: str
    engine: str
    dt: float
    amplitude_g: float
    collapsed: bool
    mode: str
    joints: tuple[str, ...] = ()

    def to_dict(self) -> dict:
        return {"check": self.check, "engine": self.engine, "dt": self.dt, "amplitude_g": self.amplitude_g,
                "collapsed": self.collapsed, "mode": self.mode, "joints": list(self.joints)}


@dataclass(frozen=True)
class Verdict:
    """Whether a threshold is the arch's or a reading of an engine at a step (:func:`check_threshold`).

    ``status``: ``settled`` (every check reads the search's bracket), ``range`` (some check does not:
    the least collapsing amplitude lies in ``[low_g, high_g]`` [g] by the readings; ``low_g`` None: some
    check collapses down to the bottom of the scan, ``high_g`` None: some check stands up to its top),
    or ``unchecked`` (``why``). ``checks``: those run; ``readings``: every run, the search's two first;
    ``wall_s``: the checks' cost [s]."""

    status: str
    why: str = ""
    low_g: float | None = None
    high_g: float | None = None
    checks: tuple[str, ...] = ()
    readings: tuple[Reading, ...] = ()
    wall_s: float = 0.0

    def text(self) -> str:
        """One line: ``settled (half step, lmgc90; within 5%)``, ``range 0.840-none up to 1.245 g (why)``,
        ``unchecked (why)``."""
        if self.status == "settled":
            return f"settled ({', '.join(self.checks)}; within {CHECK_MARGIN - 1:.0%})"
        if self.status == "unchecked":
            return f"unchecked ({self.why})"
        top = max(r.amplitude_g for r in self.readings)
        lo = "below the scan" if self.low_g is None else f"{self.low_g:.3f}"
        hi = f"none up to {top:.3f}" if self.high_g is None else f"{self.high_g:.3f}"
        return f"range {lo}-{hi} g ({self.why})"

    def lines(self) -> list[str]:
        """The verdict, the checks' count and cost, then its readings one a line."""
        n = sum(r.check != "search" for r in self.readings)
        return [f"  {self.text()}; {n} check runs, {self.wall_s:.1f} s"] + [
            f"    {r.check:<9} {r.engine:<8} dt {r.dt * 1e3:g} ms  {r.amplitude_g:.4f} g "
            f"{'collapsed' if r.collapsed else 'stands':<9} {r.mode}" + (f" (slid: {' '.join(r.joints)})" if r.joints else "")
            for r in self.readings]

    def to_dict(self) -> dict:
        return {"status": self.status, "text": self.text(), "why": self.why, "range_g": [self.low_g, self.high_g],
                "checks": list(self.checks), "readings": [r.to_dict() for r in self.readings], "wall_s": self.wall_s}


NOT_CHECKED = Verdict("unchecked", "not checked")


def reference_needed(freq: float, settings: Settings) -> bool:
    """Whether a threshold at ``freq`` [Hz] gets the reference engine's check: inside :data:`SPLIT_BAND_HZ`
    with some joint free to slide (a friction below ``NO_SLIDING_MU``), whatever its collapse mode reads
    (the study's splits read rocking as often as sliding)."""
    lo, hi = SPLIT_BAND_HZ
    return lo < freq < hi and min(settings.mu_joint, settings.mu_base) < NO_SLIDING_MU


def reference_settings(settings: Settings) -> Settings:
    """The reference engine's settings for a check: ``settings`` on LMGC90 at its own default step."""
    return settings.with_(engine=REFERENCE_ENGINE, dt=Settings().dt)


def reference_unavailable(model: Model, settings: Settings) -> str:
    """Why the reference engine cannot check ``model`` with ``settings`` ("" when it can)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.core.engines import engine_installed
    from dem.core.engines.lmgc90_engine import DEFAULT_OPTIONS, build_message

    if not engine_installed(REFERENCE_ENGINE):
        return "LMGC90 is not installed"
    if model.ties:
        return "LMGC90 runs no tie-rods"
    try:
        build_message(model, reference_settings(settings), DEFAULT_OPTIONS)
    except ArchdemInputError as e:
        return str(e).split(";")[0].replace("the lmgc90 engine", "LMGC90")
    return ""


def _read_one(args) -> Reading:
    """One check run: ``(check, model, settings, protocol, motion_fn, a_g, freq)``."""
    check, model, settings, protocol, motion_fn, a_g, freq = args
    r = shake(model, motion_fn(a_g * G, freq), settings, protocol, friction_work=False)
    slid = tuple(j.joint for j in r.sim.joints if "slide" in j.state)
    return Reading(check, settings.engine, settings.dt, float(a_g), bool(r.collapsed), r.mode, slid)


def _walk(read: Callable[[float], Reading], start: Reading, amps: Sequence[float]) -> tuple[list[Reading], float | None]:
    """Read ``amps`` in order, after ``start``, until the outcome differs from ``start``'s: the new runs and
    the amplitude where that check's least collapse lies — the last collapsing amplitude walking down, the
    first walking up — or None when the walk ends without a change."""
    runs: list[Reading] = []
    prev = start
    for a in amps:
        runs.append(read(a))
        if runs[-1].collapsed != start.collapsed:
            return runs, (prev if not runs[-1].collapsed else runs[-1]).amplitude_g
        prev = runs[-1]
    return runs, None


def check_threshold(res: ThresholdResult, model: Model, settings: Settings, protocol: ShakeProtocol | None = None,
                    motion_fn: Callable[[float, float], GroundMotion] = sine_motion, workers: int = 1,
                    reference: bool | None = None) -> Verdict:
    """Settled or a range: rerun the two ends of ``res``'s bracket (last survival / :data:`CHECK_MARGIN`,
    first collapse x :data:`CHECK_MARGIN`; the top of the scan when nothing collapsed) at half the protocol
    step and, where :func:`reference_needed` (or ``reference`` True), on LMGC90 at its default step. A check
    that reads them otherwise walks the scan's amplitudes away from the bracket (up when it stands at the
    upper end, down when it collapses at the lower) until its outcome changes, so the range holds its
    threshold too. ``workers``: processes for the bracket's runs; ``reference``: False never asks LMGC90
    (a threshold that needs it is then "unchecked"), True always, None by the rule.
    docs/decisions/011-dynamics-engine.md#settled-or-a-range."""
    wall0 = time.perf_counter()
    protocol = protocol or ShakeProtocol()
    if res.a_range_g is None:
        return NOT_CHECKED
    a_min, a_max = res.a_range_g
    grid = [float(a) for a in scan_grid(a_min, a_max, res.scan_ratio)]
    if res.bracket_g is None:
        ends: list[tuple[float, bool]] = [(grid[-1], False)]  # nothing collapsed: the top stands
        asked = [grid[-1]]
    else:
        ends = [(res.bracket_g[0], False), (res.bracket_g[1], True)]
        asked = [res.bracket_g[0] / CHECK_MARGIN, res.bracket_g[1] * CHECK_MARGIN]
    searched = {round(r.amplitude_g, 12): r for r in res.runs}
    readings = [Reading("search", settings.engine, settings.dt, a, c, getattr(searched.get(round(a, 12)), "mode", ""))
                for a, c in ends]
    ends = [(a, c) for a, (_, c) in zip(asked, ends)]
    checks = [("half step", settings.with_(dt=0.5 * settings.dt))]
    why_not = ""
    if settings.engine != REFERENCE_ENGINE and (reference is True or reference_needed(res.freq, settings)):
        why_not = "LMGC90 not asked" if reference is False else reference_unavailable(model, settings)
        if not why_not:
            checks.append((REFERENCE_ENGINE, reference_settings(settings)))
    # each reading's least collapsing amplitude [g] on the scan: inf none up to the top, -inf down to the bottom
    found = [math.inf if res.amplitude_g is None else res.amplitude_g]
    moved = []

    def run(name: str, st: Settings) -> tuple[list[Reading], float | None, str]:
        """The check's runs, where its threshold lies (None: it reads the bracket alike) and what it read."""
        got = _map(_read_one, [(name, model, st, protocol, motion_fn, a, res.freq) for a, _ in ends], workers)
        if all(r.collapsed == c for r, (_, c) in zip(got, ends)):
            return got, None, ""
        read = lambda a: _read_one((name, model, st, protocol, motion_fn, a, res.freq))  # noqa: E731
        if got[0].collapsed:  # collapses below the last survival (or at the top): walk down the scan
            a0 = ends[0][0]
            walked, at = _walk(read, got[0], [a for a in reversed(grid) if a < a0 * (1 - 1e-9)])
            return got + walked, -math.inf if at is None else at, (
                f"{name} collapses at {a0:.3f} g" + (" and down to the bottom of the scan" if at is None else ""))
        a0 = ends[-1][0]  # stands above the first collapse: walk up the scan
        walked, at = _walk(read, got[-1], [a for a in grid if a > a0 * (1 + 1e-9)])
        return got + walked, math.inf if at is None else at, (
            f"{name} stands at {a0:.3f} g" + (" and up to the top of the scan" if at is None else ""))

    for name, st in list(checks):
        try:
            runs, at, what = run(name, st)
        except RuntimeError as e:  # the reference's worker died: the search stands, unchecked by it
            if name != REFERENCE_ENGINE:
                raise
            why_not = f"LMGC90 failed: {str(e).splitlines()[0]}"
            checks.remove((name, st))
            continue
        readings += runs
        if at is not None:
            found.append(at)
            moved.append(what)
    names = tuple(n for n, _ in checks)
    wall = time.perf_counter() - wall0
    if moved:
        low, high = min(found), max(found)
        why = "; ".join(moved) + (f"; {why_not}" if why_not else "")
        return Verdict("range", why, None if low == -math.inf else low, None if high == math.inf else high, names,
                       tuple(readings), wall)
    if why_not:
        return Verdict("unchecked", why_not, checks=names, readings=tuple(readings), wall_s=wall)
    return Verdict("settled", "", checks=names, readings=tuple(readings), wall_s=wall)


def _run_one(args) -> Outcome:
    model, settings, protocol, motion_fn, a_g, freq = args
    c, mode, phase = collapses(model, motion_fn(a_g * G, freq), settings, protocol)
    return Outcome(float(a_g), bool(c), mode, phase)


def scan_grid(a_min_g: float, a_max_g: float, ratio: float) -> np.ndarray:
    """Geometric amplitudes [g] from ``a_min_g`` to ``a_max_g`` with step ratio at most ``ratio``."""
    if not (0 < a_min_g < a_max_g and math.isfinite(a_max_g)):
        raise ArchdemInputError(f"amplitude range must satisfy 0 < a_min < a_max, got {a_min_g:g}, {a_max_g:g} g")
    if not (ratio > 1):
        raise ArchdemInputError(f"scan ratio must be > 1, got {ratio:g}")
    n = int(math.ceil(math.log(a_max_g / a_min_g) / math.log(ratio) - 1e-9)) + 1
    return np.geomspace(a_min_g, a_max_g, max(n, 2))


def _map(fn, jobs: list, workers: int, scheduler: str | None = None, on_done: Callable | None = None) -> list:
    """``[fn(j) for j in jobs]``, on ``workers`` processes (or a Dask ``scheduler``); ``on_done(k, result)``
    as each finishes."""
    out: list = [None] * len(jobs)
    if not scheduler and (workers <= 1 or len(jobs) <= 1):
        for k, j in enumerate(jobs):
            out[k] = fn(j)
            if on_done is not None:
                on_done(k, out[k])
        return out
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import executor

    with executor(min(workers, len(jobs)), scheduler) as (ex, _):
        running = {ex.submit(fn, j): k for k, j in enumerate(jobs)}
        while running:
            done, _ = wait(running, return_when=FIRST_COMPLETED)
            for f in done:
                k = running.pop(f)
                out[k] = f.result()
                if on_done is not None:
                    on_done(k, out[k])
    return out


def bisections(scan_ratio: float, tol: float) -> int:
    """Geometric bisections that narrow one scan step (``scan_ratio``) to ``hi / lo - 1 <= tol``."""
    return max(0, math.ceil(math.log2(math.log(scan_ratio) / math.log1p(tol)) - 1e-9))


class _RunProgress:
    """The progress of a threshold search: runs done of those expected (the scan, then the bisections
    of the lowest bracket), the amplitude just run and the bracket."""

    def __init__(self, progress: Progress | None, n_scan: int, n_bisect: int):
        self.progress, self.n_scan, self.n_bisect, self.done = progress, n_scan, n_bisect, 0

    def ran(self, r: Outcome, bracket: str = "", total: int | None = None) -> None:
        self.done += 1
        if self.progress is not None:
            total = self.n_scan + self.n_bisect if total is None else total
            self.progress(self.done, max(total, self.done), f"{r.amplitude_g:.4f} g "
                          f"{'collapsed' if r.collapsed else 'survived'}" + (f"; {bracket}" if bracket else ""))


def _lowest_bracket(scan: list) -> int | None:
    """Index of the lowest collapsing scan amplitude once every amplitude below it is known
    (and survived); -1 if every amplitude is known and none collapsed; None while unknown."""
    for k, r in enumerate(scan):
        if r is None:
            return None
        if r.collapsed:
            return k
    return -1


def _scan_and_bisect(grid: np.ndarray, job: Callable, workers: int, tol: float, max_sims: int,
                     scheduler: str | None = None, track: _RunProgress | None = None,
                     ) -> tuple[list[Outcome], list[Outcome], tuple[float, float, Outcome] | None]:
    """Outcomes of the scan (in grid order) and of the bisection of its lowest survival ->
    collapse bracket (in order; geometric midpoints until ``hi / lo - 1 <= tol`` or ``max_sims``
    runs in all), and the final ``(lo, hi, run at hi)``; no bisection and None when the lowest
    amplitude collapses or nothing does.

    With several ``workers`` the bisection starts as soon as the scan below its bracket is known
    and has priority on the next free process, while the rest of the scan fills the others: the
    bisection no longer waits for the top of the scan, and no process idles behind its serial
    chain while scan amplitudes remain (the thresholds of the campaign: 11 rounds of simulations
    become about 9 on two cores). Every run is the one the serial order would make, so the
    answer does not depend on the number of processes. ``track``: told of every run as it ends."""
    n = len(grid)
    scan: list[Outcome | None] = [None] * n
    bis: list[Outcome] = []
    bracket: Bracket | None = None  # the bisection's, once the scan below it is known

    def next_mid() -> float | None:
        nonlocal bracket
        if bracket is None:
            k = _lowest_bracket(scan)
            if k is None or k <= 0:
                return None
            bracket = Bracket(scan[k - 1].amplitude_g, scan[k].amplitude_g, tol, "ratio", True, scan[k - 1], scan[k])
        if bracket.wide() and n + len(bis) < max_sims:
            return bracket.mid()
        return None

    def told(r: Outcome) -> None:
        if track is None:
            return
        if bracket is not None:
            # the bisections still to come, once the lowest bracket is known
            left = bisections(bracket.hi / bracket.lo, tol) if bracket.wide() else 0
            total = n + len(bis) + min(left, max_sims - n - len(bis))
            track.ran(r, f"bracket [{bracket.lo:.4f}, {bracket.hi:.4f}] g", total)
        elif (k := _lowest_bracket(scan)) is not None and k <= 0:  # nothing to bisect: the scan is all
            track.ran(r, "", n)
        else:
            track.ran(r)

    def scanned(i: int, r: Outcome) -> None:
        scan[i] = r
        next_mid()  # the bracket, as soon as it is known
        told(r)

    def take(r: Outcome) -> None:
        bis.append(r)
        bracket.take(r.amplitude_g, r.collapsed, r)
        told(r)

    def result():
        return list(scan), bis, None if bracket is None else (bracket.lo, bracket.hi, bracket.hi_run)

    if workers <= 1 and not scheduler:
        for i, a in enumerate(grid):
            scanned(i, _run_one(job(a)))
        while (mid := next_mid()) is not None:
            take(_run_one(job(mid)))
        return result()
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import executor

    with executor(min(workers, n), scheduler) as (ex, workers):
        running: dict = {}  # future -> scan index, or None for the bisection's run
        nxt = 0
        while True:
            while len(running) < workers:
                mid = None if None in running.values() else next_mid()
                if mid is not None:
                    running[ex.submit(_run_one, job(mid))] = None
                elif nxt < n:
                    running[ex.submit(_run_one, job(grid[nxt]))] = nxt
                    nxt += 1
                else:
                    break
            if not running:
                return result()
            done, _ = wait(running, return_when=FIRST_COMPLETED)
            for f in done:
                i = running.pop(f)
                if i is None:
                    take(f.result())
                else:
                    scanned(i, f.result())


def _bands(runs: Sequence[Outcome], first: float | None) -> tuple[dict, ...]:
    rs = sorted(runs, key=lambda r: r.amplitude_g)
    bands: list[dict] = []
    for k, r in enumerate(rs):
        if bands and bands[-1]["collapse"] == r.collapsed:
            bands[-1]["to_g"] = r.amplitude_g
            continue
        if bands:
            lo = rs[k - 1].amplitude_g
            edge = first if (first is not None and r.collapsed and lo < first <= r.amplitude_g * (1 + 1e-12)
                             and not any(b["collapse"] for b in bands)) else math.sqrt(lo * r.amplitude_g)
            bands[-1]["to_g"] = edge
            bands.append({"from_g": edge, "to_g": r.amplitude_g, "outcome": "collapse" if r.collapsed else "survival",
                          "collapse": r.collapsed, "edge_bracket_g": [lo, r.amplitude_g]})
        else:
            bands.append({"from_g": r.amplitude_g, "to_g": r.amplitude_g,
                          "outcome": "collapse" if r.collapsed else "survival", "collapse": r.collapsed,
                          "edge_bracket_g": None})
    return tuple(bands)


def static_onset(model: Model, settings: Settings) -> float:
    """Static collapse multiplier ``lambda`` of the model's blocks at the settings' frictions (the static
    LP, :func:`analytic.limit.limit_discrete.solve_lp`): no pulse below ``lambda g`` moves the arch."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import solve_lp

    if model.assembly is None:
        raise ArchdemInputError(f"{model.name}: the static onset needs the blocks the model was built from")
    return float(solve_lp(model.assembly, settings.mu_joint, settings.mu_base).lam)


@dataclass(frozen=True)
class ThresholdSpec:
    """A threshold search: the least collapsing amplitude [g] of ``motion_fn(a, freq)`` (a [m/s^2], ``freq``
    [Hz]; a plain one-cycle sine by default) on ``target`` (a specimen id, Specimen, PointedArch, Assembly or
    Model, see :func:`dem.core.model.as_model`, an arch cut in ``config``) with ``settings`` and ``protocol``.
    The scan runs from ``a_min_g`` (default: the static onset, :func:`static_onset`; nothing moves below it)
    to ``a_max_g`` (default ``SCAN_TOP`` x ``a_min_g``) by ``scan_ratio``, the bisection to ``tol``, at most
    ``max_sims`` runs. ``check``: give the result its settled-or-range verdict (:func:`check_threshold`;
    otherwise it reads "unchecked"); ``"half-step"``: the half-step check only (where LMGC90 would be asked
    the verdict reads "unchecked", never settled)."""

    target: Any
    freq: float
    settings: Settings = field(default_factory=dynamics_settings)
    protocol: ShakeProtocol = field(default_factory=ShakeProtocol)
    a_min_g: float | None = None
    a_max_g: float | None = None
    scan_ratio: float = 1.15
    tol: float = 0.01
    max_sims: int = 60
    config: str = "glued"
    check: bool | str = False
    motion_fn: Callable[[float, float], GroundMotion] = sine_motion


def threshold(target, freq: float, settings: Settings | None = None, protocol: ShakeProtocol | None = None,
              a_min_g: float | None = None, a_max_g: float | None = None, scan_ratio: float = 1.15, tol: float = 0.01,
              workers: int | None = None, motion_fn: Callable[[float, float], GroundMotion] = sine_motion,
              max_sims: int = 60, config: str = "glued", scheduler: str | None = None,
              progress: Progress | None = None, check: bool | str = False) -> ThresholdResult:
    """Least collapsing amplitude [g] of ``motion_fn(a, freq)`` on ``target``: :func:`run` of the
    :class:`ThresholdSpec` of these arguments."""
    spec = ThresholdSpec(target, freq, settings or dynamics_settings(), protocol or ShakeProtocol(), a_min_g, a_max_g,
                         scan_ratio, tol, max_sims, config, check, motion_fn)
    return run(spec, workers, scheduler, progress)


def run(spec: ThresholdSpec, workers: int | None = None, scheduler: str | None = None,
        progress: Progress | None = None) -> ThresholdResult:
    """The search of ``spec``; see the module docstring. ``workers``: processes for the scan (default all
    cores, 1 = serial); ``scheduler``: a Dask scheduler address to run on instead. ``progress(done, total,
    note)``: called as each run ends (:mod:`dem.core.progress`; ``done`` runs of ``total`` expected, ``note``
    the amplitude, its outcome and the bracket)."""
    model = as_model(spec.target, config=spec.config)
    settings, protocol, motion_fn = spec.settings, spec.protocol, spec.motion_fn
    workers = (os.cpu_count() or 1) if workers is None else int(workers)
    res = _search(model, spec.freq, settings, protocol, spec.a_min_g, spec.a_max_g, spec.scan_ratio, spec.tol, workers,
                  motion_fn, spec.max_sims, scheduler, progress)
    if not spec.check:
        return res
    if progress is not None:
        progress(res.n_sims, res.n_sims, "checking the bracket")
    reference = False if spec.check == "half-step" else None
    return replace(res, verdict=check_threshold(res, model, settings, protocol, motion_fn, workers, reference))


def _search(model: Model, freq: float, settings: Settings, protocol: ShakeProtocol, a_min_g: float | None,
            a_max_g: float | None, scan_ratio: float, tol: float, workers: int,
            motion_fn: Callable[[float, float], GroundMotion], max_sims: int, scheduler: str | None,
            progress: Progress | None) -> ThresholdResult:
    """The search of :func:`threshold` (its arguments, resolved)."""
    if not (math.isfinite(freq) and freq > 0):
        raise ArchdemInputError(f"frequency must be a positive number of Hz, got {freq!r}")
    if not (0 < tol < 0.5):
        raise ArchdemInputError(f"bisection tolerance must be in (0, 0.5), got {tol!r}")
    wall0 = time.perf_counter()
    a_min_g = static_onset(model, settings) if a_min_g is None else a_min_g
    a_max_g = SCAN_TOP * a_min_g if a_max_g is None else a_max_g
    grid = scan_grid(a_min_g, a_max_g, scan_ratio)
    job = lambda a: (model, settings, protocol, motion_fn, float(a), float(freq))  # noqa: E731
    track = _RunProgress(progress, len(grid), bisections(scan_ratio, tol))
    if progress is not None:
        progress(0, track.n_scan + track.n_bisect, f"scan {a_min_g:.4f}-{a_max_g:.4f} g")
    scan, bis, bracket = _scan_and_bisect(grid, job, workers, tol, max_sims, scheduler, track)
    runs = scan + bis
    if not any(r.collapsed for r in scan):
        return ThresholdResult(float(freq), None, None, _bands(runs, None), tuple(runs), scan_ratio, tol,
                               time.perf_counter() - wall0, a_range_g=(a_min_g, a_max_g))
    if bracket is not None:  # the lowest scan bracket was bisected alongside the scan
        lo, hi, hi_r = bracket
        return ThresholdResult(float(freq), float(hi), (float(lo), float(hi)), _bands(runs, hi), tuple(runs),
                               scan_ratio, tol, time.perf_counter() - wall0, hi_r.mode, hi_r.phase, a_range_g=(a_min_g, a_max_g))
    # the lowest scanned amplitude collapses: step down (at most 6 times) until something survives, then bisect

    ends: list[float] = []  # the bracket being bisected, once found

    def run(a: float) -> Outcome:
        r = _run_one(job(a))
        runs.append(r)
        if not ends:
            track.ran(r, "stepping down below the scan", len(runs) + 1 + track.n_bisect)
            return r
        ends[r.collapsed] = a
        left = bisections(ends[1] / ends[0], tol) if ends[1] / ends[0] - 1 > tol else 0
        track.ran(r, f"bracket [{ends[0]:.4f}, {ends[1]:.4f}] g", min(len(runs) + left, max_sims))
        return r

    a0 = scan[0].amplitude_g
    below = search(run, a0 / scan_ratio, a0, math.inf, rule="ratio", is_upper=lambda r: r.collapsed, hi_run=scan[0],
                   down=lambda a: a / scan_ratio, ends="first", max_down=6)  # tol inf: find the bracket only
    if below.status == "no_lower":
        raise ArchdemInputError(f"collapse at every amplitude down to {below.hi:.4g} g; lower --a-min")
    ends += [below.lo, below.hi]
    res = search(run, below.lo, below.hi, tol, rule="ratio", geometric=True, is_upper=lambda r: r.collapsed,
                 lo_run=below.lo_run, hi_run=below.hi_run, max_runs=max_sims - len(runs))
    lo, hi, hi_r = res.lo, res.hi, res.hi_run
    return ThresholdResult(float(freq), float(hi), (float(lo), float(hi)), _bands(runs, hi), tuple(runs), scan_ratio,
                           tol, time.perf_counter() - wall0, hi_r.mode, hi_r.phase, a_range_g=(a_min_g, a_max_g))


def _threshold_job(args) -> ThresholdResult:
    # a threshold at one frequency of a domain: its runs are not reported one by one (it may run in a worker)
    model, freq, settings, protocol, kw = args
    return threshold(model, freq, settings, protocol, workers=1, **kw)


def failure_domain(model: Model, freqs: Sequence[float], settings: Settings | None = None,
                   protocol: ShakeProtocol | None = None, workers: int | None = None, scheduler: str | None = None,
                   progress: Progress | None = None, **kw) -> dict:
    """DEM failure domain: :func:`threshold` at every frequency [Hz], in parallel over the grid
    (``workers`` processes, default all cores; or a Dask ``scheduler``). ``kw`` go to :func:`threshold` (amplitude range,
    scan ratio, tol). Returns a dict shaped like the analytic domain JSON: ``points`` (``x`` [Hz],
    ``amplitude_g``, ``mode``: the collapse phase mapped to the analytic names), ``bands``
    (``x``, ``from_g``, ``to_g``, ``outcome``, ``collapse``) and ``thresholds`` (full summaries).
    ``progress(done, total, note)``: called as each frequency's threshold is found (:mod:`dem.core.progress`)."""
    freqs = [float(f) for f in freqs]
    if not freqs or not all(math.isfinite(f) and f > 0 for f in freqs):
        raise ArchdemInputError("the frequency grid must contain positive numbers")
    settings = settings or dynamics_settings()
    protocol = protocol or ShakeProtocol()
    workers = (os.cpu_count() or 1) if workers is None else int(workers)
    wall0 = time.perf_counter()
    n_done = 0

    def done(k: int, r: ThresholdResult) -> None:
        nonlocal n_done
        n_done += 1
        a = "no collapse" if r.amplitude_g is None else f"{r.amplitude_g:.4f} g"
        progress(n_done, len(freqs), f"{r.freq:g} Hz: {a}")

    if progress is not None:
        progress(0, len(freqs), f"{len(freqs)} frequencies")
    res = _map(_threshold_job, [(model, f, settings, protocol, kw) for f in freqs], workers, scheduler,
               None if progress is None else done)
    names = {"before-first-rebound": "first-half-cycle", "after-first-rebound": "after-impact"}
    points, bands = [], []
    for r in res:
        if r.amplitude_g is not None:
            points.append({"x": r.freq, "amplitude_g": r.amplitude_g, "mode": names.get(r.phase or "", r.phase),
                           "dem_mode": r.mode})
        # further survival -> collapse edges (scan resolution)
        for b0, b1 in zip(r.bands[:-1], r.bands[1:]):
            if not b0["collapse"] and b1["collapse"] and r.amplitude_g is not None and b1["from_g"] > r.amplitude_g * 1.001:
                points.append({"x": r.freq, "amplitude_g": b1["from_g"], "mode": "collapse", "dem_mode": ""})
        bands += [{"x": r.freq, **{k: b[k] for k in ("from_g", "to_g", "outcome", "collapse")}} for b in r.bands]
    return {"engine": "dem", "points": points, "bands": bands, "thresholds": [r.summary() for r in res],
            "wall_s": time.perf_counter() - wall0}
