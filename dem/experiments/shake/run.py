"""Virtual shake table: one run of a horizontal ground motion on a rigid-block model.

Load (``ShakeProtocol.load``): ``inertial`` (default), the uniform inertial field of
:class:`dem.core.loads.GroundShake` (fixed base, every body feels ``(-a_g(t), -g, 0)``), exact for a
rigid table and needing no kinematic body (PyBullet has none); or ``driven-base``, plain gravity
and the base moved by the ground displacement (a heavy dynamic base in PyBullet, a slide joint in
MuJoCo; see the engines). Both give the same relative motion; results are in the table frame.

Run: the motion, then a zero tail (``ShakeProtocol.tail`` [s]) so that a rocking arch either
comes back to rest or falls. Poses are recorded every ``ShakeProtocol.record_every`` [s].

**Collapse in a shake** (docs/physics/dem.md#5-collapse-criterion, no per-specimen tuning): some
body point has moved more than ``collapse_fraction x size`` (size = ring thickness of an arch,
height of a single block) while that body still moves faster than ``Settings.collapse_speed``.
The fraction is 1.0 by default, larger than the 0.06 of the tilt test: under a pulse a mechanism
may open well past its static limit during the input and still close again
(docs/physics/dynamics.md#6-time-integration-and-the-collapse-rule: passing ``phi_cr`` while the
input acts is not collapse), whereas a body point displaced by a full ring thickness (a block: by its
height, i.e. rotated ~2 x its slenderness angle) is usually falling. Usually, not always: the
criterion's firing is an **excursion**, and the run goes on. The collapse is **confirmed** once a
point has moved ``confirm_fraction x size`` (2 ring thicknesses), or when the run ends — at rest or
at its duration — still past the criterion; an arch that comes back below it has survived, its
peak and residual displacements and the firing (``t_exceed``) reported
(docs/decisions/012-collapse-confirmed.md).

**First impact / rebound**: from the horizontal displacement ``u(t)`` of the crown body's
centroid (the block's centroid for a single block). The motion starts when ``|u|`` first
exceeds ``onset_mm`` (default 0.1 mm, above the at-rest drift, docs/validation.md#2-at-rest); the first rebound is
the first later instant where the crown velocity ``du/dt`` changes sign (the first extremum of
``u``): the opening mechanism stops and closes back, which is where the analytic model's first
impact follows. ``collapse_phase`` is ``"before-first-rebound"`` (the analytic
``first-half-cycle`` mode) if collapse is detected before that instant (or no reversal
happened), else ``"after-first-rebound"`` (the analytic ``after-impact`` mode).

Crown displacement: ``peak_crown_mm`` = max ``|u|`` [mm] over the record; ``residual_crown_mm``
= ``u`` at the end of the record (for a collapsed run: at the confirmation, since the run stops
there by default). ``collapse_phase`` compares the rebound with ``t_collapse``, the instant the
excursion that did not come back passed the criterion.

A run is :func:`run` of a :class:`ShakeSpec` (what is shaken, by what motion, with which settings and
protocol); its :class:`ShakeResult` declares its summary's columns once (:class:`dem.experiments.contract.Result`):
the JSON of ``archdem shake`` and the summary in the result file are its row. :func:`shake` is the same
call with the spec's fields as arguments.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from analytic.motions.inputs import GroundMotion
from dem.core import detect
from dem.core.loads import GroundShake
from dem.core.engines import get_engine
from dem.core.model import Model, as_model
from dem.core.progress import Progress, TimedEngine
from dem.core.settings import Settings, dynamics_settings
from dem.core.simulate import SimResult, simulate
from dem.experiments.contract import Column, Result, Schema
from specimens.constants import G
from foundation.errors import ArchdemInputError

FORMAT = "archdem-shake-1"
LOADS = ("inertial", "driven-base")  # how the ground motion is applied (module docstring)


#: Longest tail or run a protocol accepts [s]: 600 simulated seconds are hours of wall time.
MAX_SIMULATED_S = 600.0
#: Longest simulated time of one run [s]: the longest record a reader takes (MAX_RECORD_S, 1200 s) plus the
#: longest tail; a motion built by hand (a SampledMotion of 10 million samples) is refused before the run.
MAX_RUN_S = 1800.0
#: A run that may simulate longer than this [s] says so before it starts (it can take minutes).
ANNOUNCE_SIMULATED_S = 10.0


@dataclass(frozen=True)
class ShakeProtocol:
    """Parameters of a shake run (stored with each result)."""

    tail: float = 1.0  # zero acceleration after the motion [s]; a 5 s tail changed no threshold
    #   (docs/decisions/005-shake-end-at-rest.md)
    duration: float | None = None  # total simulated time [s]; default motion duration + tail
    collapse_fraction: float = 1.0  # collapse: a point moved > this x size while moving ...
    # ... confirmed at this x size or by ending past it: arches came back from 1.13 x (decision 012); None: at once
    confirm_fraction: float | None = 2.0
    record_every: float = 0.005  # [s] history sampling (and collapse check)
    onset_mm: float = 0.1  # crown displacement at which the motion is said to start [mm]
    stop_on_collapse: bool = True
    load: str = "inertial"  # inertial (uniform inertial field, fixed base) | driven-base
    rest_after: float | None = 0.1  # [s] after the motion: from then on a run at rest (displacement varying
    #   by less than rest_span x size over rest_window) ends as survived; None: the whole duration (decision 005)
    rest_window: float = 0.1  # [s]
    rest_span: float = 3e-4  # largest minus smallest displacement over rest_window / size

    def __post_init__(self) -> None:
        if not (math.isfinite(self.tail) and 0 <= self.tail <= MAX_SIMULATED_S):
            raise ArchdemInputError(f"zero tail must be between 0 and {MAX_SIMULATED_S:g} s, got {self.tail!r}")
        if self.rest_after is not None and not (math.isfinite(self.rest_after) and self.rest_after >= 0):
            raise ArchdemInputError(f"shake protocol rest_after must be >= 0 s or None, got {self.rest_after!r}")
        if self.duration is not None and not (math.isfinite(self.duration) and 0 < self.duration <= MAX_SIMULATED_S):
            raise ArchdemInputError(f"--duration must be between 0 and {MAX_SIMULATED_S:g} s, got {self.duration!r}")
        for k in ("collapse_fraction", "record_every", "onset_mm", "rest_window", "rest_span"):
            v = getattr(self, k)
            if not (math.isfinite(v) and v > 0):
                raise ArchdemInputError(f"shake protocol {k} must be > 0, got {v!r}")
        if self.load not in LOADS:
            raise ArchdemInputError(f"shake load must be one of {', '.join(LOADS)}, got {self.load!r}")
        c = self.confirm_fraction
        if c is not None and not (math.isfinite(c) and c > self.collapse_fraction):
            raise ArchdemInputError(f"shake protocol confirm_fraction must be None or > collapse_fraction "
                                    f"{self.collapse_fraction:g}, got {c!r}")

    def total_duration(self, motion: GroundMotion) -> float:
        """Simulated time of a run [s]; more than :data:`MAX_RUN_S` is refused."""
        if self.duration is not None:
            return float(self.duration)
        total = float(motion.duration) + self.tail
        if not total <= MAX_RUN_S:
            raise ArchdemInputError(f"the run would simulate {total:g} s (motion and tail), more than {MAX_RUN_S:g} s; "
                                    "cut the record or give --duration")
        return total


@dataclass(frozen=True)
class ShakeSpec:
    """One shake run: ``target`` (a specimen id, Specimen, PointedArch, Assembly or Model, see
    :func:`dem.core.model.as_model`, an arch cut in ``config``) under ``motion`` (ground acceleration
    [m/s^2], +x), with ``settings`` (the shakes' engine by default) and ``protocol``; ``label`` names it
    (default the model's name); ``friction_work`` False skips the contact-force readout behind the friction
    work (NaN then)."""

    target: Any
    motion: GroundMotion
    settings: Settings = field(default_factory=dynamics_settings)
    protocol: ShakeProtocol = field(default_factory=ShakeProtocol)
    label: str | None = None
    config: str = "glued"
    friction_work: bool = True


@dataclass
class ShakeResult(Result):
    """Outcome of one shake run (SI inside; the summary reports mm and g): its summary row declared once."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("id", "str"), Column("collapsed", "bool"), Column("t_collapse", "float", "s"), Column("mode", "str"),
        Column("collapse_phase", "str"), Column("t_motion_start", "float", "s"), Column("t_first_rebound", "float", "s"),
        Column("peak_crown_mm", "float", "mm"), Column("residual_crown_mm", "float", "mm"),
        Column("max_displacement_mm", "float", "mm"), Column("residual_displacement_mm", "float", "mm"),
        Column("t_exceed", "float", "s"), Column("recovered", "bool"), Column("t_collapse_confirmed", "float", "s"),
        Column("joints", "json"), Column("input", "json"), Column("pga_g", "float", "g"), Column("duration", "float", "s"),
        Column("config", "str"), Column("contact", "float"), Column("mu_joint", "float"), Column("mu_base", "float"),
        Column("load", "str"), Column("friction_work_J", "float", "J"), Column("out_of_plane", "json"),
        Column("t_end_at_rest", "float", "s"), Column("wall_s", "float", "s"), Column("steps", "int"),
        Column("result_file", "str"),
    ))

    label: str
    model: Model
    settings: Settings
    protocol: ShakeProtocol
    motion: GroundMotion
    sim: SimResult
    crown_u: np.ndarray  # (nt,) horizontal crown displacement [m] at sim.history.t
    t_start: float | None  # motion onset [s] (|u| > onset_mm)
    t_rebound: float | None  # first reversal of the crown velocity after the onset [s]
    collapse_phase: str | None  # before-first-rebound | after-first-rebound | None (no collapse)
    criterion: dict
    versions: dict = field(default_factory=dict)
    result_file: str = ""

    @property
    def collapsed(self) -> bool:
        return bool(self.sim.collapsed)

    @property
    def t_collapse(self) -> float | None:
        return float(self.sim.t_collapse) if self.sim.collapsed else None

    @property
    def t_exceed(self) -> float | None:
        """When the criterion first fired [s] (the old rule's collapse time), None if it never did."""
        return None if math.isnan(self.sim.t_exceed) else float(self.sim.t_exceed)

    @property
    def recovered(self) -> bool:
        """The criterion fired but the arch came back: survived after an excursion."""
        return self.t_exceed is not None and not self.collapsed

    @property
    def mode(self) -> str:
        return self.sim.mode

    @property
    def peak_crown_mm(self) -> float:
        return float(np.max(np.abs(self.crown_u)) * 1e3) if len(self.crown_u) else 0.0

    @property
    def residual_crown_mm(self) -> float:
        return float(self.crown_u[-1] * 1e3) if len(self.crown_u) else 0.0

    def rows(self) -> list[dict]:
        return [{
            "id": self.label, "collapsed": self.collapsed, "t_collapse": self.t_collapse, "mode": self.mode,
            "collapse_phase": self.collapse_phase, "t_motion_start": self.t_start, "t_first_rebound": self.t_rebound,
            "peak_crown_mm": self.peak_crown_mm, "residual_crown_mm": self.residual_crown_mm,
            "max_displacement_mm": float(np.max(self.sim.history.dmax) * 1e3),
            "residual_displacement_mm": float(self.sim.history.dmax[-1] * 1e3),
            "t_exceed": self.t_exceed, "recovered": self.recovered,
            "t_collapse_confirmed": float(self.sim.t_confirm) if self.collapsed else None,
            "joints": [j.to_dict() for j in self.sim.joints],
            "input": self.motion.describe(), "pga_g": float(self.motion.pga / G), "duration": self.sim.duration,
            "config": self.model.source.get("config", ""), "contact": self.model.source.get("contact", 1.0),
            "mu_joint": self.settings.mu_joint,
            "mu_base": self.settings.mu_base, "load": self.protocol.load,
            "friction_work_J": self.sim.history.friction_work, "out_of_plane": self.sim.out_of_plane,
            "t_end_at_rest": None if math.isnan(self.sim.t_rest) else float(self.sim.t_rest),
            "wall_s": self.sim.wall_s, "steps": self.sim.steps, "result_file": self.result_file,
        }]

    def summary(self) -> dict:
        """The JSON answer of ``archdem shake`` (its row)."""
        return self.to_json()[0]

    def text(self) -> str:
        """The line ``archdem shake`` prints: the outcome, the crown's peak and residual, the file."""
        s = self.summary()
        act = ", ".join(f"{j['joint']}:{j['state']}" for j in s["joints"] if j["state"] != "closed")
        if self.collapsed:
            what = (f"COLLAPSE at t = {self.t_collapse:.3f} s ({self.collapse_phase}; confirmed at "
                    f"{s['t_collapse_confirmed']:.3f} s), {self.mode} [{act}]")
        elif self.recovered:
            what = (f"survival after an excursion to {s['max_displacement_mm']:.1f} mm (criterion at t = "
                    f"{self.t_exceed:.3f} s, {s['residual_displacement_mm']:.1f} mm at the end), {self.mode}")
        else:
            what = f"survival, {self.mode}"
        return (f"{self.label} ({s['config']}, mu {self.settings.mu_joint:g}/{self.settings.mu_base:g}), PGA "
                f"{s['pga_g']:.3f} g: {what}; crown peak {self.peak_crown_mm:.2f} mm, residual "
                f"{self.residual_crown_mm:.2f} mm; {self.sim.wall_s:.1f} s -> {self.result_file}")


def shake_settings(settings: Settings, protocol: ShakeProtocol) -> Settings:
    """``settings`` with the shake collapse fraction, its confirmation and record interval of ``protocol``."""
    lo, hi = settings.mode_window
    return settings.with_(collapse_fraction=protocol.collapse_fraction, collapse_confirm=protocol.confirm_fraction,
                          record_every=max(protocol.record_every, settings.dt),
                          mode_window=(lo, min(hi, protocol.collapse_fraction)))


def crown_displacement(model: Model, sim: SimResult) -> np.ndarray:
    """Horizontal displacement [m] of the crown body's centroid at every record."""
    c0 = float(model.bodies[model.crown].centroid[0])
    return sim.history.pos[:, model.crown, 0] - c0


def first_rebound(t: np.ndarray, u: np.ndarray, onset: float) -> tuple[float | None, float | None]:
    """``(t_start, t_rebound)`` [s]: first time ``|u| > onset`` [m], then the first sign change of
    ``du/dt`` after it (linear interpolation of the velocity zero between records); None if absent."""
    t = np.asarray(t, float)
    u = np.asarray(u, float)
    idx = np.nonzero(np.abs(u) > onset)[0]
    if len(idx) == 0 or len(t) < 3:
        return None, None
    k0 = int(idx[0])
    t_start = float(t[k0])
    v = np.gradient(u, t)
    s0 = np.sign(u[k0])  # the direction of the first excursion
    # after the onset the crown moves along s0; the rebound is the first record where it moves back
    for k in range(max(k0, 1), len(t)):
        if v[k] * s0 < 0 and v[k - 1] * s0 >= 0:
            v0, v1 = v[k - 1], v[k]
            frac = v0 / (v0 - v1) if v0 != v1 else 0.0
            return t_start, float(t[k - 1] + frac * (t[k] - t[k - 1]))
    return t_start, None


def shake(target, motion: GroundMotion, settings: Settings | None = None, protocol: ShakeProtocol | None = None,
          label: str | None = None, friction_work: bool = True, config: str = "glued",
          progress: Progress | None = None) -> ShakeResult:
    """Run ``motion`` (ground acceleration [m/s^2], +x; :func:`analytic.motions.records.ground_motion` builds
    one in g) on ``target``: :func:`run` of the :class:`ShakeSpec` of these arguments."""
    return run(ShakeSpec(target, motion, settings or dynamics_settings(), protocol or ShakeProtocol(), label, config,
                         friction_work), progress)


def run(spec: ShakeSpec, progress: Progress | None = None) -> ShakeResult:
    """Run ``spec``; see the module docstring. ``progress(done, total, note)``: called as the run advances
    (:mod:`dem.core.progress`; ``done`` and ``total`` simulated seconds, rounded to 0.01 s)."""
    model = as_model(spec.target, config=spec.config)
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.core.provenance import run_provenance

    motion, proto, friction_work = spec.motion, spec.protocol, spec.friction_work
    st = shake_settings(spec.settings, proto)
    duration = proto.total_duration(motion)
    load = GroundShake(motion, g=st.g, driven_base=proto.load == "driven-base")
    rest = None
    if proto.rest_after is not None:
        rest = (float(motion.duration) + proto.rest_after, proto.rest_window, proto.rest_span * model.size)
    engine = None
    if progress is not None:
        total = round(duration, 2)
        progress(0.0, total, "input")
        engine = TimedEngine(get_engine(st.engine, st.engine_options), st.dt,
                             lambda t: progress(round(t, 2), total, "input" if t < motion.duration else "tail"))
    sim = simulate(model, st, load, duration, record_every=st.record_every, stop_on_collapse=proto.stop_on_collapse,
                   friction_work=friction_work, rest=rest, rest_span=True, engine=engine)
    if progress is not None:
        progress(round(sim.steps * st.dt, 2), round(sim.steps * st.dt, 2),
                 "collapsed" if sim.collapsed else ("at rest" if not math.isnan(sim.t_rest) else "end"))
    u = crown_displacement(model, sim)
    t_start, t_reb = first_rebound(sim.history.t, u, proto.onset_mm * 1e-3)
    phase = None
    if sim.collapsed:
        phase = "before-first-rebound" if (t_reb is None or sim.t_collapse <= t_reb) else "after-first-rebound"
    crit = detect.criterion(st, model)
    crit.update({"first_rebound": "first sign change of the crown horizontal velocity after |u| > onset_mm",
                 "onset_mm": proto.onset_mm})
    return ShakeResult(spec.label or model.name, model, st, proto, motion, sim, u, t_start, t_reb, phase, crit,
                       run_provenance(st.engine, st.engine_options))


def collapses(model: Model, motion: GroundMotion, settings: Settings, protocol: ShakeProtocol) -> tuple[bool, str, str | None]:
    """``(collapsed, mode, collapse_phase)`` of one run (for amplitude scans). The friction work
    is not read: nothing keeps it, and its contact readout is about 7 % of a run's wall time."""
    r = shake(model, motion, settings, protocol, friction_work=False)
    return r.collapsed, r.mode, r.collapse_phase


# ------------------------------------------------------------------------------------ I/O
def motion_trace(motion: GroundMotion, duration: float, dt: float) -> tuple[np.ndarray, np.ndarray]:
    n = int(math.floor(duration / dt + 1e-9)) + 1
    t = dt * np.arange(n)
    return t, np.asarray(motion.acceleration(t), float)


__all__ = ["FORMAT", "ShakeProtocol", "ShakeSpec", "ShakeResult", "run", "shake", "collapses", "crown_displacement", "first_rebound",
           "shake_settings"]
