"""Free vibration of a model on compliant joints: the frequencies and damping ratios the DEM gives,
for checks against closed forms and ``analytic.compliant.modes`` (docs/physics/dem.md#17-compliant-joints).

The model starts as built, its joints unloaded: under its weight it drops onto its springs and
swings about its rest position (the vertical modes); once that has settled, a short horizontal
gravity pulse sets it rocking (nudged at once, PyBullet's sequential contact solver feeds the drop's
vertical energy into the rocking, which then grows before it decays). The time history is read every
step; each signal's frequency is the peak of its spectrum and its damping ratio the decay of its
successive peaks.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.signal import find_peaks

from dem.core.loads import Load
from dem.core.model import Model
from dem.core.settings import Settings
from dem.core.simulate import simulate
from foundation.errors import ArchdemInputError


@dataclass(frozen=True)
class Nudge(Load):
    """Gravity with a horizontal component ``a`` [m/s^2] from ``t0`` for ``pulse`` [s]."""

    a: float
    pulse: float
    g: float
    t0: float = 0.0

    def gravity(self, t: float) -> np.ndarray:
        return np.array([self.a if self.t0 <= t < self.t0 + self.pulse else 0.0, -self.g, 0.0])

    def describe(self) -> dict:
        return {"kind": "nudge", "a": self.a, "pulse": self.pulse, "g": self.g, "t0": self.t0}


@dataclass(frozen=True)
class Vibration:
    """Frequency [Hz] and damping ratio of one signal of the free vibration."""

    frequency_hz: float
    damping: float


def _frequency(y: np.ndarray, dt: float) -> float:
    """Peak of the Hann-windowed spectrum, zero-padded 16 times, refined by a parabola through the
    log of the three highest bins [Hz]."""
    y = y - y.mean()
    n = 16 * len(y)
    S = np.abs(np.fft.rfft(y * np.hanning(len(y)), n))
    k = int(np.argmax(S[1:])) + 1
    a, b, c = np.log(S[k - 1:k + 2] + 1e-300)
    return float((k + 0.5 * (a - c) / (a - 2 * b + c)) / (n * dt))


def _damping(y: np.ndarray, dt: float, f_hz: float) -> float:
    """Damping ratio from the decay of the signal's successive peaks (log-linear fit)."""
    y = y - y[len(y) // 2:].mean()
    pk, _ = find_peaks(y, distance=max(1, int(0.5 / (f_hz * dt))))
    pk = pk[y[pk] > 1e-3 * y[pk].max()] if len(pk) else pk
    if len(pk) < 3:
        return float("nan")
    slope = np.polyfit(pk * dt, np.log(y[pk]), 1)[0]
    return float(-slope / (2 * math.pi * f_hz))


def free_vibration(model: Model, settings: Settings, duration: float = 1.0, settle: float = 0.5,
                   nudge_g: float = 0.02, pulse: float = 0.005) -> dict[str, Vibration]:
    """The body ``model.crown``'s vertical (``"vertical"``, over the whole run) and rotational (``"rocking"``,
    over ``duration`` [s] after the nudge) free vibration on compliant joints; ``nudge_g`` [g] over
    ``pulse`` [s] at ``settle`` [s] starts the rocking."""
    if settings.contact_law != "compliant":
        raise ArchdemInputError("free vibration needs compliant joints (contact_law 'compliant')")
    res = simulate(model, settings, Nudge(nudge_g * settings.g, pulse, settings.g, settle), settle + duration,
                   record_every=settings.dt, stop_on_collapse=False, friction_work=False)
    h = res.history
    i0 = int(np.searchsorted(h.t, settle + 2 * pulse))
    y = h.pos[:, model.crown, 1]
    R = h.rotations()[i0:, model.crown]
    theta = np.arctan2(R[:, 1, 0], R[:, 0, 0])
    out = {}
    for name, sig in (("vertical", y), ("rocking", theta)):
        f = _frequency(sig, settings.dt)
        out[name] = Vibration(f, _damping(sig, settings.dt, f))
    return out
