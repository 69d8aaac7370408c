"""Time integration of a rocking mechanism across impacts (docs/physics/dynamics.md#6-time-integration-and-the-collapse-rule).

:func:`simulate` integrates ``M phi'' + M'/2 phi'^2 + V' = -a_g(t) sum m x'`` with
``scipy.integrate.solve_ivp`` (DOP853, tight tolerances) and event detection: an impact at
``phi = 0`` hands over to the post-impact mechanism of :mod:`analytic.rocking.impact`; at rest the
mechanism (either direction) starts when the generalised force exceeds ``V'(0)``.

**Collapse rule**: the mechanism passes ``phi_cr`` after the input has ended (gravity then
drives it on: rule ``"phi_cr-after-input"``), or reaches the rotation limit ``phi_limit`` of its
linkage at any time (rule ``"rotation-limit"``). Passing ``phi_cr`` while the input acts is not
collapse. **Survival** is certified once the input has ended and the mechanical energy is below
the energy barrier of the moving mechanism and of the one that follows its next impact (energy
cannot grow without input: rule ``"energy"``), or the mechanism is at rest when the input ends
(``"rest"``), or the simulated time runs out (``"time-out"``). ``mode``: ``"first-half-cycle"``
(collapse before the first impact) or ``"after-impact"``.

:func:`linearised_collapse` is the conservative quick estimate: the equation linearised at
``phi = 0`` (constant coefficients) solved in closed form by Duhamel's integral over the first
half-cycle, with the energy criterion of the linear system at the end of the input.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import cumulative_trapezoid, solve_ivp
from scipy.optimize import brentq

from analytic.motions.inputs import GroundMotion, PulseA, PulseB, SinePulse
from analytic.rocking.impact import ImpactTransition, post_impact
from analytic.rocking.mechanism import Mechanism
from foundation.errors import ArchdemInputError

RTOL = 1e-10
ATOL = 1e-12
REST_ENERGY = 1e-12  # post-impact kinetic energy / barrier below which the mechanism is at rest


@dataclass(frozen=True)
class ImpactRecord:
    """One impact: time [s], velocities before/after [rad/s] (each of its own mechanism),
    energy restitution of the momentum balance ``e`` and the one applied, mechanism labels, rule."""

    t: float
    phidot_before: float
    phidot_after: float
    e: float
    e_applied: float
    before: str
    after: str
    rule: str


@dataclass(frozen=True)
class Response:
    """Outcome of one time history.

    ``collapsed``; ``rule`` (what decided, see module doc); ``mode`` for a collapse;
    ``t_collapse`` [s]; ``max_ratio``: the largest ``phi / phi_cr`` reached (of the mechanism
    moving); ``residual``: ``phi / phi_cr`` at the end; ``impacts``; ``t_start`` (first motion, None
    if the input never exceeds the onset); the history ``t`` [s], ``ratio`` (signed ``phi / phi_cr``:
    + for mechanisms opened by a positive ground acceleration) and ``phi`` [rad], when recorded.
    """

    collapsed: bool
    rule: str
    mode: str | None
    t_collapse: float | None
    max_ratio: float
    residual: float
    impacts: tuple[ImpactRecord, ...]
    t_start: float | None
    t: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)
    ratio: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)
    phi: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)

    @property
    def n_impacts(self) -> int:
        return len(self.impacts)

    def summary(self) -> dict:
        return {"collapsed": self.collapsed, "rule": self.rule, "mode": self.mode, "t_collapse": self.t_collapse,
                "max_ratio": self.max_ratio, "residual": self.residual, "n_impacts": self.n_impacts,
                "t_start": self.t_start,
                "impacts": [{"t": i.t, "e": i.e, "e_applied": i.e_applied, "mechanism": i.after, "rule": i.rule}
                            for i in self.impacts]}


class _Transitions:
    """Cache of post-impact transitions (one per mechanism)."""

    def __init__(self, restitution: float | None):
        self.restitution = restitution
        self._cache: dict[int, tuple[Mechanism, ImpactTransition]] = {}

    def __call__(self, m: Mechanism) -> ImpactTransition:
        k = id(m)
        if k not in self._cache:
            self._cache[k] = (m, post_impact(m, self.restitution))
        return self._cache[k][1]


def scalar_acceleration(motion: GroundMotion):
    """A fast ``t -> a_g(t)`` [m/s^2] for scalar ``t`` (plain ``math`` for the analytic pulses; the
    motion's own vectorised ``acceleration`` otherwise). Same values as ``motion.acceleration``."""
    if isinstance(motion, SinePulse):
        a, w, ph, T = motion.a, 2 * math.pi * motion.f, motion.phase, motion.duration
        return lambda t: a * math.sin(w * t + ph) if 0.0 <= t <= T else 0.0
    if isinstance(motion, PulseA):
        a, T = motion.a, motion.t_i
        return lambda t: a if 0.0 <= t <= T else 0.0
    if isinstance(motion, PulseB):
        a, T = motion.a, motion.t_i
        return lambda t: -a if 0.0 <= t <= T else (0.5 * a if T < t <= 3 * T else 0.0)
    return lambda t: float(motion.acceleration(t))


def _check_restitution(restitution: float | None) -> None:
    if restitution is not None and not (isinstance(restitution, (int, float)) and 0 <= restitution <= 1):
        raise ArchdemInputError(f"restitution must be 'auto' or a number in [0, 1], got {restitution!r}")


def _excess(m: Mechanism, a: float) -> float:
    """Generalised force at rest minus the gravity threshold, per unit ``V'(0)``."""
    return (a * m.direction - abs(m.onset)) / abs(m.onset)


def _next_start(mechs: list[Mechanism], motion: GroundMotion, t0: float) -> tuple[float, Mechanism] | None:
    """First time ``>= t0`` at which one of ``mechs`` starts moving from rest."""
    t_end = motion.duration
    if t0 >= t_end:
        return None
    bps = [b for b in motion.breakpoints if t0 < b < t_end]
    n = max(400, 4 * len(bps))
    grid = np.unique(np.concatenate([[t0], np.linspace(t0, t_end, n), bps, [t_end]]))
    a = motion.acceleration(grid)
    ex = np.max([(a * m.direction - abs(m.onset)) for m in mechs], axis=0)
    idx = np.nonzero(ex > 0)[0]
    if len(idx) == 0:
        return None
    k = int(idx[0])
    best = max(mechs, key=lambda m: a[k] * m.direction - abs(m.onset))
    if k == 0:
        return float(grid[0]), best
    f = lambda t: float(motion.acceleration(t)) * best.direction - abs(best.onset)  # noqa: E731
    lo, hi = float(grid[k - 1]), float(grid[k])
    if f(lo) > 0:
        return lo, best
    ts = brentq(f, lo, hi, xtol=1e-15 * max(1.0, hi), rtol=1e-15)
    # step just past the root so that the net generalised force is positive
    dt = 1e-12 * max(hi - lo, 1e-6)
    while f(ts) <= 0 and ts < hi:
        ts = min(hi, ts + dt)
        dt *= 4
    return float(ts), best


def simulate(mech: Mechanism, motion: GroundMotion, restitution: float | None = None,
             t_after: float | None = None, record: bool = True, max_impacts: int = 1000,
             rtol: float = RTOL, atol: float = ATOL) -> Response:
    """Response of ``mech`` (at rest at t = 0) to the ground acceleration ``motion``.

    ``restitution``: ``None`` for the momentum balance at each impact, or a user energy
    restitution in [0, 1]; ``t_after`` [s]: simulated time after the input ends (default
    ``50 / omega_0``; survival is usually certified earlier by energy); ``record``: keep the history.
    """
    _check_restitution(restitution)
    if not mech.admissible:
        raise ArchdemInputError(f"{mech.label} is not an admissible mechanism (a hinge would close)")
    trans = _Transitions(restitution)
    partner = trans(mech).after
    rest_set = [mech, partner]
    t_end = float(motion.duration)
    if t_after is None:
        t_after = 50.0 / mech.omega0
    record_dt = 0.02 / mech.omega0  # history sampling [s]
    t_final = t_end + float(t_after)
    bps = sorted({float(b) for b in motion.breakpoints if 0.0 < b < t_end} | {t_end})
    acc = scalar_acceleration(motion)

    ts_hist: list[np.ndarray] = []
    r_hist: list[np.ndarray] = []
    p_hist: list[np.ndarray] = []
    impacts: list[ImpactRecord] = []
    max_ratio = 0.0

    def done(collapsed, rule, t_c=None, residual=0.0, t_start=None):
        collapse_kind = None
        if collapsed:
            collapse_kind = "first-half-cycle" if not impacts else "after-impact"
        t = np.concatenate(ts_hist) if ts_hist else np.zeros(0)
        return Response(collapsed, rule, collapse_kind, t_c, max_ratio, residual, tuple(impacts), t_start,
                        t, np.concatenate(r_hist) if r_hist else np.zeros(0),
                        np.concatenate(p_hist) if p_hist else np.zeros(0))

    start = _next_start(rest_set, motion, 0.0)
    if start is None:
        return done(False, "no-motion")
    t_first = start[0]
    t, cur = start
    y = np.array([0.0, 0.0])
    guard = 0
    while True:
        guard += 1
        if guard > 100 * (max_impacts + 10):
            return done(False, "time-out", residual=y[0] / cur.phi_cr * cur.direction, t_start=t_first)
        M_terms = cur.terms
        dirn = cur.direction

        def rhs(tt, yy, M_terms=M_terms):
            M, dM, dV, S = M_terms(yy[0])
            a = acc(tt) if tt <= t_end else 0.0
            return (yy[1], (-a * S - dV - 0.5 * dM * yy[1] * yy[1]) / M)

        def ev_impact(tt, yy):
            return yy[0]
        ev_impact.terminal = True
        ev_impact.direction = -1

        phi_lim, phi_cr = cur.phi_limit, cur.phi_cr

        def ev_limit(tt, yy):
            return yy[0] - phi_lim
        ev_limit.terminal = True
        ev_limit.direction = 1

        def ev_peak(tt, yy):
            return yy[1]
        ev_peak.terminal = False
        ev_peak.direction = -1

        # next stop: the next breakpoint of the input, or the end of the simulated time
        if t < t_end:
            t_stop = next((b for b in bps if b > t + 1e-15 * max(1.0, t_end)), t_end)
            events = [ev_impact, ev_limit, ev_peak]
        else:
            # after the input: energy certificate, then integrate to phi_cr or the next impact
            if y[0] >= phi_cr and y[1] >= 0:
                # beyond the top of the potential and moving out: gravity drives it on
                return done(True, "phi_cr-after-input", t, residual=y[0] / phi_cr * dirn, t_start=t_first)
            E = cur.energy(y[0], y[1])
            nxt = trans(cur).after
            if y[0] < phi_cr and E < min(cur.barrier, nxt.barrier):
                # inside the barrier with too little energy to cross it, now or after the next impact
                return done(False, "energy", residual=y[0] / phi_cr * dirn, t_start=t_first)
            t_stop = t_final

            def ev_cr(tt, yy):
                return yy[0] - phi_cr
            ev_cr.terminal = True
            ev_cr.direction = 1
            events = [ev_impact, ev_limit, ev_peak, ev_cr]
        if t_stop <= t:
            t_stop = t + 1e-12
        sol = solve_ivp(rhs, (t, t_stop), y, method="DOP853", rtol=rtol, atol=atol, events=events,
                        dense_output=record)
        if sol.status == -1:
            raise RuntimeError(f"integration failed: {sol.message}")
        ratio_seg = sol.y[0] / phi_cr
        if record:
            # the steps of DOP853 are long: sample the dense output for the history
            n_s = max(2, int(math.ceil((sol.t[-1] - sol.t[0]) / record_dt)) + 1)
            tt = np.unique(np.concatenate([np.linspace(sol.t[0], sol.t[-1], n_s), sol.t]))
            ph = sol.sol(tt)[0]
            ts_hist.append(tt)
            r_hist.append(ph / phi_cr * dirn)
            p_hist.append(ph * dirn)
        max_ratio = max(max_ratio, float(np.max(ratio_seg)))
        for te, ye in zip(sol.t_events[2], sol.y_events[2]):
            max_ratio = max(max_ratio, float(ye[0]) / phi_cr)
        t = float(sol.t[-1])
        y = sol.y[:, -1].copy()
        if sol.status == 1:  # a terminal event
            if len(sol.t_events[1]):
                return done(True, "rotation-limit", float(sol.t_events[1][0]), residual=phi_lim / phi_cr * dirn,
                            t_start=t_first)
            if len(events) > 3 and len(sol.t_events[3]):
                return done(True, "phi_cr-after-input", float(sol.t_events[3][0]), residual=dirn, t_start=t_first)
            # impact
            tr = trans(cur)
            vb = float(y[1])
            va = tr.ratio * abs(vb)
            nxt = tr.after
            impacts.append(ImpactRecord(t, vb, va, tr.e, tr.e_applied, cur.label, nxt.label, tr.rule))
            if len(impacts) > max_impacts:
                return done(False, "time-out", residual=0.0, t_start=t_first)
            cur = nxt
            y = np.array([0.0, va])
            if 0.5 * nxt.M0 * va * va < REST_ENERGY * nxt.barrier:
                # at rest: wait for the input to start it again
                st = _next_start(rest_set, motion, t) if t < t_end else None
                if st is None:
                    return done(False, "rest", residual=0.0, t_start=t_first)
                t, cur = st
                y = np.array([0.0, 0.0])
            continue
        # reached t_stop
        if t >= t_final - 1e-12:
            return done(False, "time-out", residual=y[0] / phi_cr * dirn, t_start=t_first)
        if t >= t_end and y[0] <= 0 and abs(y[1]) == 0:
            return done(False, "rest", t_start=t_first)


def linearised_collapse(mech: Mechanism, motion: GroundMotion, n: int = 4001) -> bool:
    """Quick conservative estimate: collapse in the first half-cycle of the linearised equation.

    ``M0 phi'' - |V''(0)| phi = -a_g S(0) - V'(0)`` from rest (closed form by Duhamel's integral,
    trapezoidal quadrature on ``n`` points per input interval); collapse iff at the end of the input
    the linear system's energy drives it past ``phi_cr,lin = V'(0)/|V''(0)|`` (``phi' + p (phi -
    phi_cr,lin) > 0``) without returning to ``phi = 0`` during the input.
    """
    start = _next_start([mech], motion, 0.0)
    if start is None:
        return False
    ts = start[0]
    t_end = float(motion.duration)
    M0, S0, dV0 = mech.M0, mech.terms(0.0)[3], mech.dpotential(0.0)
    p = math.sqrt(abs(mech.d2potential(0.0)) / M0)
    knots = sorted({ts, t_end} | {b for b in motion.breakpoints if ts < b < t_end})
    tt = np.unique(np.concatenate([np.linspace(a, b, n) for a, b in zip(knots[:-1], knots[1:])]))
    # one-sided values inside each interval (the input may jump at the knots)
    c = (-motion.acceleration(tt) * S0 - dV0) / M0
    # w+ = phi' + p phi, w- = phi' - p phi: w+' = p w+ + c, w-' = -p w- + c
    wp = np.exp(p * (tt - ts)) * cumulative_trapezoid(np.exp(-p * (tt - ts)) * c, tt, initial=0.0)
    wm = np.exp(-p * (tt - ts)) * cumulative_trapezoid(np.exp(p * (tt - ts)) * c, tt, initial=0.0)
    phi = (wp - wm) / (2 * p)
    if np.any(phi[1:] < 0):
        return False
    phidot = 0.5 * (wp + wm)
    phi_c = dV0 / abs(mech.d2potential(0.0))
    return bool(phidot[-1] + p * (phi[-1] - phi_c) > 0)


def integrate(mech: Mechanism, y0: tuple[float, float], t_span: tuple[float, float],
              motion: GroundMotion | None = None, rtol: float = RTOL, atol: float = ATOL, **kw):
    """Plain integration of one mechanism's equation of motion (no impact, no collapse rule):
    ``solve_ivp`` result for state ``(phi, phi')`` from ``y0``; ``motion=None`` is no input."""
    def rhs(t, y):
        a = 0.0 if motion is None else float(motion.acceleration(t))
        return (y[1], mech.acceleration(y[0], y[1], a))
    return solve_ivp(rhs, t_span, list(y0), method="DOP853", rtol=rtol, atol=atol, **kw)
