"""Kinematic analysis of a local mechanism, as the codes do it for masonry
(docs/physics/assessment.md#2-linear-kinematic-analysis and #3-non-linear-kinematic-analysis).

From a one-degree-of-freedom mechanism (:class:`analytic.rocking.mechanism.Mechanism`: a four-bar of an
arch, on piers or not, a rocking block) with horizontal virtual displacements ``dx_i`` of the
bodies' centroids at rest (along the load):

    alpha0 = lambda                                   (the collapse multiplier)
    M*     = (sum m_i dx_i)^2 / sum m_i dx_i^2        (participating mass)
    e*     = M* / sum m_i                             (participating mass fraction)
    a0*    = alpha0 g / (e* FC)                       (spectral activation acceleration)

with the confidence factor ``FC`` of the knowledge level. The **linear** check (life safety, behaviour
factor ``q = 2``): ``q a0* >= ag S`` (at a height ``q a0* >= a_Z``, the floor's peak acceleration); the
safety index is ``q a0* / (ag S)``, and ``capacity_ag`` the hazard's ``ag`` at which the two are equal.

The **non-linear** analysis follows the mechanism to large rotations: ``alpha(phi)`` is the multiplier
that holds it displaced (virtual work in the displaced configuration), the control point is the
bodies' mass centroid (``d_C``) and the equivalent oscillator has ``d* = d_C / e*``,
``a* = alpha g / (e* FC)``. ``d0*`` is where ``a*`` vanishes; the ultimate displacements are
``0.4 d0*`` (SLV) and ``0.6 d0*`` (SLC), their periods ``T = c pi sqrt(d / a(d))`` (c = 1.68, 1.56),
and the demand is the largest spectral displacement up to that period at the mechanism's damping
(8 %, 10 %). The displacement check is ``d_u* >= demand``, its safety index their ratio.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from analytic.motions.spectra import TabulatedSpectrum, floor_spectrum, rebuild
from specimens.constants import G
from foundation.errors import ArchdemInputError

#: Behaviour factor of the linear kinematic check of unreinforced masonry mechanisms.
Q_MASONRY = 2.0
#: Confidence factors of the knowledge levels LC1, LC2, LC3.
CONFIDENCE_FACTORS = {"LC1": 1.35, "LC2": 1.2, "LC3": 1.0}
#: Accepted ranges of the confidence and behaviour factors (beyond them a typo, not a judgement).
FC_RANGE, Q_RANGE = (1.0, 3.0), (1.0, 10.0)
#: Ultimate displacement of the equivalent oscillator as a fraction of d0*, per limit state.
ULTIMATE_FRACTION = {"SLV": 0.4, "SLC": 0.6}
#: Coefficient c of the limit state's period T = c pi sqrt(d / a(d)).
PERIOD_COEFFICIENT = {"SLV": 1.68, "SLC": 1.56}
#: Equivalent viscous damping of the rocking mechanism at each limit state [%].
MECHANISM_DAMPING = {"SLV": 8.0, "SLC": 10.0}
#: Points of the capacity curve between rest and d0*.
CURVE_POINTS = 201
#: Periods sampled per second of the demand's search for the largest spectral displacement.
DEMAND_SAMPLES_PER_S = 400


def _factor(name: str, value, lo_hi: tuple[float, float]) -> float:
    lo, hi = lo_hi
    if isinstance(value, bool) or not (isinstance(value, (int, float)) and math.isfinite(value) and lo <= value <= hi):
        raise ArchdemInputError(f"{name} must be a number from {lo:g} to {hi:g}, got {value!r}")
    return float(value)


@dataclass(frozen=True)
class Height:
    """A mechanism at a height of a building: ``z_ratio`` = z / H (0 < z/H <= 1), the building's
    first-mode period ``T1`` [s], number of ``floors`` and first-mode ``damping1`` [%]."""

    z_ratio: float
    T1: float
    floors: int
    damping1: float = 5.0

    def __post_init__(self) -> None:
        if not (isinstance(self.z_ratio, (int, float)) and math.isfinite(self.z_ratio) and 0 < self.z_ratio <= 1):
            raise ArchdemInputError(f"height ratio z/H must be in (0, 1], got {self.z_ratio!r}")
        if not (isinstance(self.T1, (int, float)) and math.isfinite(self.T1) and 0 < self.T1 <= 4):
            raise ArchdemInputError(f"building period T1 must be in (0, 4] s, got {self.T1!r}")
        if isinstance(self.floors, bool) or not isinstance(self.floors, int) or not 1 <= self.floors <= 100:
            raise ArchdemInputError(f"number of floors must be a whole number from 1 to 100, got {self.floors!r}")
        _factor("building damping [%]", self.damping1, (0.5, 30.0))


def peak_acceleration(site, height: Height | None) -> float:
    """Peak acceleration [m/s^2] where the mechanism stands: the site's ``ag S`` at ground level, the
    floor's ``a_Z`` at a height (:func:`analytic.motions.spectra.floor_spectrum` at T = 0)."""
    if height is None:
        return float(site.pga)

    return float(floor_spectrum(site, 0.0, 5.0, height.z_ratio, height.T1, height.floors, height.damping1))


def capacity_ag(site, demand: Callable[[object], float], capacity: float) -> float:
    """The ``ag`` [m/s^2] of the site's spectrum (rebuilt at that ``ag``) at which ``demand(spectrum)``
    equals ``capacity``; ``inf`` if even 3 g does not reach it."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from scipy.optimize import brentq

    if isinstance(site, TabulatedSpectrum):  # a user's spectrum scales linearly
        return site.ag * capacity / demand(site)
    f = lambda ag: demand(rebuild(site, ag=ag)) - capacity  # noqa: E731
    lo, hi = 1e-6 * G, 3.0 * G
    if f(hi) < 0:
        return math.inf
    if f(lo) > 0:
        return lo
    return float(brentq(f, lo, hi, xtol=1e-10 * G, rtol=1e-10))


def _verdict(site, ag_cap: float, demand: float, capacity: float, extra: dict) -> dict:
    """The check's dict: ``demand`` and ``capacity`` in the clause's own quantity (m/s^2 or m), the
    safety index ``capacity / demand`` and the verdict; ``capacity_ag`` [m/s^2]: the hazard's ``ag``
    at which the clause holds with equality (the spectrum rebuilt), ``capacity_pga`` its ``ag S``."""
    if math.isfinite(ag_cap):
        cap_pga = ag_cap if isinstance(site, TabulatedSpectrum) else ag_cap * rebuild(site, ag=ag_cap).S
    else:
        cap_pga = math.inf
    # the index is the ratio of the two quantities the clause compares, so it can be recomputed from them
    index = capacity / demand if demand > 0 else math.inf
    return {**extra, "demand": demand, "capacity": capacity, "capacity_ag": ag_cap, "capacity_pga": cap_pga,
            "demand_ag": site.ag, "demand_pga": site.pga, "safety_index": index, "verified": bool(capacity >= demand)}


@dataclass(frozen=True)
class LinearKinematic:
    """``alpha0`` [-], ``M_star`` [kg], ``e_star`` [-], ``a0_star`` [m/s^2] of a mechanism at
    confidence factor ``FC``; ``mass`` [kg] the mechanism's total mass."""

    alpha0: float
    M_star: float
    e_star: float
    a0_star: float
    FC: float
    mass: float

    def check(self, site, q: float = Q_MASONRY, height: Height | None = None) -> dict:
        """The linear check (life safety) as the Circolare writes it, ``q a0* >= ag S`` at ground level
        (``q a0* >= a_Z`` at a height): ``demand`` = the peak acceleration where the mechanism stands,
        ``capacity`` = ``q a0*`` [m/s^2], safety index their ratio; ``activation_ag``: the hazard's ``ag``
        that activates the mechanism (no ``q``); ``capacity_ag``: the one at which the check holds with
        equality."""
        q = _factor("behaviour factor q", q, Q_RANGE)
        peak = lambda s: peak_acceleration(s, height)  # noqa: E731
        ag_act = capacity_ag(site, peak, self.a0_star)
        return _verdict(site, capacity_ag(site, peak, q * self.a0_star), peak(site), q * self.a0_star,
                        {"kind": "linear", "limit_state": "SLV", "q": q, "activation_ag": ag_act,
                         "activation_acceleration": self.a0_star, "demand_acceleration": peak(site),
                         "where": "ground" if height is None else f"z/H = {height.z_ratio:g}"})

    def activation(self, site, height: Height | None = None, limit_state: str = "SLD") -> dict:
        """The activation check (no behaviour factor), ``a0* >= ag S`` (``a_Z`` at a height): ``demand`` =
        the peak acceleration where the mechanism stands, ``capacity`` = ``a0*`` [m/s^2] (``site`` the
        hazard of ``limit_state``: SLD for the code's damage-limitation check)."""
        peak = lambda s: peak_acceleration(s, height)  # noqa: E731
        ag_act = capacity_ag(site, peak, self.a0_star)
        return _verdict(site, ag_act, peak(site), self.a0_star,
                        {"kind": "activation", "limit_state": limit_state, "q": 1.0, "activation_ag": ag_act,
                         "activation_acceleration": self.a0_star, "demand_acceleration": peak(site),
                         "where": "ground" if height is None else f"z/H = {height.z_ratio:g}"})

    def describe(self) -> dict:
        return {"alpha0": self.alpha0, "M_star": self.M_star, "e_star": self.e_star, "a0_star": self.a0_star,
                "FC": self.FC, "mass": self.mass}


def _participation(mech) -> tuple[np.ndarray, np.ndarray, float]:
    """Masses, horizontal virtual displacements along the load (per unit rotation) and e*."""
    m = np.asarray(mech.masses, dtype=float)
    dx = -mech.direction * mech.velocity_map(0.0)[:, 0]
    den = float(np.sum(m * dx * dx))
    if not den > 0 or not float(np.sum(m * dx)) > 0:
        raise ArchdemInputError("the mechanism moves no mass along the load: no participating mass")
    return m, dx, float(np.sum(m * dx)) ** 2 / den / float(m.sum())


def virtual_displacements(mech) -> list[dict]:
    """Per body: mass ``m`` [kg], centroid virtual displacements ``dx`` (along the load), ``dy`` [m per rad of
    the first link] and rotation ``dtheta`` [-] at rest: the velocity map the codes' M* and e* are built on."""
    m = np.asarray(mech.masses, dtype=float)
    v = mech.velocity_map(0.0)
    return [{"body": k, "m": float(m[k]), "dx": float(-mech.direction * v[k, 0]), "dy": float(v[k, 1]),
             "dtheta": float(v[k, 2])} for k in range(len(m))]


def linear_kinematic(mech, FC: float = CONFIDENCE_FACTORS["LC1"], alpha0: float | None = None) -> LinearKinematic:
    """The linear kinematic analysis of ``mech`` (module doc) at confidence factor ``FC`` >= 1;
    ``alpha0``: the multiplier when other forces than gravity act (e.g. strips), else ``mech.lam``."""
    FC = _factor("confidence factor FC", FC, FC_RANGE)
    m, _, e_star = _participation(mech)
    alpha0 = float(mech.lam if alpha0 is None else alpha0)
    return LinearKinematic(alpha0, e_star * float(m.sum()), e_star, alpha0 * G / (e_star * FC), FC, float(m.sum()))


@dataclass(frozen=True)
class CapacityCurve:
    """The capacity curve of a mechanism from rest to ``d0*``: rotation ``phi`` [rad], control
    displacement ``d_C`` [m] (mass centroid of the bodies, along the load), multiplier ``alpha`` [-];
    the equivalent oscillator's ``d_star`` [m] and ``a_star`` [m/s^2]; ``d0_star`` [m] where ``a*``
    vanishes (``d0_star_from``: which curve it was taken from), ``e_star``, ``FC``."""

    phi: np.ndarray
    d_C: np.ndarray
    alpha: np.ndarray
    d_star: np.ndarray
    a_star: np.ndarray
    d0_star: float
    e_star: float
    FC: float
    d0_star_from: str = "this curve"

    @property
    def a0_star(self) -> float:
        return float(self.a_star[0])

    def a_at(self, d: float) -> float:
        """``a*`` [m/s^2] at spectral displacement ``d`` [m] (0 beyond the curve's end)."""
        return float(np.interp(d, self.d_star, self.a_star, right=0.0))

    def linear(self, d) -> np.ndarray:
        """The codes' linear approximation ``a0* (1 - d / d0*)`` [m/s^2]."""
        return self.a0_star * (1.0 - np.asarray(d, float) / self.d0_star)

    def check(self, site, limit_state: str = "SLV", height: Height | None = None) -> dict:
        """The displacement check of ``limit_state`` (module doc): ultimate displacement ``d_u`` =
        fraction of ``d0*``, period ``T``, demand = largest spectral displacement up to ``T`` at the
        mechanism's damping (at a height: of the floor spectrum); capacity ``ag`` by rebuilding the
        site's spectrum at the ``ag`` whose demand equals ``d_u``."""
        ls = str(limit_state).upper()
        if ls not in ULTIMATE_FRACTION:
            raise ArchdemInputError(f"limit state must be SLV or SLC, got {limit_state!r}")

        d_u = ULTIMATE_FRACTION[ls] * self.d0_star
        a_u = self.a_at(d_u)
        if not a_u > 0:
            raise ArchdemInputError(f"the capacity curve holds no acceleration at the {ls} displacement")
        T = PERIOD_COEFFICIENT[ls] * math.pi * math.sqrt(d_u / a_u)
        xi = MECHANISM_DAMPING[ls]
        if T > site.t_max:
            raise ArchdemInputError(f"the mechanism's {ls} period {T:.3g} s exceeds the spectrum's range "
                                    f"({site.t_max:g} s)")
        Ts = np.append(np.linspace(0.0, T, max(2, int(DEMAND_SAMPLES_PER_S * T) + 1)), T)

        def demand(s) -> float:
            if height is None:
                Se = rebuild(s, damping=xi).Se(Ts)
            else:
                Se = floor_spectrum(s, Ts, xi, height.z_ratio, height.T1, height.floors, height.damping1)
            return float(np.max(Se * (Ts / (2 * math.pi)) ** 2))

        d_dem = demand(site)
        if height is None:
            Se_T = float(rebuild(site, damping=xi).Se(T))
        else:
            Se_T = float(floor_spectrum(site, T, xi, height.z_ratio, height.T1, height.floors, height.damping1))
        return _verdict(site, capacity_ag(site, demand, d_u), d_dem, d_u,
                        {"kind": "non-linear", "limit_state": ls, "d_u_star": d_u, "a_u_star": a_u, "period": T,
                         "damping": xi, "Se_at_period": Se_T, "demand_displacement": d_dem, "capacity_displacement": d_u,
                         "where": "ground" if height is None else f"z/H = {height.z_ratio:g}"})

    def describe(self) -> dict:
        return {"d0_star": self.d0_star, "d0_star_from": self.d0_star_from, "a0_star": self.a0_star,
                "d_SLV_star": ULTIMATE_FRACTION["SLV"] * self.d0_star,
                "d_SLC_star": ULTIMATE_FRACTION["SLC"] * self.d0_star,
                "curve": {"d_star": self.d_star.tolist(), "a_star": self.a_star.tolist()}}


def capacity_curve(mech, FC: float = CONFIDENCE_FACTORS["LC1"],
                   extra_force: Callable[[float], float] | None = None, n: int = CURVE_POINTS) -> CapacityCurve:
    """The capacity curve of ``mech`` (module doc): ``alpha(phi) = (V'(phi) + W'(phi)) / (g sum m_i
    dx_i(phi))`` with ``extra_force(phi) = W'(phi)`` [J/rad] the generalised force of other resisting
    actions (strips), from rest to where ``alpha`` vanishes. With ``extra_force``, ``d0*`` is taken from
    the curve of gravity alone (actions not shown to last until collapse do not extend it)."""
    FC = _factor("confidence factor FC", FC, FC_RANGE)
    m, dx0, e_star = _participation(mech)
    s = -mech.direction
    M = float(m.sum())
    x0 = np.array([b.x for b in mech.body_states(0.0)])

    def alpha(phi: float, extra: bool = True) -> float:
        _, _, dV, S = mech.terms(phi)
        W = extra_force(phi) if (extra and extra_force is not None) else 0.0
        return (dV + W) / (mech.g * s * S)

    def zero(extra: bool) -> float:
        if extra_force is None or not extra:
            return float(mech.phi_cr)
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from scipy.optimize import brentq

        lim = mech.geometric_limit()
        grid = np.linspace(0.0, lim, 129)
        vals = [alpha(float(p)) for p in grid]
        for k in range(1, len(grid)):
            if vals[k] <= 0:
                return float(brentq(alpha, float(grid[k - 1]), float(grid[k]), xtol=1e-12))
        return float(lim)

    phi0 = zero(True)
    if not phi0 > 0:
        raise ArchdemInputError("the mechanism is not held at rest (alpha0 <= 0): no capacity curve")
    phis = np.linspace(0.0, phi0, n)
    d_C = np.array([s * float(np.sum(m * (np.array([b.x for b in mech.body_states(float(p))]) - x0))) / M
                    for p in phis])
    al = np.array([alpha(float(p)) for p in phis])
    al[-1] = max(al[-1], 0.0)
    d_star = d_C / e_star
    if np.any(np.diff(d_star) <= 0):
        raise ArchdemInputError("the mechanism's control point does not move monotonically along the load")
    phi_g = zero(False) if extra_force is not None else phi0
    if extra_force is not None:
        dg = s * float(np.sum(m * (np.array([b.x for b in mech.body_states(phi_g)]) - x0))) / M / e_star
    else:
        dg = float(d_star[-1])
    return CapacityCurve(phis, d_C, al, d_star, al * G / (e_star * FC), float(dg), e_star, FC,
                         "gravity alone" if extra_force is not None else "this curve")
