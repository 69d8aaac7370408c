"""Horizontal ground-acceleration inputs, shared by the linkage models and the simulator.

docs/physics/dynamics.md#8-ground-motion-inputs. Every input is a frozen object with ``acceleration(t)`` [m/s^2] (zero
outside its support), ``duration`` [s] and ``breakpoints`` (times where the signal or its
slope jumps: an ODE integrator should stop there). Amplitudes are in m/s^2; use
:data:`G` to convert from g.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from specimens.constants import G
from foundation.errors import ArchdemInputError


def _check_positive(name: str, v: float) -> None:
    if not (isinstance(v, (int, float, np.floating, np.integer)) and math.isfinite(v) and v > 0):
        raise ArchdemInputError(f"{name} must be a positive finite number, got {v!r}")


class GroundMotion:
    """Base class: a horizontal ground acceleration history."""

    duration: float

    def acceleration(self, t: float | np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    @property
    def breakpoints(self) -> tuple[float, ...]:
        return (0.0, self.duration)

    @property
    def pga(self) -> float:
        """Peak absolute acceleration [m/s^2] (sampled finely)."""
        t = np.linspace(0.0, self.duration, 20001)
        return float(np.max(np.abs(self.acceleration(t))))

    def scaled(self, factor: float) -> "GroundMotion":  # pragma: no cover - abstract
        raise NotImplementedError

    def describe(self) -> dict:
        """Parameters for result files."""
        return {"kind": type(self).__name__, "duration": self.duration}


@dataclass(frozen=True)
class PulseA(GroundMotion):
    """Constant acceleration ``a`` during ``[0, t_i]``."""

    a: float
    t_i: float

    def __post_init__(self) -> None:
        _check_positive("pulse duration t_i", self.t_i)

    @property
    def duration(self) -> float:  # type: ignore[override]
        return self.t_i

    def acceleration(self, t):
        t = np.asarray(t, dtype=float)
        return np.where((t >= 0) & (t <= self.t_i), self.a, 0.0)

    def scaled(self, factor: float) -> "PulseA":
        return replace(self, a=self.a * factor)

    def describe(self) -> dict:
        return {"kind": "pulse-A", "a": self.a, "t_i": self.t_i, "duration": self.duration}


@dataclass(frozen=True)
class PulseB(GroundMotion):
    """``-a`` during ``[0, t_i]``, then ``+a/2`` during ``(t_i, 3 t_i]``."""

    a: float
    t_i: float

    def __post_init__(self) -> None:
        _check_positive("pulse duration t_i", self.t_i)

    @property
    def duration(self) -> float:  # type: ignore[override]
        return 3 * self.t_i

    @property
    def breakpoints(self) -> tuple[float, ...]:
        return (0.0, self.t_i, 3 * self.t_i)

    def acceleration(self, t):
        t = np.asarray(t, dtype=float)
        return np.where((t >= 0) & (t <= self.t_i), -self.a, np.where((t > self.t_i) & (t <= 3 * self.t_i), 0.5 * self.a, 0.0))

    def scaled(self, factor: float) -> "PulseB":
        return replace(self, a=self.a * factor)

    def describe(self) -> dict:
        return {"kind": "pulse-B", "a": self.a, "t_i": self.t_i, "duration": self.duration}


@dataclass(frozen=True)
class SinePulse(GroundMotion):
    """One cycle ``a sin(2 pi f t + phase)`` for ``t in [0, (2 pi - phase) / (2 pi f)]``.

    ``phase = 0`` is the plain one-cycle sine of a shake table; :meth:`phased` starts the
    motion at the onset acceleration (docs/physics/dynamics.md#8-ground-motion-inputs).
    """

    a: float
    f: float
    phase: float = 0.0

    def __post_init__(self) -> None:
        _check_positive("frequency f", self.f)
        if not (0.0 <= self.phase <= math.pi / 2):
            raise ArchdemInputError(f"sine phase must be in [0, pi/2], got {self.phase!r}")

    @classmethod
    def phased(cls, a: float, f: float, onset: float) -> "SinePulse":
        """Phase ``asin(onset / a)`` so that ``a_g(0)`` equals the onset acceleration [m/s^2]."""
        if a < onset:
            raise ArchdemInputError(f"phased sine needs amplitude >= onset acceleration ({a:g} < {onset:g} m/s^2)")
        return cls(a, f, math.asin(onset / a))

    @property
    def duration(self) -> float:  # type: ignore[override]
        return (2 * math.pi - self.phase) / (2 * math.pi * self.f)

    def acceleration(self, t):
        t = np.asarray(t, dtype=float)
        inside = (t >= 0) & (t <= self.duration)
        return np.where(inside, self.a * np.sin(2 * math.pi * self.f * t + self.phase), 0.0)

    def scaled(self, factor: float) -> "SinePulse":
        # the phased pulse keeps its phase rule only if rebuilt by the caller
        return replace(self, a=self.a * factor)

    @property
    def pga(self) -> float:
        return abs(self.a)

    def describe(self) -> dict:
        return {"kind": "sine", "a": self.a, "f": self.f, "phase": self.phase, "duration": self.duration}


#: Smallest peak a sampled motion may have [m/s^2]: 1e-6 g, the resolution of a strong-motion
#: accelerometer; below it (a record of zeros, a typo in a scale) no block can move.
MIN_PEAK_ACCELERATION = 1e-6 * G


@dataclass(frozen=True)
class SampledMotion(GroundMotion):
    """A sampled accelerogram: values [m/s^2] at ``t_k = k dt``, linear in between, times ``scale``.

    ``name`` and ``source`` are provenance strings kept in result files.
    """

    values: np.ndarray = field(repr=False)
    dt: float
    scale: float = 1.0
    name: str = ""
    source: str = ""

    def __post_init__(self) -> None:
        _check_positive("time step dt", self.dt)
        v = np.asarray(self.values, dtype=float)
        if v.ndim != 1 or len(v) < 2:
            raise ArchdemInputError("a sampled motion needs a 1-D array of at least 2 values")
        if not np.all(np.isfinite(v)):
            raise ArchdemInputError("a sampled motion contains non-finite values")
        peak = abs(float(self.scale)) * float(np.max(np.abs(v)))
        if not (math.isfinite(peak) and peak >= MIN_PEAK_ACCELERATION):
            what = "is all zeros" if peak == 0 else f"peaks at {peak / G:.3g} g"
            raise ArchdemInputError(f"the motion{f' {self.name!r}' if self.name else ''} {what}: below "
                                    f"{MIN_PEAK_ACCELERATION / G:g} g, an accelerometer's resolution, it moves nothing")
        object.__setattr__(self, "values", v)

    @property
    def duration(self) -> float:  # type: ignore[override]
        return self.dt * (len(self.values) - 1)

    @property
    def times(self) -> np.ndarray:
        return self.dt * np.arange(len(self.values))

    def acceleration(self, t):
        t = np.asarray(t, dtype=float)
        return self.scale * np.interp(t, self.times, self.values, left=0.0, right=0.0)

    @property
    def breakpoints(self) -> tuple[float, ...]:
        return tuple(self.times)

    @property
    def pga(self) -> float:
        return float(self.scale * np.max(np.abs(self.values)))

    def scaled(self, factor: float) -> "SampledMotion":
        return replace(self, scale=self.scale * factor)

    def to_pga(self, target: float) -> "SampledMotion":
        """Scaled so that its peak absolute acceleration is ``target`` [m/s^2]."""
        _check_positive("target PGA", target)
        return replace(self, scale=target / float(np.max(np.abs(self.values))))

    def describe(self) -> dict:
        return {"kind": "record", "name": self.name, "source": self.source, "dt": self.dt,
                "npts": len(self.values), "scale": self.scale, "pga": self.pga, "duration": self.duration}
