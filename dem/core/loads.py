"""The load: the gravity field as a function of time, in the arch frame (y up).

* static tilt: gravity rotated by ``theta`` at constant magnitude,
  ``g (sin theta, -cos theta, 0)`` with ``lambda = tan theta`` (docs/physics/dem.md#3-loads); the horizontal
  component points to +x;
* a level reached by a smooth ramp (``ramp``) or a linear one in ``lambda`` (``linear``);
* a horizontal ground acceleration ``a_g(t)`` (:class:`analytic.motions.inputs.GroundMotion`), applied
  as a uniform inertial field in the table frame: the base is fixed and the bodies feel
  ``(-a_g(t), -g, 0)`` (d'Alembert). A ground acceleration to +x throws the arch to -x.
  With ``driven_base=True`` the same motion is applied the laboratory way instead: gravity
  ``(0, -g, 0)`` and the base moved by the ground displacement (:func:`dem.core.simulate.simulate`
  integrates ``a_g``); ``gravity(t)`` is then the equivalent field in the table frame, which is
  what the results record.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from analytic.motions.inputs import GroundMotion
from specimens.constants import G


def tilt_gravity(lam: float, g: float = G) -> np.ndarray:
    """Gravity of a ramp tilted to ``theta = atan(lam)``, constant magnitude ``g`` [m/s^2]."""
    th = math.atan(lam)
    return np.array([g * math.sin(th), -g * math.cos(th), 0.0])


class Load:
    """Base class: ``gravity(t)`` -> (3,) [m/s^2]; ``describe()`` for result files."""

    duration: float = math.inf

    def gravity(self, t: float) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def describe(self) -> dict:  # pragma: no cover - abstract
        raise NotImplementedError


@dataclass(frozen=True)
class Rest(Load):
    """Gravity alone."""

    g: float = G

    def gravity(self, t: float) -> np.ndarray:
        return tilt_gravity(0.0, self.g)

    def describe(self) -> dict:
        return {"kind": "rest", "g": self.g}


@dataclass(frozen=True)
class TiltHold(Load):
    """Tilt from ``lam0`` to ``lam`` over ``ramp_time`` [s] (smooth, zero-rate ends), then held."""

    lam: float
    ramp_time: float = 1.0
    lam0: float = 0.0
    g: float = G

    def level(self, t: float) -> float:
        if self.ramp_time <= 0 or t >= self.ramp_time:
            return self.lam
        s = max(t, 0.0) / self.ramp_time
        return self.lam0 + (self.lam - self.lam0) * (s * s * (3 - 2 * s))

    def gravity(self, t: float) -> np.ndarray:
        return tilt_gravity(self.level(t), self.g)

    def describe(self) -> dict:
        return {"kind": "tilt-hold", "lambda": self.lam, "lambda0": self.lam0, "ramp_time": self.ramp_time, "g": self.g}


@dataclass(frozen=True)
class TiltRamp(Load):
    """``lambda(t) = lam0 + rate t`` (continuous ramp) [1/s]."""

    rate: float
    lam0: float = 0.0
    g: float = G

    def level(self, t: float) -> float:
        return self.lam0 + self.rate * max(t, 0.0)

    def gravity(self, t: float) -> np.ndarray:
        return tilt_gravity(self.level(t), self.g)

    def describe(self) -> dict:
        return {"kind": "tilt-ramp", "rate": self.rate, "lambda0": self.lam0, "g": self.g}


@dataclass(frozen=True)
class TiltStairs(Load):
    """Staircase: ``lam0 + k step`` held ``hold`` [s] each, raised over ``rise`` [s] (smooth)."""

    step: float
    hold: float
    rise: float = 0.2
    lam0: float = 0.0
    g: float = G

    def level(self, t: float) -> float:
        period = self.hold + self.rise
        k = math.floor(max(t, 0.0) / period)
        s = min((max(t, 0.0) - k * period) / self.rise, 1.0) if self.rise > 0 else 1.0
        return self.lam0 + self.step * (k + s * s * (3 - 2 * s))

    def gravity(self, t: float) -> np.ndarray:
        return tilt_gravity(self.level(t), self.g)

    def describe(self) -> dict:
        return {"kind": "tilt-staircase", "step": self.step, "hold": self.hold, "rise": self.rise,
                "lambda0": self.lam0, "g": self.g}


@dataclass(frozen=True)
class GroundShake(Load):
    """Horizontal ground acceleration ``motion`` (starting at ``t0`` [s]) as an inertial field, or,
    with ``driven_base``, as the motion of the base under plain gravity."""

    motion: GroundMotion
    t0: float = 0.0
    g: float = G
    driven_base: bool = False

    def ground_acceleration(self, t: float) -> float:
        """Table acceleration a_g [m/s^2] (+x) at time ``t`` [s]."""
        return float(self.motion.acceleration(t - self.t0))

    @property
    def duration(self) -> float:  # type: ignore[override]
        return self.t0 + self.motion.duration

    def gravity(self, t: float) -> np.ndarray:
        return np.array([-self.ground_acceleration(t), -self.g, 0.0])

    def describe(self) -> dict:
        return {"kind": "ground-motion", "t0": self.t0, "g": self.g, "motion": self.motion.describe(),
                "load": "driven-base" if self.driven_base else "inertial"}
