"""Virtual experiments: ``simulate`` (any load) and the tilt test (hold-and-bisect, staircase, ramp).

``simulate(model, settings, load, duration)`` is the one entry point: it builds an engine,
applies ``load.gravity(t)`` before every step, records poses every ``settings.record_every``
and applies the collapse criterion of :mod:`dem.core.detect`. A shake-table test is ``simulate``
with a :class:`dem.core.loads.GroundShake` load.

Tilt protocols (lambda = tan theta; gravity rotated at constant magnitude, horizontal part +x):

* ``hold`` (default): a level lambda is reached by a smooth ramp (``ramp_time``, 0.5 s) and held
  ``hold_time`` (1 s; a level at rest 0.5 s into the hold ends there, ``rest_after``); the
  threshold is bracketed around a first estimate (``guess`` if given;
  with ``start="lp"``, the default when the blocks are known, the static LP of the same blocks,
  :func:`lp_guess`; otherwise a fast continuous ramp) and bisected until the bracket is narrower
  than ``tol`` relative; an end of the first bracket is simulated only if the bisection ends on
  it (``probe_ends``), so both ends of the final bracket were simulated. The answer is the upper
  end of the bracket (first collapsing level); non-monotonic outcomes near the threshold
  (docs/validation.md#7-non-monotonic-outcomes-near-the-threshold) make thresholds reproducible
  to about +-1 %.
* ``staircase``: one simulation, lambda raised by ``step`` and held ``stair_hold`` each time;
  the answer is the step during which the collapsing motion started (:func:`onset_time`).
* ``ramp``: one simulation at a constant rate; lambda read at the onset of the collapsing
  motion (:func:`onset_time`), which lags the threshold by a rate-dependent amount.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace
from typing import Any, Callable, ClassVar

from analytic.search import search
from dem.core import detect
from dem.core.loads import TiltHold, TiltRamp, TiltStairs
from dem.core.engines import get_engine
from dem.core.model import Model, as_model
from dem.core.progress import Progress, TimedEngine
from dem.core.settings import Settings
from dem.core.simulate import SimResult, onset_time, simulate
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.tilt.check import LpCheck, lp_check, prevents_sliding
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch

# First bracket of the hold protocol, relative to its first estimate: the widest that reaches the
# 0.5 % tolerance in 3 bisections (docs/decisions/002-guess-bracket.md)
GUESS_BRACKET = (0.972, 1.01)
GUESS_STEPS = (1.05, 0.95)  # an end of the first bracket that turns out wrong moves out by these factors
# an end of the first bracket is simulated only if the bisection ends on it: 3 simulations per test
# instead of 5, the same answers (docs/decisions/003-probe-ends.md)
PROBE_ENDS = "last"
RC_REF = 0.200  # m, Rc of every catalogue specimen: the scale at which the protocol defaults hold
# m, the largest length scale of the catalogue (Sh1's Rp), which its drawings carry: a drawing's counterpart of RC_REF
LENGTH_REF = 0.400


def time_scale_of(target, time_scale: float | str = "auto") -> float:
    """Time scale of the tilt protocol (and of the friction map's time step): for ``"auto"``,
    ``max(1, sqrt(L / L_ref))`` with the arch's Rc against :data:`RC_REF` (a
    :class:`~specimens.geometry.PointedArch` or blocks cut from one) or the blocks' length scale against
    :data:`LENGTH_REF` (a drawing, a rocking frame); 1 for a model without blocks; else the number
    given. Similar arches then run the same dimensionless test (docs/physics/dem.md#75-arches-larger-than-the-catalogue)."""
    if time_scale != "auto":
        s = float(time_scale)
        if not (math.isfinite(s) and s > 0):
            raise ArchdemInputError(f"time scale must be 'auto' or a positive number, got {time_scale!r}")
        return s
    if isinstance(target, Model):
        target = target.assembly
    if target is None:
        return 1.0
    arch = target if isinstance(target, PointedArch) else getattr(target, "arch", None)
    if arch is not None:
        return max(1.0, math.sqrt(arch.Rc / RC_REF))
    length = getattr(target, "length_scale", None)  # a drawing's, a rocking frame's
    return 1.0 if length is None else max(1.0, math.sqrt(float(length) / LENGTH_REF))


@dataclass(frozen=True)
class TiltProtocol:
    """Tilt-test protocol parameters (stored with each result)."""

    kind: str = "hold"  # hold | staircase | ramp

    # hold: each level ramped, held, ended early once at rest (docs/decisions/001-hold-time-and-rest-rule.md)
    ramp_time: float = 0.5  # smooth ramp to each level [s]; faster ramps lost hinge layouts (decision 007)
    hold_time: float = 1.0  # longest time held at a level [s]: a block sliding near mu needs it
    rest_after: float | None = 0.5  # from this time into the hold [s] a level at rest ends as stable; None: never
    rest_window: float = 0.1  # window of the rest rule [s]
    rest_growth: float = 3e-4  # rest rule: displacement growth over rest_window / size

    # hold: the search (docs/physics/dem.md#7-tilt-test-hold-and-bisect)
    tol: float = 0.005  # relative bracket width at which bisection stops
    guess_bracket: tuple[float, float] = GUESS_BRACKET  # first bracket [x guess]
    probe_ends: str = PROBE_ENDS  # "last": an end simulated only if the bisection ends on it; "first": both first
    scan_rate: float = 0.25  # rate of the first-estimate ramp [1/s]
    max_sims: int = 30

    step: float = 0.01  # staircase: lambda increment
    stair_hold: float = 0.5  # staircase: hold per step [s]
    rate: float = 0.02  # ramp: d lambda / dt [1/s]
    lam_max: float = 3.0  # give up above this lambda

    guess: float | None = None  # hold: first estimate of lambda; None: found as ``start`` says
    start: str = "auto"  # hold: "scan" (a ramp at scan_rate), "lp" (lp_guess), "auto" (lp when the blocks are known)
    # the durations above are the catalogue's; a larger arch runs them (and records) x its time_scale_of
    # (None: found from the arch by tilt(); a number: already applied)
    time_scale: float | None = None

    def __post_init__(self) -> None:
        if self.kind not in ("hold", "staircase", "ramp"):
            raise ArchdemInputError(f"tilt protocol must be hold, staircase or ramp, got {self.kind!r}")
        for k in ("ramp_time", "hold_time", "tol", "scan_rate", "step", "stair_hold", "rate", "lam_max",
                  "rest_window", "rest_growth") + (("rest_after",) if self.rest_after is not None else ()):
            v = getattr(self, k)
            if not (math.isfinite(v) and v > 0):
                raise ArchdemInputError(f"tilt protocol {k} must be > 0, got {v!r}")
        # a number or None (a non-number, e.g. the former "lp" sentinel of stored map cases, is an input error)
        if self.guess is not None and not (isinstance(self.guess, (int, float)) and not isinstance(self.guess, bool)
                                           and math.isfinite(self.guess) and 0 < self.guess < self.lam_max):
            raise ArchdemInputError(f"tilt protocol guess must be in (0, lam_max), got {self.guess!r}")
        if self.start not in ("auto", "scan", "lp"):
            raise ArchdemInputError(f"tilt protocol start must be auto, scan or lp, got {self.start!r}")
        if self.time_scale is not None and not (isinstance(self.time_scale, (int, float)) and math.isfinite(self.time_scale)
                                                and self.time_scale > 0):
            raise ArchdemInputError(f"tilt protocol time_scale must be a positive number or None, got {self.time_scale!r}")
        if self.probe_ends not in ("first", "last"):
            raise ArchdemInputError(f"tilt protocol probe_ends must be first or last, got {self.probe_ends!r}")
        try:  # a list read back from JSON becomes the tuple
            lo, hi = (float(x) for x in self.guess_bracket)
        except (TypeError, ValueError):
            raise ArchdemInputError(f"tilt protocol guess_bracket must be two numbers, got {self.guess_bracket!r}") from None
        if not (0 < lo < hi and math.isfinite(hi)):
            raise ArchdemInputError(f"tilt protocol guess_bracket must satisfy 0 < low < high, got {self.guess_bracket!r}")
        object.__setattr__(self, "guess_bracket", (lo, hi))

    def slowed(self, factor: float) -> "TiltProtocol":
        """The same protocol run ``factor`` times slower: every duration (ramp, hold, staircase
        step, and the rest rule's start and window) x factor, every rate / factor."""
        durations = ("ramp_time", "hold_time", "stair_hold", "rest_after", "rest_window")
        kw = {k: getattr(self, k) * factor for k in durations if getattr(self, k) is not None}
        kw.update({k: getattr(self, k) / factor for k in ("scan_rate", "rate")})
        return replace(self, **kw)


@dataclass(frozen=True)
class TiltSpec:
    """What a tilt test runs: ``target`` (a specimen id, Specimen, PointedArch, Assembly or Model:
    :func:`dem.core.model.as_model`, which cuts an arch in ``config``), the simulator's ``settings``, the
    ``protocol``; ``label`` names it (default the model's name); ``assembly``: the blocks the model was built
    from (default the model's own); ``check``: set the answer beside the LP of the same blocks."""

    target: Any
    settings: Settings = field(default_factory=Settings)
    protocol: TiltProtocol = field(default_factory=TiltProtocol)
    config: str = "glued"
    label: str | None = None
    assembly: Any = None
    check: bool = True


@dataclass
class TiltResult(Result):
    """The answer of a tilt test: its one row (the JSON answer of ``archdem tilt``) declared once in ``SCHEMA``."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("id", "str"), Column("lambda", "float"), Column("theta_deg", "float", "deg"), Column("mode", "str"),
        Column("joints", "json"), Column("bracket", "json"), Column("n_sims", "int"), Column("wall_s", "float", "s"),
        Column("protocol", "str"), Column("time_scale", "float"), Column("config", "str"), Column("contact", "float"),
        Column("mu_joint", "float"), Column("mu_base", "float"), Column("planar", "bool"),
        Column("friction_work_J", "float", "J"), Column("out_of_plane", "json"), Column("result_file", "str"),
        Column("lp_check", "json"),
    ))

    label: str
    model: Model
    settings: Settings
    protocol: TiltProtocol
    lam: float
    bracket: tuple[float, float]
    n_sims: int
    wall_s: float
    mode: str
    joints: list
    levels: list  # (lambda, collapsed) of each simulation, in order
    collapse: SimResult | None
    stable: SimResult | None
    criterion: dict
    versions: dict = field(default_factory=dict)
    result_file: str = ""
    lp_check: LpCheck | None = None  # the answer beside the LP of the same blocks (dem.experiments.tilt.check)

    @property
    def theta_deg(self) -> float:
        return math.degrees(math.atan(self.lam))

    @property
    def out_of_plane(self) -> dict:
        return self.collapse.out_of_plane if self.collapse is not None else {}

    def rows(self) -> list[dict]:
        return [{
            "id": self.label, "lambda": self.lam, "theta_deg": self.theta_deg, "mode": self.mode,
            "joints": [j.to_dict() if hasattr(j, "to_dict") else j for j in self.joints],
            "bracket": list(self.bracket), "n_sims": self.n_sims, "wall_s": self.wall_s,
            "protocol": self.protocol.kind, "time_scale": self.protocol.time_scale, "config": self.model.source.get("config", ""),
            "contact": self.model.source.get("contact", 1.0),
            "mu_joint": self.settings.mu_joint, "mu_base": self.settings.mu_base, "planar": self.settings.planar,
            "friction_work_J": self.collapse.history.friction_work if self.collapse else float("nan"),
            "out_of_plane": self.out_of_plane, "result_file": self.result_file,
            "lp_check": self.lp_check.to_dict() if self.lp_check is not None else None,
        }]

    def summary(self) -> dict:
        """The JSON answer of ``archdem tilt``: the table's one row."""
        return self.to_json()[0]

    def lines(self) -> list[str]:
        """The answer as ``archdem tilt`` prints it: lambda, bracket, mode and hinges, the result file, the
        protocol's time scale if slowed, the check against limit analysis."""
        hinges = ", ".join(f"{j['joint']}:{j['state']}" for j in self.rows()[0]["joints"] if j["state"] != "closed")
        st = self.settings
        out = [f"{self.label} ({self.model.source.get('config', '')}, mu {st.mu_joint:g}/{st.mu_base:g}, "
               f"{self.protocol.kind}): lambda = {self.lam:.4f} (theta = {self.theta_deg:.2f} deg), bracket "
               f"[{self.bracket[0]:.4f}, {self.bracket[1]:.4f}], {self.mode} [{hinges}], {self.n_sims} simulations, "
               f"{self.wall_s:.1f} s -> {self.result_file}"]
        if (self.protocol.time_scale or 1.0) > 1.0:
            out.append(f"  protocol {self.protocol.time_scale:.2f} x slower than at the catalogue's scale (a larger "
                       "arch moves more slowly: docs/physics/dem.md#75-arches-larger-than-the-catalogue)")
        out.append(lp_check_line(self.lp_check))
        return out


def lp_check_line(chk: LpCheck | None) -> str:
    """The tilt's own check, as printed under its answer."""
    if chk is None:
        return "  limit analysis: none for this model (no blocks to solve)"
    if chk.agrees is None:
        return f"  limit analysis of the same blocks: no multiplier (lambda = {chk.lp_lam:g}); the tilt is unchecked"
    return (f"  limit analysis of the same blocks{' (no sliding)' if chk.no_sliding else ''}: lambda = {chk.lp_lam:.4f}; "
            f"the tilt is {100 * chk.rel_err:+.1f} % from it "
            f"({'within' if chk.agrees else 'beyond'} {100 * chk.tolerance:g} %)")


def calibration_lines(cal, n_tests: int, out) -> list[str]:
    """A fitted imperfect-fit model (:class:`analytic.limit.calibration.Calibration`, fitted to ``n_tests``
    specimens' laboratory tilts and stored in ``out``) as ``archdem calibrate`` prints it: the fit, a row per
    specimen."""
    rows = [f"{r['id']:<12} {r['t_mm']:5.0f} {r['lambda_lab']:6.3f} {r['lambda_lab_sd']:6.3f} {r['lambda_ideal_lp']:6.3f} "
            f"{r['contact']:7.3f} {r['lambda_fit']:6.3f} {r['residual_pct']:+8.1f} {r['lambda_loo']:6.3f} "
            f"{r['loo_error_pct']:+7.1f}  {r['observed_mode']}" for r in cal.rows]
    return [f"edge loss {cal.edge_loss * 1e3:.2f} mm (scatter {cal.edge_loss_sd * 1e3:.2f} mm per edge), fitted to "
            f"{n_tests} specimens; leave-one-out RMS error {cal.loo_rms_pct:.1f} % "
            f"(one contact fraction for all, {cal.fraction:.3f}: {cal.fraction_loo_rms_pct:.1f} %)",
            f"{'id':<12} {'t mm':>5} {'lab':>6} {'sd':>6} {'ideal':>6} {'contact':>7} {'fit':>6} {'resid %':>8} "
            f"{'LOO':>6} {'LOO %':>7}  mode", *rows, f"-> {out} (used by --contact calibrated)"]


def _static_lp(assembly, settings: Settings):
    """The static LP of ``assembly`` at the settings' frictions, or None if it cannot be solved."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import solve_lp

    try:
        return solve_lp(assembly, settings.mu_joint, settings.mu_base)
    except Exception:  # no admissible LP (e.g. degenerate geometry): fall back to the ramp scan
        return None


def _guess_of(lp) -> float | None:
    lam = float(lp.lam) if lp is not None else math.nan
    return lam if math.isfinite(lam) and lam > 0 else None


def lp_guess(assembly, settings: Settings) -> float | None:
    """First estimate of the tilt lambda of ``assembly`` (a :mod:`specimens.blocks` assembly):
    the static LP of the same blocks at the settings' frictions, or None if it has none."""
    return _guess_of(_static_lp(assembly, settings))


def scaled(proto: TiltProtocol, settings: Settings, s: float) -> tuple[TiltProtocol, Settings]:
    """``proto`` run ``s`` times slower and ``settings`` recorded ``s`` times less often: an arch ``s^2``
    times larger runs the same dimensionless test. The time step stays: PyBullet's contacts are not
    similar under a larger step (a 4 m ring at 3.3 x 0.5 ms collapsed 4 % below its LP)."""
    if s != 1.0:
        settings = settings.with_(record_every=settings.record_every * s)
        proto = proto.slowed(s)
    return replace(proto, time_scale=float(s)), settings


def hold_level(model: Model, settings: Settings, proto: TiltProtocol, lam: float, engine=None) -> SimResult:
    """One simulation of the hold protocol: smooth ramp to ``lam`` over ``proto.ramp_time``,
    then held ``proto.hold_time`` [s], or less if the blocks come to rest (``proto.rest_after``).
    ``engine``: an unbuilt backend (default: ``settings.engine``'s)."""
    rest = None
    if proto.rest_after is not None and proto.rest_after < proto.hold_time:
        rest = (proto.ramp_time + proto.rest_after, proto.rest_window, proto.rest_growth * model.size)
    return simulate(model, settings, TiltHold(lam, proto.ramp_time, g=settings.g), proto.ramp_time + proto.hold_time,
                    rest=rest, engine=engine)


class _LevelProgress:
    """The progress of a hold search: the simulations run, the bracket as :func:`analytic.search.search`
    moves it (an end not run yet marked ``?``), the simulations it still needs, the simulated time of the
    running one."""

    def __init__(self, progress: Progress, proto: TiltProtocol, lo: float, hi: float, up: float, down: float, done: int):
        self.progress, self.proto, self.up, self.down = progress, proto, up, down
        self.lo, self.hi, self.lo_run, self.hi_run, self.done = lo, hi, False, False, done

    def left(self) -> int:
        """Simulations still expected: the bisections to the tolerance, then any end not run."""
        if self.hi - self.lo > self.proto.tol * self.hi:
            return max(1, math.ceil(math.log2((self.hi - self.lo) / (self.proto.tol * self.hi))))
        return (not self.lo_run) + (not self.hi_run)

    def bracket(self) -> str:
        return f"bracket [{self.lo:.4f}{'' if self.lo_run else '?'}, {self.hi:.4f}{'' if self.hi_run else '?'}]"

    def running(self, lam: float, t: float | None = None) -> None:
        now = "" if t is None else f" {t:.1f}/{self.proto.ramp_time + self.proto.hold_time:.1f} s"
        self.progress(self.done, self.done + self.left(), f"level {lam:.4f}{now}; {self.bracket()}")

    def ran(self, lam: float, collapsed: bool) -> None:
        """Move the bracket as the search does (a wrong guessed end moves outward)."""
        if collapsed and lam <= self.lo:
            self.hi, self.hi_run, self.lo, self.lo_run = lam, True, lam * self.down, False
        elif not collapsed and lam >= self.hi:
            self.lo, self.lo_run, self.hi, self.hi_run = lam, True, lam * self.up, False
        elif collapsed:
            self.hi, self.hi_run = lam, True
        else:
            self.lo, self.lo_run = lam, True
        self.done += 1
        self.progress(self.done, self.done + self.left(),
                      f"level {lam:.4f} {'collapsed' if collapsed else 'held'}; {self.bracket()}")


def tilt(target, settings: Settings | None = None, protocol: TiltProtocol | None = None,
         label: str | None = None, assembly=None, config: str = "glued",
         on_level: Callable[[float, SimResult], None] | None = None, check: bool = True,
         progress: Progress | None = None) -> TiltResult:
    """Tilt test of ``target`` (a specimen id, Specimen, PointedArch, Assembly or Model: see
    :func:`dem.core.model.as_model`, which cuts an arch in the ``config`` configuration); see the
    module docstring. ``assembly``: the blocks the model was built from (default: the model's own),
    needed by a hold protocol with ``start="lp"`` and used by ``start="auto"`` (the default; the
    ramp scan without it). The result's ``protocol`` holds the resolved start and, with the LP
    start, the estimate as ``guess``. ``on_level(lam, sim)``: called after every held level (hold).
    ``check``: set the answer beside the LP of the same blocks (``lp_check``, with its warning).
    ``progress(done, total, note)``: called as simulations start, advance and end (:mod:`dem.core.progress`;
    ``done`` simulations, ``total`` the expected number, ``note`` the level and the bracket).
    The same as :func:`run` of a :class:`TiltSpec`."""
    return run(TiltSpec(target, settings or Settings(), protocol or TiltProtocol(), config, label, assembly, check),
               on_level=on_level, progress=progress)


def run(spec: TiltSpec, on_level: Callable[[float, SimResult], None] | None = None,
        progress: Progress | None = None) -> TiltResult:
    """The tilt test of ``spec`` (the module docstring). ``on_level(lam, sim)`` and ``progress(done, total,
    note)``: as :func:`tilt`'s, watchers of the run, not part of what it runs."""
    model = as_model(spec.target, config=spec.config)
    assembly = model.assembly if spec.assembly is None else spec.assembly
    settings, proto, label, check = spec.settings, spec.protocol, spec.label, spec.check
    wall0 = time.perf_counter()
    if proto.time_scale is None:
        proto, settings = scaled(proto, settings, time_scale_of(assembly if assembly is not None else model))
    if proto.start == "auto":
        proto = replace(proto, start="lp" if assembly is not None else "scan")
    lp = None
    if proto.kind == "hold" and proto.guess is None and proto.start == "lp":
        if assembly is None:
            raise ValueError("a tilt protocol with start='lp' needs the assembly of the model")
        if progress is not None:
            progress(0, None, "static LP of the blocks (first estimate)")
        lp = _static_lp(assembly, settings)
        proto = replace(proto, guess=_guess_of(lp))  # None (no LP): the ramp scan
    levels: list[tuple[float, bool]] = []
    collapse = stable = None

    def engine(note: str, duration: float, total: int | None = 1):
        """The backend of the one simulation of a scan, staircase or ramp: telling ``progress`` (if any) its
        simulated time, out of ``duration`` [s] at most (it ends at collapse)."""
        if progress is None:
            return None
        progress(0, total, note)
        return TimedEngine(get_engine(settings.engine, settings.engine_options), settings.dt,
                           lambda t: progress(0, total, f"{note} {t:.1f}/{duration:.1f} s"))

    if proto.kind == "hold":
        if proto.guess is not None:
            n = 0
            hi, lo = proto.guess_bracket[1] * proto.guess, proto.guess_bracket[0] * proto.guess
            up, down = GUESS_STEPS
        else:
            duration = proto.lam_max / proto.scan_rate
            scan = simulate(model, settings, TiltRamp(proto.scan_rate, g=settings.g), duration,
                            engine=engine("ramp scan for a first estimate:", duration, total=None))
            n = 1
            if not scan.collapsed:
                raise ArchdemInputError(f"no collapse up to lambda = {proto.lam_max:g}")
            # the ramp's level at detection overshoots the held threshold by 10-18 % (catalogue,
            # reference friction, rate 0.25/s): the bracket starts 15 % below it
            est = proto.scan_rate * scan.t_collapse
            hi, lo = est, 0.85 * est
            up, down = 1.1, 0.85

        track = _LevelProgress(progress, proto, lo, hi, up, down, n) if progress is not None else None

        def run_level(lam: float) -> SimResult:
            if track is None:
                r = hold_level(model, settings, proto, lam)
            else:
                track.running(lam)
                r = hold_level(model, settings, proto, lam, engine=TimedEngine(
                    get_engine(settings.engine, settings.engine_options), settings.dt, lambda t: track.running(lam, t)))
            levels.append((lam, r.collapsed))
            if track is not None:
                track.ran(lam, r.collapsed)
            if on_level is not None:
                on_level(lam, r)
            return r

        res = search(run_level, lo, hi, proto.tol, rule="width/hi", is_upper=lambda r: r.collapsed,
                     up=lambda x: x * up, down=lambda x: x * down, ends=proto.probe_ends, limit=proto.lam_max,
                     max_runs=proto.max_sims - n)
        n += res.runs
        if res.status == "no_upper":
            raise ArchdemInputError(f"no collapse up to lambda = {res.hi:g} under held levels")
        if not res.bracketed:
            raise ArchdemInputError(f"no bracket of a held and a collapsing level within {proto.max_sims} simulations "
                                    f"(levels {', '.join(f'{x:.4g}' for x, _ in levels)}); from Python raise "
                                    "TiltProtocol.max_sims; from the command line the joints' law is the suspect")
        lam, bracket, collapse, stable = res.hi, (res.lo, res.hi), res.hi_run, res.lo_run
    elif proto.kind == "staircase":
        load = TiltStairs(proto.step, proto.stair_hold, g=settings.g)
        period = proto.stair_hold + load.rise
        duration = period * math.ceil(proto.lam_max / proto.step)
        r = simulate(model, settings, load, duration, engine=engine("staircase:", duration))
        n = 1
        if not r.collapsed:
            raise ArchdemInputError(f"no collapse up to lambda = {proto.lam_max:g}")
        # the answer is the step during which the collapsing motion started (every lower step
        # was held without it), not the one at which the collapse criterion fired: slow
        # collapses just above the threshold take longer than one hold to travel that far
        k = math.floor(onset_time(model, settings, r) / period + 1e-9)
        lam = proto.step * (k + 1)
        levels.append((lam, True))
        collapse, bracket = r, (proto.step * k, lam)
    else:
        duration = proto.lam_max / proto.rate
        r = simulate(model, settings, TiltRamp(proto.rate, g=settings.g), duration, engine=engine("ramp:", duration))
        n = 1
        if not r.collapsed:
            raise ArchdemInputError(f"no collapse up to lambda = {proto.lam_max:g}")
        # lambda at the onset of the collapsing motion; it still lags the threshold by the time
        # the mechanism needs to move onset_displacement (for a block sliding on a ramp of rate r:
        # about r^(2/3) (6 d / g)^(1/3), i.e. 1 % of mu = 0.3 at r = 0.005/s)
        t_on = onset_time(model, settings, r)
        lam = proto.rate * t_on
        levels.append((lam, True))
        collapse, bracket = r, (proto.rate * max(t_on - settings.record_every, 0.0), lam)
    if progress is not None:
        progress(n, n, f"lambda = {lam:.4f}")
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.core.provenance import run_provenance

    res = TiltResult(label or model.name, model, settings, proto, float(lam), (float(bracket[0]), float(bracket[1])),
                     n, time.perf_counter() - wall0, collapse.mode if collapse else "none",
                     collapse.joints if collapse else [], levels, collapse, stable,
                     detect.criterion(settings, model), run_provenance(settings.engine, settings.engine_options))
    if check and assembly is not None:
        # the guess's LP is the reference unless both frictions prevent sliding (then the LP without friction)
        same = lp is not None and not prevents_sliding(settings.mu_joint, settings.mu_base)
        res.lp_check = lp_check(res, assembly, lp if same else None)
    return res
