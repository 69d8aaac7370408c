"""``simulate``: any load on a model, recorded, with the collapse criterion and the failure mode.

``simulate(model, settings, load, duration)`` is the one entry point of every virtual experiment:
it builds an engine, applies ``load.gravity(t)`` (or drives the base) before every step, records
poses every ``settings.record_every`` and applies the collapse criterion of :mod:`dem.core.detect`
(docs/physics/dem.md), confirmed as ``settings.collapse_confirm`` says (#5-collapse-criterion).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

import numpy as np

from dem.core import detect
from dem.core.engines import get_engine
from dem.core.engines.inputs import accel
from dem.core.loads import Load
from dem.core.model import Model
from dem.core.settings import Settings
from foundation.errors import ArchdemInputError


@dataclass
class History:
    """Time history sampled every ``record_every``: t (nt,), pos (nt, n, 3), quat (nt, n, 4)
    (x, y, z, w, relative to the initial orientation), gravity (nt, 3), dmax (nt,) largest point
    displacement [m], ke (nt,) kinetic energy [J], fpower (nt,) friction dissipation rate [W]
    (NaN if the engine gives no contact forces)."""

    t: np.ndarray
    pos: np.ndarray
    quat: np.ndarray
    gravity: np.ndarray
    dmax: np.ndarray
    ke: np.ndarray
    fpower: np.ndarray

    def rotations(self) -> np.ndarray:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from scipy.spatial.transform import Rotation

        nt, n = self.quat.shape[:2]
        return Rotation.from_quat(self.quat.reshape(-1, 4)).as_matrix().reshape(nt, n, 3, 3)

    @property
    def friction_work(self) -> float:
        """Friction work [J] (rectangle rule over the samples)."""
        if len(self.t) < 2 or not np.all(np.isfinite(self.fpower)):
            return float("nan")
        return float(np.sum(self.fpower[1:] * np.diff(self.t)))


@dataclass
class SimResult:
    """One simulation: load description, history, collapse and mode read from the history."""

    load: dict
    duration: float
    history: History
    collapsed: bool
    t_collapse: float
    joints: list
    mode: str
    out_of_plane: dict
    wall_s: float
    steps: int
    t_rest: float = float("nan")  # time [s] at which the run was ended at rest (``rest``), NaN if it was not
    # the criterion's first firing [s] (NaN if never), kept when the excursion was recovered from (no collapse)
    t_exceed: float = float("nan")
    t_confirm: float = float("nan")  # when the collapse was confirmed [s] (= t_collapse without confirmation)


def _kinetic_energy(mass: np.ndarray, inertia: np.ndarray, v: np.ndarray, w: np.ndarray, R: np.ndarray) -> float:
    """Kinetic energy [J] of bodies of ``mass`` (n,) and body-frame ``inertia`` (n, 3, 3) moving at
    ``v``, ``w`` (n, 3) with orientations ``R`` (n, 3, 3): w . (R I R^T w) = (R^T w) . I (R^T w)."""
    wb = np.einsum("kji,kj->ki", R, w)
    return float(0.5 * np.sum(mass * np.einsum("ki,ki->k", v, v)) + 0.5 * np.einsum("ki,kij,kj->", wb, inertia, wb))


def _friction_power(engine, v: np.ndarray, w: np.ndarray, pos: np.ndarray, base_x: float = 0.0) -> float:
    """Friction dissipation rate [W]; ``v``, ``pos`` in the table frame, which the engine's
    contact points are moved into by the base displacement ``base_x`` [m]."""
    c = engine.contacts()
    if c is None:
        return float("nan")
    if len(c.fn) == 0:
        return 0.0
    if base_x:
        c = replace(c, point=c.point - np.array([base_x, 0.0, 0.0]))

    def vel(idx, p):
        out = np.zeros_like(p)
        m = idx >= 0
        out[m] = v[idx[m]] + np.cross(w[idx[m]], p[m] - pos[idx[m]])
        return out

    vrel = vel(c.a, c.point) - vel(c.b, c.point)
    vt = vrel - (vrel * c.normal).sum(1, keepdims=True) * c.normal
    return float(np.sum(np.linalg.norm(c.ft, axis=1) * np.linalg.norm(vt, axis=1)))


def simulate(model: Model, settings: Settings, load: Load, duration: float, record_every: float | None = None,
             stop_on_collapse: bool = True, friction_work: bool = True, engine=None,
             rest: tuple[float, float, float] | None = None, rest_span: bool = False) -> SimResult:
    """Run ``load`` on ``model`` for ``duration`` [s]; stop at collapse if ``stop_on_collapse``.

    ``record_every`` [s] defaults to ``settings.record_every``; the collapse criterion is
    checked at each record (``t_exceed``: its first firing). With ``settings.collapse_confirm`` None
    a firing is the collapse; otherwise the run goes on and the collapse is confirmed once a point
    moved more than ``collapse_confirm x size``, or when the run ends (at rest or at ``duration``)
    still in an excursion past the criterion; ``t_collapse`` is then where that excursion passed
    it, ``t_confirm`` where it was confirmed. ``engine``: an unbuilt backend (default: ``settings.engine``
    with ``settings.engine_options``; one with other options is refused).
    ``rest = (t_from, window, growth)`` [s, s, m]: from ``t_from`` on, end the run (not collapsed,
    ``t_rest`` set) at the first record at which the largest displacement grew by less than
    ``growth`` over the last ``window`` (``rest_span``: varied by less than ``growth``, i.e. its
    largest minus its smallest value over the window, which a swing back also fails).
    A load with ``driven_base`` (a ground motion) moves the base by the ground displacement
    (velocity and displacement integrated with the engine's own symplectic Euler, so that the
    relative motion matches the inertial field step for step) under plain gravity; poses and
    velocities are then recorded in the table frame, as with the inertial field.
    """
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from scipy.spatial.transform import Rotation

    if not (duration > 0 and math.isfinite(duration)):
        raise ArchdemInputError(f"simulation duration must be > 0 s, got {duration!r}")
    wall0 = time.perf_counter()
    eng = engine if engine is not None else get_engine(settings.engine, settings.engine_options)
    if getattr(eng, "options", settings.engine_options) != settings.engine_options:
        raise ArchdemInputError(f"the {settings.engine} engine given runs other options than settings.engine_options: "
                                "make it with get_engine(settings.engine, settings.engine_options)")
    rec = max(1, int(round((record_every or settings.record_every) / settings.dt)))
    n_steps = int(round(duration / settings.dt))
    tracker = detect.PointTracker(model)
    d_c = settings.collapse_fraction * model.size
    d_ok = None if settings.collapse_confirm is None else settings.collapse_confirm * model.size
    T, P, RM, Gv, D, KE, FP = [], [], [], [], [], [], []
    mass = np.array([b.mass for b in model.bodies])
    inertia = np.array([b.inertia for b in model.bodies])
    collapsed, t_col, t_rest = False, float("nan"), float("nan")
    # t_above: when the current excursion past d_c met the criterion (NaN below d_c or before it did)
    t_exc = t_above = t_conf = float("nan")
    if rest is not None:
        rest_from, rest_k, rest_growth = rest[0], max(1, int(round(rest[1] / (rec * settings.dt)))), rest[2]
    driven = bool(getattr(load, "driven_base", False))
    xb = vb = 0.0  # prescribed base displacement [m] and velocity [m/s] (driven base)
    try:
        eng.build(model, settings, driven_base=driven)
        step = 0
        if driven:
            eng.set_gravity(np.array([0.0, -load.g, 0.0]))

        def record() -> tuple[float, int]:
            pos, R = eng.poses()
            v, w = eng.velocities()
            bx, bv = eng.base_motion()
            if driven:  # into the table frame (the actual base motion, not the prescribed one)
                pos = pos - np.array([bx, 0.0, 0.0])
                v = v - np.array([bv, 0.0, 0.0])
            d, i = tracker.max_displacement(pos, R)
            T.append(step * settings.dt)
            P.append(pos)
            RM.append(R)  # turned into quaternions once, at the end
            Gv.append(load.gravity(step * settings.dt))
            D.append(d)
            KE.append(_kinetic_energy(mass, inertia, v, w, R))
            FP.append(_friction_power(eng, v, w, pos, bx) if friction_work else float("nan"))
            return d, tracker.body_speed(v, w, i)

        record()
        g_set = None  # the gravity last given to the engine (on the engine's input grid)
        while step < n_steps:
            n = min(rec, n_steps - step)
            if driven:
                for _ in range(n):
                    vb += float(accel(load.ground_acceleration(step * settings.dt))) * settings.dt
                    xb += vb * settings.dt
                    eng.drive_base(xb, vb)
                    eng.step(1)
                    step += 1
            else:
                # the field of each step (as the engine takes it); a constant stretch (a held tilt
                # level, rest) is set once and stepped in one call: the same commands in effect
                gs = [accel(load.gravity((step + j) * settings.dt)) for j in range(n)]
                j = 0
                while j < n:
                    m = 1
                    while j + m < n and np.array_equal(gs[j + m], gs[j]):
                        m += 1
                    if g_set is None or not np.array_equal(gs[j], g_set):
                        eng.set_gravity(gs[j])
                        g_set = gs[j]
                    eng.step(m)
                    j += m
                    step += m
            d, speed = record()
            t_now = step * settings.dt
            if d <= d_c:
                t_above = float("nan")
            elif math.isnan(t_above) and speed > settings.collapse_speed:
                t_above = t_now
                t_exc = t_now if math.isnan(t_exc) else t_exc
            if not collapsed and not math.isnan(t_above) and (d_ok is None or d > d_ok):
                collapsed, t_col, t_conf = True, t_above, t_now
                if stop_on_collapse:
                    break
            if (rest is not None and not collapsed and step * settings.dt >= rest_from - 1e-9 and len(D) > rest_k
                    and (np.ptp(D[-1 - rest_k:]) if rest_span else D[-1] - D[-1 - rest_k]) < rest_growth):
                t_rest = step * settings.dt
                break
    finally:
        eng.close()
    if d_ok is not None and not collapsed and not math.isnan(t_above):
        # the run ended (at rest or at its duration) still past the criterion: it did not come back
        collapsed, t_col, t_conf = True, t_above, step * settings.dt
    nt, nb = len(T), model.n_bodies
    Q = Rotation.from_matrix(np.array(RM).reshape(-1, 3, 3)).as_quat().reshape(nt, nb, 4)
    hist = History(np.array(T), np.array(P), Q, np.array(Gv), np.array(D), np.array(KE), np.array(FP))
    Rs = hist.rotations()
    joints, mode = read_mode(model, settings, hist, Rs)
    oop = detect.out_of_plane(model, hist.pos[-1], Rs[-1])
    oop["max_dz_history_m"] = float(np.abs(tracker.all_displacements(hist.pos, Rs)[..., 2]).max())
    return SimResult(load.describe(), duration, hist, collapsed, t_col, joints, mode, oop,
                     time.perf_counter() - wall0, step, t_rest, t_exc, t_conf)


def read_mode(model: Model, settings: Settings, hist: History,
              Rs: np.ndarray | None = None) -> tuple[list[detect.JointState], str]:
    """Joint states and mode over the mode window of ``hist`` (or over the whole history when
    the largest displacement never reached the window: then the states describe creep).
    ``Rs``: ``hist.rotations()`` if already computed."""
    lo, hi = (f * model.size for f in settings.mode_window)
    Rs = hist.rotations() if Rs is None else Rs
    i0 = int(np.argmax(hist.dmax >= lo)) if np.any(hist.dmax >= lo) else 0
    i1 = int(np.argmax(hist.dmax >= hi)) if np.any(hist.dmax >= hi) else len(hist.t) - 1
    if i1 <= i0:
        i0, i1 = 0, len(hist.t) - 1
    states, mode = detect.classify(model, settings, hist.pos[i0], Rs[i0], hist.pos[i1], Rs[i1],
                                   float(hist.dmax[i1] - hist.dmax[i0]))
    if not np.any(hist.dmax >= lo):
        mode = "none"
    return states, mode


# ------------------------------------------------------------------------------------- tilt
def onset_time(model: Model, settings: Settings, sim: SimResult) -> float:
    """Time [s] at which the motion that ended in the collapse of ``sim`` started: the first
    record of the last excursion of the largest displacement above ``mode_window[0] x size``
    (the lower end of the mode window, above pre-collapse creep; docs/physics/dem.md#8-tilt-test-staircase-and-ramp)."""
    below = np.flatnonzero(sim.history.dmax < settings.mode_window[0] * model.size)
    k = min(int(below[-1]) + 1, len(sim.history.t) - 1) if len(below) else 0
    return float(sim.history.t[k])
