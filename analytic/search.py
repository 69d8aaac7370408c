"""Bracket-and-bisect: the one search behind every threshold of archdem.

A threshold is the least ``x`` at which an outcome turns "upper" (collapse, rocking, ...): a
bracket ``[lo, hi]`` has a run at ``lo`` that is not upper and one at ``hi`` that is. The
bracket is halved at its midpoint

    arithmetic: m = (lo + hi) / 2,        geometric: m = sqrt(lo hi),

and the half that still brackets the change is kept, until it is narrow by its rule:

    "width/hi": hi - lo <= tol hi      "width/lo": hi - lo <= tol lo
    "ratio":    hi / lo - 1 <= tol     "width":    hi - lo <= tol

The answer is ``hi``, an ``x`` that was run and found upper. :func:`search` also finds the first
bracket from a guess of its ends, running an end only when it is needed and moving a wrong end
outward (``up`` / ``down``); :class:`Bracket` is the step-by-step form for callers that run
several evaluations at once. Used by the tilt test (levels), shake thresholds, the friction
map (mu*) and the analytic failure domains (docs/physics/dem.md#7-tilt-test-hold-and-bisect).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable

RULES = ("width/hi", "width/lo", "ratio", "width")


def midpoint(lo: float, hi: float, geometric: bool = False) -> float:
    """The point that halves ``[lo, hi]``: arithmetically, or geometrically (``lo > 0``)."""
    return math.sqrt(lo * hi) if geometric else 0.5 * (lo + hi)


def wide(lo: float, hi: float, tol: float, rule: str = "width/hi") -> bool:
    """True while ``[lo, hi]`` is wider than ``tol`` by ``rule`` (module docstring)."""
    if rule == "width/hi":
        return (hi - lo) > tol * hi
    if rule == "width/lo":
        return hi - lo > tol * lo
    if rule == "ratio":
        return hi / lo - 1 > tol
    if rule == "width":
        return hi - lo > tol
    raise ValueError(f"unknown bracket rule {rule!r}; one of {', '.join(RULES)}")


@dataclass
class Bracket:
    """A bracket being narrowed: its ends and the runs at them (None: the end is a guess, not run)."""

    lo: float
    hi: float
    tol: float
    rule: str = "width/hi"
    geometric: bool = False
    lo_run: Any = None
    hi_run: Any = None

    def wide(self) -> bool:
        return wide(self.lo, self.hi, self.tol, self.rule)

    def mid(self) -> float:
        return midpoint(self.lo, self.hi, self.geometric)

    def take(self, x: float, upper: bool, run: Any) -> None:
        """Narrow to the half that still brackets the change, given the run at ``x``."""
        if upper:
            self.hi, self.hi_run = x, run
        else:
            self.lo, self.lo_run = x, run


@dataclass(frozen=True)
class SearchResult:
    """The final bracket and its runs; ``runs``: evaluations made; ``status``: ``"converged"`` (both
    ends run, narrow), ``"budget"`` (both ends run, ``max_runs`` reached first), ``"no_upper"`` (no
    upper run below ``limit``: ``hi`` is where the next try would have been), ``"no_lower"`` (every
    run below was upper for ``max_down`` steps down) or ``"unbracketed"`` (``max_runs`` reached with an
    end never run: the bracket is not one)."""

    lo: float
    hi: float
    lo_run: Any
    hi_run: Any
    runs: int
    status: str

    @property
    def bracketed(self) -> bool:
        return self.status in ("converged", "budget")


class _Stop(Exception):
    def __init__(self, status: str):
        self.status = status


def search(evaluate: Callable[[float], Any], lo: float, hi: float, tol: float, *, rule: str = "width/hi",
           geometric: bool = False, is_upper: Callable[[Any], bool] = bool, lo_run: Any = None, hi_run: Any = None,
           up: Callable[[float], float] | None = None, down: Callable[[float], float] | None = None,
           ends: str = "last", limit: float = math.inf, max_runs: float = math.inf, max_down: float = math.inf,
           on_run: Callable[[float, Any], None] | None = None) -> SearchResult:
    """Bracket the change of ``is_upper(evaluate(x))`` and bisect it to ``tol`` by ``rule``.

    ``lo``/``hi``: the first bracket; an end whose run is not given (``lo_run``/``hi_run`` None) is a
    guess, run only when needed: ``ends="last"`` bisects at once and runs a guessed end only if the
    bisection ends on it, ``"first"`` runs the guessed ends before bisecting (upper first). An end
    found wrong moves the bracket: an ``hi`` that is not upper becomes ``lo`` and ``hi = up(hi)``
    (stopping with ``"no_upper"`` above ``limit`` or at ``max_runs``); a ``lo`` that is upper becomes
    ``hi`` and ``lo = down(lo)`` (``"no_lower"`` after ``max_down`` such steps). ``on_run(x, run)``
    is called after every evaluation, in order; at most ``max_runs`` evaluations are made. Nothing
    else is stored between runs, so the runs depend only on the outcomes.
    """
    if ends not in ("first", "last"):
        raise ValueError(f"ends must be 'first' or 'last', got {ends!r}")
    if (hi_run is None and up is None) or (lo_run is None and down is None):
        raise ValueError("a guessed end (no run given) needs its way out: up for hi, down for lo")
    b = Bracket(lo, hi, tol, rule, geometric, lo_run, hi_run)
    runs = downs = 0

    def run(x: float) -> Any:
        nonlocal runs
        r = evaluate(x)
        runs += 1
        if on_run is not None:
            on_run(x, r)
        return r

    def probe_hi() -> bool:
        """Run the guessed upper end; False: it was not upper, and the bracket moved up."""
        r = run(b.hi)
        if is_upper(r):
            b.hi_run = r
            return True
        b.lo, b.lo_run = b.hi, r
        b.hi = up(b.hi)
        if b.hi > limit or runs >= max_runs:
            raise _Stop("no_upper")
        return False

    def probe_lo() -> bool:
        """Run the guessed lower end; False: it was upper, and the bracket moved down."""
        nonlocal downs
        r = run(b.lo)
        downs += 1
        if not is_upper(r):
            b.lo_run = r
            return True
        b.hi, b.hi_run = b.lo, r
        if downs >= max_down:
            raise _Stop("no_lower")
        b.lo = down(b.lo)
        return False

    try:
        if ends == "first":
            while b.hi_run is None and runs < max_runs and not probe_hi():
                pass
            while b.lo_run is None and runs < max_runs and not probe_lo():
                pass
        while True:
            while b.wide() and runs < max_runs:
                x = b.mid()
                r = run(x)
                b.take(x, is_upper(r), r)
            if b.hi_run is None and runs < max_runs and not probe_hi():
                continue
            if b.lo_run is None and runs < max_runs and not probe_lo():
                continue
            break
        status = "unbracketed" if b.lo_run is None or b.hi_run is None else ("budget" if b.wide() else "converged")
    except _Stop as stop:
        status = stop.status
    return SearchResult(b.lo, b.hi, b.lo_run, b.hi_run, runs, status)
