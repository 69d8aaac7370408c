"""Elastic response spectra of the seismic codes: the demand of a code-based assessment
(docs/physics/assessment.md#1-elastic-response-spectra).

Both codes share one shape (horizontal component, damping ratio ``xi`` in %):

    0  <= T < TB :  Se = ag S [1 + (T / TB)(eta F0 - 1)]
    TB <= T < TC :  Se = ag S eta F0
    TC <= T < TD :  Se = ag S eta F0 TC / T
    TD <= T      :  Se = ag S eta F0 TC TD / T^2
    eta = max(0.55, sqrt(10 / (5 + xi))),   SDe(T) = Se(T) (T / 2 pi)^2

* **NTC 2018 §3.2.3.2** (:func:`ntc2018`): site parameters ``ag``, ``F0``, ``Tc*``; soil category A-E
  gives ``S_S`` and ``C_C``, topography T1-T4 gives ``S_T``; ``S = S_S S_T``, ``TC = C_C Tc*``,
  ``TB = TC / 3``, ``TD = 4 ag/g + 1.6 s``.
* **EN 1998-1 §3.2.2.2** (:func:`ec8`): ``F0 = 2.5``; spectrum type 1 or 2 and ground type A-E give
  ``S``, ``TB``, ``TC``, ``TD`` (the recommended values of its Tables 3.2 and 3.3).

The displacement spectrum ``Se (T / 2 pi)^2`` is that of the codes up to ``TE`` (the corner beyond
which they bend it towards the ground displacement); longer periods are refused.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from specimens.constants import G
from specimens.errors import ArchdemInputError

#: NTC 2018 Tab. 3.2.IV: soil category -> (S_S(F0 ag/g) as (a, b, lo, hi): clip(a - b F0 ag/g, lo, hi), C_C as (c, p): c Tc*^p).
NTC_SOIL = {
    "A": ((1.00, 0.00, 1.00, 1.00), (1.00, 0.00)),
    "B": ((1.40, 0.40, 1.00, 1.20), (1.10, -0.20)),
    "C": ((1.70, 0.60, 1.00, 1.50), (1.05, -0.33)),
    "D": ((2.40, 1.50, 0.90, 1.80), (1.25, -0.50)),
    "E": ((2.00, 1.10, 1.00, 1.60), (1.15, -0.40)),
}
#: NTC 2018 Tab. 3.2.V/VI: topographic amplification S_T.
NTC_TOPOGRAPHY = {"T1": 1.0, "T2": 1.2, "T3": 1.2, "T4": 1.4}
#: EN 1998-1 Tables 3.2 (type 1) and 3.3 (type 2): ground type -> (S, TB, TC, TD) [-, s, s, s].
EC8_GROUND = {
    1: {"A": (1.00, 0.15, 0.40, 2.0), "B": (1.20, 0.15, 0.50, 2.0), "C": (1.15, 0.20, 0.60, 2.0),
        "D": (1.35, 0.20, 0.80, 2.0), "E": (1.40, 0.15, 0.50, 2.0)},
    2: {"A": (1.00, 0.05, 0.25, 1.2), "B": (1.35, 0.05, 0.25, 1.2), "C": (1.50, 0.10, 0.25, 1.2),
        "D": (1.80, 0.10, 0.30, 1.2), "E": (1.60, 0.05, 0.25, 1.2)},
}
#: Corner period TE [s] up to which the displacement spectrum is Se (T / 2 pi)^2 (ground A; B; C-E).
TE = {"A": 4.5, "B": 5.0, "C": 6.0, "D": 6.0, "E": 6.0}
#: EN 1998-1 gives its elastic spectrum up to 4 s.
EC8_T_MAX = 4.0


def damping_correction(xi: float) -> float:
    """``eta = max(0.55, sqrt(10 / (5 + xi)))`` for a viscous damping ratio ``xi`` [%]."""
    if not (isinstance(xi, (int, float)) and math.isfinite(xi) and 0 <= xi <= 100):
        raise ArchdemInputError(f"damping ratio must be a percentage from 0 to 100, got {xi!r}")
    return max(0.55, math.sqrt(10.0 / (5.0 + xi)))


@dataclass(frozen=True)
class ElasticSpectrum:
    """An elastic spectrum of the codes' shape: ``ag`` [m/s^2] on rock, ``S`` soil (and topography)
    factor, ``eta`` damping correction, ``F0`` plateau amplification, corner periods ``TB``, ``TC``,
    ``TD`` and the longest period ``t_max`` [s] of its validity; ``params``: what it was built from."""

    name: str
    ag: float
    S: float
    eta: float
    F0: float
    TB: float
    TC: float
    TD: float
    t_max: float
    params: dict = field(default_factory=dict)

    @property
    def pga(self) -> float:
        """Peak ground acceleration at the site ``ag S`` [m/s^2] (``Se(0)``)."""
        return self.ag * self.S

    def _periods(self, T) -> np.ndarray:
        T = np.asarray(T, dtype=float)
        if not np.all(np.isfinite(T)) or np.any(T < 0) or np.any(T > self.t_max + 1e-12):
            raise ArchdemInputError(f"{self.name}: periods must be in [0, {self.t_max:g}] s")
        return T

    def Se(self, T) -> np.ndarray:
        """Elastic spectral acceleration [m/s^2] at periods ``T`` [s]."""
        T = self._periods(T)
        top = self.ag * self.S * self.eta * self.F0
        rise = self.ag * self.S * (1.0 + T / self.TB * (self.eta * self.F0 - 1.0))
        Tl = np.maximum(T, self.TC)  # the branches beyond TC, kept finite where they are not used
        return np.where(T < self.TB, rise, np.where(T < self.TC, top, np.where(
            T < self.TD, top * self.TC / Tl, top * self.TC * self.TD / Tl ** 2)))

    def SDe(self, T) -> np.ndarray:
        """Elastic spectral displacement [m] at periods ``T`` [s]: ``Se (T / 2 pi)^2``."""
        T = self._periods(T)
        return self.Se(T) * (T / (2.0 * math.pi)) ** 2

    def describe(self) -> dict:
        return {"code": self.name, **self.params, "ag": self.ag, "S": self.S, "eta": self.eta, "F0": self.F0,
                "TB": self.TB, "TC": self.TC, "TD": self.TD, "t_max": self.t_max}


def _category(value: str, table, what: str) -> str:
    key = str(value).strip().upper()
    if key not in table:
        raise ArchdemInputError(f"{what} must be one of {', '.join(table)}, got {value!r}")
    return key


def _positive(name: str, v: float, hi: float) -> float:
    if not (isinstance(v, (int, float)) and math.isfinite(v) and 0 < v <= hi):
        raise ArchdemInputError(f"{name} must be in (0, {hi:g}], got {v!r}")
    return float(v)


def ntc2018(ag: float, F0: float, Tc_star: float, soil: str = "A", topography: str = "T1",
            damping: float = 5.0) -> ElasticSpectrum:
    """NTC 2018 §3.2.3.2.1 elastic spectrum: ``ag`` [m/s^2] on rock, ``F0`` [-], ``Tc_star`` [s] of the
    site and return period; ``soil`` A-E, ``topography`` T1-T4, ``damping`` [%]."""
    _positive("ag [m/s^2]", ag, 3 * G)
    _positive("F0", F0, 5.0)
    _positive("Tc* [s]", Tc_star, 2.0)
    soil = _category(soil, NTC_SOIL, "soil category")
    topo = _category(topography, NTC_TOPOGRAPHY, "topographic category")
    (a, b, lo, hi), (c, p) = NTC_SOIL[soil]
    S_S = min(hi, max(lo, a - b * F0 * ag / G))
    C_C = c * Tc_star ** p
    TC = C_C * Tc_star
    params = {"F0": F0, "Tc_star": Tc_star, "soil": soil, "topography": topo, "damping": damping,
              "S_S": S_S, "S_T": NTC_TOPOGRAPHY[topo], "C_C": C_C}
    return ElasticSpectrum("NTC 2018", float(ag), S_S * NTC_TOPOGRAPHY[topo], damping_correction(damping), float(F0),
                           TC / 3.0, TC, 4.0 * ag / G + 1.6, TE[soil], params)


def ec8(ag: float, ground: str = "A", spectrum_type: int = 1, damping: float = 5.0) -> ElasticSpectrum:
    """EN 1998-1 §3.2.2.2 elastic spectrum: design ground acceleration on rock ``ag`` [m/s^2],
    ``ground`` type A-E, ``spectrum_type`` 1 (large earthquakes) or 2 (moderate), ``damping`` [%]."""
    _positive("ag [m/s^2]", ag, 3 * G)
    if spectrum_type not in EC8_GROUND:
        raise ArchdemInputError(f"EC8 spectrum type must be 1 or 2, got {spectrum_type!r}")
    ground = _category(ground, EC8_GROUND[spectrum_type], "ground type")
    S, TB, TC, TD = EC8_GROUND[spectrum_type][ground]
    params = {"ground": ground, "type": spectrum_type, "damping": damping}
    return ElasticSpectrum("EN 1998-1", float(ag), S, damping_correction(damping), 2.5, TB, TC, TD,
                           min(EC8_T_MAX, TE[ground]), params)
