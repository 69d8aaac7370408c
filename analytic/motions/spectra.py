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
import os
from dataclasses import dataclass, field, replace

import numpy as np

from specimens.constants import G
from foundation.errors import ArchdemInputError

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


class _SpectrumBase:
    """What every spectrum shares: the period range and the displacement spectrum."""

    name: str
    t_max: float

    def _periods(self, T) -> np.ndarray:
        T = np.asarray(T, dtype=float)
        if not np.all(np.isfinite(T)) or np.any(T < 0) or np.any(T > self.t_max + 1e-12):
            raise ArchdemInputError(f"{self.name}: periods must be in [0, {self.t_max:g}] s")
        return T

    def Se(self, T) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def SDe(self, T) -> np.ndarray:
        """Elastic spectral displacement [m] at periods ``T`` [s]: ``Se (T / 2 pi)^2``."""
        T = self._periods(T)
        return self.Se(T) * (T / (2.0 * math.pi)) ** 2


@dataclass(frozen=True)
class ElasticSpectrum(_SpectrumBase):
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

    def Se(self, T) -> np.ndarray:
        """Elastic spectral acceleration [m/s^2] at periods ``T`` [s]."""
        T = self._periods(T)
        top = self.ag * self.S * self.eta * self.F0
        rise = self.ag * self.S * (1.0 + T / self.TB * (self.eta * self.F0 - 1.0))
        Tl = np.maximum(T, self.TC)  # the branches beyond TC, kept finite where they are not used
        return np.where(T < self.TB, rise, np.where(T < self.TC, top, np.where(
            T < self.TD, top * self.TC / Tl, top * self.TC * self.TD / Tl ** 2)))

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


def rebuild(site, ag: float | None = None, damping: float | None = None):
    """The same site's spectrum at another ``ag`` [m/s^2] (the return period's hazard scaled) and/or
    another ``damping`` [%]: the code's spectrum rebuilt (its soil factor and ``TD`` follow ``ag``),
    a user's spectrum scaled."""
    if isinstance(site, TabulatedSpectrum):
        return site.rebuilt(ag, damping)
    p = site.params
    ag = site.ag if ag is None else ag
    damping = p["damping"] if damping is None else damping
    if site.name == "NTC 2018":
        return ntc2018(ag, p["F0"], p["Tc_star"], p["soil"], p["topography"], damping)
    return ec8(ag, p["ground"], p["type"], damping)


#: Longest period [s] and most rows of a user's spectrum file.
USER_T_MAX, USER_MAX_ROWS = 10.0, 100_000


@dataclass(frozen=True)
class TabulatedSpectrum(_SpectrumBase):
    """A user's elastic acceleration spectrum at 5 % damping: periods ``T`` [s] from 0, ``Se`` [m/s^2];
    ``scale`` multiplies it (a stripe of intensity), ``eta`` corrects it for another damping (the codes'
    factor, applied for T > 0; the peak ground acceleration ``Se(0)`` is not damped)."""

    name: str
    T: np.ndarray
    Se0: np.ndarray
    scale: float = 1.0
    eta: float = 1.0
    params: dict = field(default_factory=dict)

    @property
    def ag(self) -> float:
        """Peak ground acceleration of the scaled spectrum [m/s^2] (a user's spectrum has ``S = 1``)."""
        return float(self.Se0[0]) * self.scale

    S = 1.0

    @property
    def pga(self) -> float:
        return self.ag

    @property
    def t_max(self) -> float:  # type: ignore[override]
        return float(self.T[-1])

    def Se(self, T) -> np.ndarray:
        T = self._periods(T)
        return self.scale * np.interp(T, self.T, self.Se0) * np.where(T > 0, self.eta, 1.0)

    def rebuilt(self, ag: float | None = None, damping: float | None = None) -> "TabulatedSpectrum":
        scale = self.scale if ag is None else ag / float(self.Se0[0])
        eta = self.eta if damping is None else damping_correction(damping)
        params = {**self.params, "damping": self.params.get("damping", 5.0) if damping is None else damping}
        return replace(self, scale=scale, eta=eta, params=params)

    def describe(self) -> dict:
        return {"code": "user spectrum", **self.params, "pga": self.pga, "scale": self.scale, "eta": self.eta,
                "t_max": self.t_max, "rows": int(len(self.T))}


def read_spectrum(path: str, damping: float = 5.0) -> TabulatedSpectrum:
    """A user's 5 %-damped elastic spectrum from a text file: two columns, period [s] and spectral
    acceleration [g], separated by spaces, tabs, commas or semicolons; ``#`` starts a comment; periods
    start at 0 and increase, up to :data:`USER_T_MAX`."""
    name = os.path.basename(str(path))
    try:
        with open(path, encoding="utf-8") as fh:
            text = fh.read(10_000_000)
    except FileNotFoundError:
        raise ArchdemInputError(f"spectrum file {path}: no such file") from None
    except IsADirectoryError:
        raise ArchdemInputError(f"spectrum file {path}: is a directory") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ArchdemInputError(f"spectrum file {path}: cannot be read as text ({type(exc).__name__})") from None
    rows = []
    for k, line in enumerate(text.splitlines(), 1):
        body = line.split("#", 1)[0].replace(",", " ").replace(";", " ").split()
        if not body:
            continue
        if len(body) != 2:
            raise ArchdemInputError(f"spectrum file {name}, line {k}: expected two numbers (period [s], Se [g]), "
                                    f"got {len(body)} fields")
        try:
            T, Se = float(body[0]), float(body[1])
        except ValueError:
            raise ArchdemInputError(f"spectrum file {name}, line {k}: not numbers: {line.strip()[:60]!r}") from None
        if not (math.isfinite(T) and math.isfinite(Se) and Se > 0 and Se <= 20):
            raise ArchdemInputError(f"spectrum file {name}, line {k}: Se must be in (0, 20] g at a finite period, "
                                    f"got {line.strip()[:60]!r}")
        if rows and T <= rows[-1][0]:
            raise ArchdemInputError(f"spectrum file {name}, line {k}: periods must increase, got {T:g} s after "
                                    f"{rows[-1][0]:g} s")
        rows.append((T, Se))
        if len(rows) > USER_MAX_ROWS:
            raise ArchdemInputError(f"spectrum file {name}: more than {USER_MAX_ROWS} rows")
    if len(rows) < 2:
        raise ArchdemInputError(f"spectrum file {name}: needs at least two rows (period [s], Se [g])")
    arr = np.array(rows)
    if arr[0, 0] != 0.0:
        raise ArchdemInputError(f"spectrum file {name}: the first period must be 0 s (Se(0) is the peak ground "
                                f"acceleration), got {arr[0, 0]:g} s")
    if arr[-1, 0] > USER_T_MAX:
        raise ArchdemInputError(f"spectrum file {name}: periods up to {USER_T_MAX:g} s, got {arr[-1, 0]:g} s")
    return TabulatedSpectrum(name, arr[:, 0], arr[:, 1] * G, 1.0, damping_correction(damping),
                             {"file": name, "damping": damping})


def floor_spectrum(site, T, damping: float, z_ratio: float, T1: float, floors: int,
                   damping1: float = 5.0) -> np.ndarray:
    """Elastic acceleration spectrum [m/s^2] at a height ``z_ratio = z / H`` of a building, from its
    first mode only (period ``T1`` [s], damping ``damping1`` [%], linear mode shape ``psi = z / H``,
    participation ``gamma = 3 n / (2 n + 1)`` for ``floors = n``), for an element of damping ``damping``
    [%] (docs/physics/assessment.md#4-mechanisms-at-a-height): the Circolare 2019 floor spectrum::

        a_Z  = Se(T1, xi1) gamma psi sqrt(1 + 0.0004 xi1^2)             floor acceleration
        A    = 1.1 xi1^-0.5 eta(xi) a_Z                                 (xi1 as a fraction)
        SeZ  = a_Z A / (a_Z + (A - a_Z)(1 - T / (a T1))^1.6)            T < a T1
             = A                                                        a T1 <= T < b T1
             = a_Z A / (a_Z + (A - a_Z)(T / (b T1) - 1)^1.2)            T >= b T1, and >= Se(T, xi)

    with ``a = 0.8``, ``b = 1.1``; never below the ground spectrum for ``T > T1``."""
    T = np.asarray(T, dtype=float)
    ground = rebuild(site, damping=damping1)
    aZ = float(ground.Se(T1)) * (3.0 * floors / (2.0 * floors + 1.0)) * z_ratio * math.sqrt(1 + 0.0004 * damping1 ** 2)
    A = 1.1 * (damping1 / 100.0) ** -0.5 * damping_correction(damping) * aZ
    a, b = 0.8, 1.1
    with np.errstate(invalid="ignore", divide="ignore"):
        rise = A / (1.0 + (A / aZ - 1.0) * np.clip(1.0 - T / (a * T1), 0, None) ** 1.6)
        fall = A / (1.0 + (A / aZ - 1.0) * np.clip(T / (b * T1) - 1.0, 0, None) ** 1.2)
    out = np.where(T < a * T1, rise, np.where(T < b * T1, A, fall))
    mech = rebuild(site, damping=damping)
    return np.where(T > T1, np.maximum(out, mech.Se(np.minimum(T, mech.t_max))), out)
