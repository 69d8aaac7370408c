"""The own options of ``archdem shake`` and ``archdem threshold`` as frozen specs: each field is an option
(its help and unit in its metadata, its default the library's), checked once in the spec itself, so a
script that builds one meets the command's refusals. The commands add them from the fields
(:func:`dem.experiments.contract.add_spec_options`); the specs build the motion, the protocol and the run
specs of :mod:`dem.experiments.shake.run` and :mod:`dem.experiments.shake.thresholds`."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property, partial
from typing import Any, Callable

from analytic.motions.inputs import MIN_PEAK_ACCELERATION, GroundMotion
from analytic.motions.records import MAX_RECORD_BYTES, MAX_RECORD_S, MAX_RECORD_SAMPLES, ground_motion
from dem.common.limits import MAX_AMPLITUDE_G, MAX_SINE_HZ, MIN_SINE_HZ
from dem.core.settings import Settings
from dem.experiments.shake.run import ANNOUNCE_SIMULATED_S, LOADS, MAX_RUN_S, MAX_SIMULATED_S, ShakeProtocol, ShakeSpec
from dem.experiments.shake.thresholds import SCAN_TOP, ThresholdSpec, sine_motion
from foundation.errors import ArchdemInputError
from foundation.fields import default_of
from specimens.constants import G

#: Fastest table speed an option takes [m/s].
MAX_TABLE_SPEED = 100.0


def _opt(default: Any, help: str, **meta: Any) -> Any:
    """A field that is an option: its ``help`` (with its unit in it), argparse's ``choices`` or ``metavar``,
    and ``shown`` None: the help says the default itself."""
    return field(default=default, metadata={"help": help, **meta})


def check_sine(sine: float | None) -> None:
    """A one-cycle sine's frequency [Hz] within the bounds of :mod:`dem.common.limits`."""
    if sine is not None and not (math.isfinite(sine) and MIN_SINE_HZ <= sine <= MAX_SINE_HZ):
        raise ArchdemInputError(f"--sine must be a frequency in [{MIN_SINE_HZ:g}, {MAX_SINE_HZ:g}] Hz, got {sine:g}")


def check_amplitude(option: str, a: float | None) -> None:
    """A sine's amplitude [g] (``option`` names it) within (0, MAX_AMPLITUDE_G] and above an accelerometer's
    resolution."""
    if a is not None and not (math.isfinite(a) and 0 < a <= MAX_AMPLITUDE_G):
        raise ArchdemInputError(f"{option} must be in (0, {MAX_AMPLITUDE_G:g}] g, got {a:g}")
    if a is not None and a * G < MIN_PEAK_ACCELERATION:
        raise ArchdemInputError(f"{option} {a:g} g is below {MIN_PEAK_ACCELERATION / G:g} g, an accelerometer's "
                                "resolution: it moves nothing")


@dataclass(frozen=True)
class TableOptions:
    """What a shake and a threshold search share: the zero tail, how the motion loads the arch, and the
    table's speed limit (None: the ideal sine)."""

    tail: float = _opt(default_of(ShakeProtocol, "tail"),
                       f"zero-acceleration tail after the motion [s], up to {MAX_SIMULATED_S:g}")
    load: str = _opt(default_of(ShakeProtocol, "load"), "ground motion as a uniform inertial field on a fixed base "
                     f"(inertial) or as a moving base (driven-base); default {default_of(ShakeProtocol, 'load')}",
                     choices=LOADS, shown=None)
    table_speed: float | None = _opt(None, "the table's speed limit [m/s] (the laboratory's servo: 1): a sine faster "
                                     "than it runs as the motion of a table that cannot follow it (default: the ideal "
                                     "sine)", metavar="M_PER_S")

    def _check_table_speed(self, record: Any = None) -> None:
        v = self.table_speed
        if v is not None and not (math.isfinite(v) and 0 < v <= MAX_TABLE_SPEED):
            raise ArchdemInputError(f"--table-speed must be a speed in (0, {MAX_TABLE_SPEED:g}] m/s, got {v:g}")
        if v is not None and record is not None:
            raise ArchdemInputError("--table-speed applies to a one-cycle sine (--sine), not to a record")

    def motion_fn(self) -> Callable[[float, float], GroundMotion]:
        """The one-cycle sine ``(a [m/s^2], f [Hz]) -> motion``: the ideal sine, or with a table speed the
        motion of a table whose servo cannot exceed it (:func:`analytic.motions.table.servo_sine`)."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.motions.table import servo_sine

        return sine_motion if self.table_speed is None else partial(servo_sine, v_max=float(self.table_speed))


@dataclass(frozen=True)
class ShakeOptions(TableOptions):
    """The options of ``archdem shake`` besides the structure and the simulator's: the motion (a one-cycle
    sine of ``sine`` [Hz] and ``amplitude`` [g], or a record) and the run's length; ``units``: the record's
    (the shared ``--units``). Checked on construction; ``motion`` and ``protocol`` are built then."""

    sine: float | None = _opt(None, f"one-cycle sine pulse of FREQ [Hz], up to {MAX_SINE_HZ:g}", metavar="FREQ")
    amplitude: float | None = _opt(None, f"sine amplitude [g], from {MIN_PEAK_ACCELERATION / G:g} up to "
                                   f"{MAX_AMPLITUDE_G:g}", metavar="A_G")
    record: str | None = _opt(None, f"accelerogram (.AT2, .smc, ESM ASCII, CSV), up to {MAX_RECORD_BYTES // 2**20} MB, "
                              f"{MAX_RECORD_SAMPLES} samples and {MAX_RECORD_S:g} s", metavar="FILE")
    scale: float | None = _opt(None, "record scale factor")
    pga: float | None = _opt(None, "scale the record to this PGA [g]", metavar="A_G")
    baseline: bool = _opt(False, "baseline-correct the record (linear velocity fit)", shown=None)
    duration: float | None = _opt(None, f"simulated time [s], up to {MAX_SIMULATED_S:g} (default: motion + tail, up "
                                  f"to {MAX_RUN_S:g})")
    full: bool = _opt(False, "simulate the whole duration (default: stop at collapse, or once at rest after the "
                      "motion)", shown=None)
    units: str | None = None

    def __post_init__(self) -> None:
        check_sine(self.sine)
        check_amplitude("--amplitude", self.amplitude)
        self.motion  # noqa: B018 (built here: its refusals before any work)
        self.protocol  # noqa: B018

    @cached_property
    def motion(self) -> GroundMotion:
        """The ground motion [m/s^2] (:func:`analytic.motions.records.ground_motion`), through the table's
        servo with a table speed."""
        m = ground_motion(sine=self.sine, amplitude=self.amplitude, record=self.record, units=self.units,
                          baseline=self.baseline, scale=self.scale, pga=self.pga)
        self._check_table_speed(self.record)
        return m if self.table_speed is None else self.motion_fn()(m.a, m.f)

    @cached_property
    def protocol(self) -> ShakeProtocol:
        """The run's protocol: ``full`` simulates the whole duration (no stop at collapse or at rest)."""
        return ShakeProtocol(tail=self.tail, duration=self.duration, stop_on_collapse=not self.full, load=self.load,
                             **({"rest_after": None} if self.full else {}))

    def run_spec(self, model: Any, settings: Settings, label: str) -> ShakeSpec:
        """The run's :class:`~dem.experiments.shake.run.ShakeSpec` on ``model``, named ``label``."""
        return ShakeSpec(model, self.motion, settings, self.protocol, label)

    def announcement(self, settings: Settings) -> str:
        """What a run longer than ANNOUNCE_SIMULATED_S says before it starts (how much it simulates, in how
        many steps), "" for a shorter one; a run longer than the protocol takes is refused here."""
        total = self.protocol.total_duration(self.motion)
        if total <= ANNOUNCE_SIMULATED_S:
            return ""
        return (f"simulating up to {total:g} s of motion and tail ({math.ceil(total / settings.dt)} steps of "
                f"{settings.dt:g} s)" + ("" if self.full else "; stops at collapse, or once at rest after the motion"))

    def stem(self, label: str, config: str) -> str:
        """The run file's name stem."""
        return f"shake-{label}-{config}-" + (f"sine{self.sine:g}Hz-{self.amplitude:g}g" if self.sine else "record")


@dataclass(frozen=True)
class ThresholdOptions(TableOptions):
    """The options of ``archdem threshold`` besides the structure and the simulator's: the amplitude scan
    [g] and the bisection's tolerance at ``sine`` [Hz]; ``check``: the settled-or-range check (the command's
    ``--no-check`` turns it off). Checked on construction."""

    sine: float | None = _opt(None, f"sine frequency [Hz], up to {MAX_SINE_HZ:g}", metavar="FREQ", required=True)
    a_min: float | None = _opt(None, f"scan start [g], at least {MIN_PEAK_ACCELERATION / G:g} (default: static "
                               "lambda)", shown=None)
    a_max: float | None = _opt(None, f"scan end [g] (default {SCAN_TOP:g} x start)", shown=None)
    scan_ratio: float = _opt(default_of(ThresholdSpec, "scan_ratio"), "scan step ratio")
    tol: float = _opt(default_of(ThresholdSpec, "tol"), "relative bisection tolerance")
    check: bool = True

    def __post_init__(self) -> None:
        if self.sine is None:
            raise ArchdemInputError("a threshold search needs --sine FREQ")
        check_sine(self.sine)
        check_amplitude("--a-min", self.a_min)
        check_amplitude("--a-max", self.a_max)
        if not (math.isfinite(self.scan_ratio) and 1 < self.scan_ratio <= 10):
            raise ArchdemInputError(f"--scan-ratio must be in (1, 10], got {self.scan_ratio:g}")
        if not (math.isfinite(self.tol) and 1e-3 <= self.tol <= 0.5):
            raise ArchdemInputError(f"--tol must be a relative tolerance in [0.001, 0.5], got {self.tol}")
        ShakeProtocol(tail=self.tail, load=self.load)
        self._check_table_speed()

    def run_spec(self, model: Any, settings: Settings) -> ThresholdSpec:
        """The search's :class:`~dem.experiments.shake.thresholds.ThresholdSpec` on ``model``."""
        return ThresholdSpec(model, self.sine, settings, ShakeProtocol(tail=self.tail, load=self.load), self.a_min,
                             self.a_max, self.scan_ratio, self.tol, check=self.check, motion_fn=self.motion_fn())
