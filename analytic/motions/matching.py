"""Records matched to a site spectrum (docs/physics/assessment.md#6-records-matched-to-the-site).

Each record is baseline-corrected, cut to its significant duration (5-95 % of the Arias intensity
``integral a^2 dt``, plus a zero tail at the simulation) and scaled by one factor ``k`` so that its
5 %-damped pseudo-acceleration spectrum ``Sa(T)`` (computed by pyrotd) matches the site's elastic
spectrum ``Se(T)`` over a period range in the least-squares sense on a log scale::

    ln k = mean over T of [ln Se(T) - ln Sa(T)]

The misfit reported is the largest and the mean |ln(k Sa / Se)| over the range.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

with warnings.catch_warnings():
    # pyrotd 0.6.1 reads its own version through pkg_resources, which warns on import that it is deprecated
    warnings.filterwarnings("ignore", message="pkg_resources is deprecated")
    import pyrotd

from analytic.motions.inputs import SampledMotion
from foundation.errors import ArchdemInputError

#: Periods sampled (log-spaced) over the matching range.
MATCH_PERIODS = 40
#: Fractions of the Arias intensity that bound the significant duration.
ARIAS_WINDOW = (0.05, 0.95)


def response_spectrum(motion: SampledMotion, periods, damping: float = 5.0) -> np.ndarray:
    """Pseudo-spectral acceleration [m/s^2] of ``motion`` at ``periods`` [s], ``damping`` [%] (pyrotd)."""
    T = np.asarray(periods, dtype=float)
    if np.any(T <= 0) or not np.all(np.isfinite(T)):
        raise ArchdemInputError("response-spectrum periods must be positive")
    if np.any(T < 2.0 * motion.dt):
        raise ArchdemInputError(f"{motion.name or 'record'}: periods below 2 dt = {2 * motion.dt:g} s are not resolved")
    accel = np.asarray(motion.values, float) * motion.scale
    r = pyrotd.calc_spec_accels(motion.dt, accel, 1.0 / T, damping / 100.0)
    return np.asarray(r.spec_accel, dtype=float)


def arias_window(motion: SampledMotion, bounds: tuple[float, float] = ARIAS_WINDOW) -> tuple[int, int]:
    """Sample indices ``[i0, i1)`` between the times ``motion``'s Arias intensity reaches ``bounds``
    (fractions of its total)."""
    a = np.asarray(motion.values, float)
    ia = np.concatenate([[0.0], np.cumsum(0.5 * (a[1:] ** 2 + a[:-1] ** 2))])
    if not ia[-1] > 0:
        raise ArchdemInputError(f"{motion.name or 'record'}: the record holds no motion")
    i0 = int(np.searchsorted(ia, bounds[0] * ia[-1]))
    i1 = int(np.searchsorted(ia, bounds[1] * ia[-1])) + 1
    i0, i1 = max(0, i0 - 1), min(len(a), max(i1, i0 + 2))
    return i0, i1


def significant_window(motion: SampledMotion, bounds: tuple[float, float] = ARIAS_WINDOW) -> SampledMotion:
    """The part of ``motion`` between the times its Arias intensity reaches ``bounds`` (fractions)."""
    i0, i1 = arias_window(motion, bounds)
    return SampledMotion(motion.values[i0:i1], motion.dt, motion.scale, name=f"{motion.name} [{i0 * motion.dt:.2f}, "
                         f"{(i1 - 1) * motion.dt:.2f}] s", source=motion.source)


@dataclass(frozen=True)
class MatchedRecord:
    """``motion``: the windowed record times ``scale``; ``periods`` [s] of the match, the record's
    ``Sa`` (unscaled) and the site's ``Se`` there [m/s^2]; misfits of ln(k Sa / Se)."""

    motion: SampledMotion
    scale: float
    periods: np.ndarray
    Sa: np.ndarray
    Se: np.ndarray

    @property
    def misfit_max(self) -> float:
        return float(np.max(np.abs(np.log(self.scale * self.Sa / self.Se))))

    @property
    def misfit_mean(self) -> float:
        return float(np.mean(np.abs(np.log(self.scale * self.Sa / self.Se))))

    def describe(self) -> dict:
        return {"record": self.motion.name, "source": self.motion.source, "scale": self.scale,
                "pga_scaled": self.motion.pga, "period_range": [float(self.periods[0]), float(self.periods[-1])],
                "misfit_max_ln": self.misfit_max, "misfit_mean_ln": self.misfit_mean,
                "duration": self.motion.duration}


def match_record(motion: SampledMotion, site, t_range: tuple[float, float]) -> MatchedRecord:
    """``motion`` (baseline-corrected by the caller) cut to its significant duration and scaled to the
    site's spectrum over ``t_range`` [s] (module doc)."""
    lo, hi = t_range
    if not (math.isfinite(lo) and math.isfinite(hi) and 0 < lo < hi <= site.t_max):
        raise ArchdemInputError(f"matching periods must satisfy 0 < T_lo < T_hi <= {site.t_max:g} s, got {lo:g}-{hi:g} s")
    w = significant_window(motion)
    T = np.geomspace(lo, hi, MATCH_PERIODS)
    Sa = response_spectrum(w, T)
    if not np.all(Sa > 0):
        raise ArchdemInputError(f"{motion.name or 'record'}: zero response over the matching periods")
    Se = np.asarray(site.Se(T), float)
    k = float(np.exp(np.mean(np.log(Se) - np.log(Sa))))
    return MatchedRecord(w.scaled(k), k, T, Sa, Se)


def parse_im(text: str) -> tuple[str, float | None]:
    """An intensity measure: ``pga`` [m/s^2], ``pgv`` [m/s] or ``sa:T`` (5 %-damped pseudo-spectral
    acceleration at period T [s], m/s^2)."""
    t = str(text).strip().lower()
    if t in ("pga", "pgv"):
        return t, None
    if t.startswith("sa:"):
        try:
            T = float(t[3:])
        except ValueError:
            T = math.nan
        if not (math.isfinite(T) and 0.01 <= T <= 10):
            raise ArchdemInputError(f"--im sa:T needs a period T in [0.01, 10] s, got {text!r}")
        return "sa", T
    raise ArchdemInputError(f"--im must be pga, pgv or sa:T (T in s), got {text!r}")


def intensity_measure(motion: SampledMotion, im: tuple[str, float | None]) -> float:
    """The value of ``im`` (:func:`parse_im`) for ``motion`` (with its scale)."""
    kind, T = im
    a = np.asarray(motion.values, float) * motion.scale
    if kind == "pga":
        return float(np.max(np.abs(a)))
    if kind == "pgv":
        v = np.concatenate([[0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * motion.dt)])
        return float(np.max(np.abs(v)))
    return float(response_spectrum(motion, [T])[0])
