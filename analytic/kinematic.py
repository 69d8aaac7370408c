"""Linear kinematic analysis of a local mechanism, as the codes do it for masonry
(docs/physics/assessment.md#2-linear-kinematic-analysis).

From a one-degree-of-freedom mechanism (:class:`analytic.mechanism.Mechanism`: a four-bar of an
arch, on piers or not, a rocking block) at rest:

    alpha0 = lambda                                   (the collapse multiplier)
    M*     = (sum m_i dx_i)^2 / sum m_i dx_i^2        (participating mass, dx_i the horizontal
                                                       virtual displacements of the bodies' centroids)
    e*     = M* / sum m_i                             (participating mass fraction)
    a0*    = alpha0 g / (e* FC)                       (spectral activation acceleration)

with the confidence factor ``FC`` of the knowledge level. The check of a mechanism at ground level
(the life-safety limit state) is ``a0* >= ag S / q`` with the behaviour factor ``q = 2``; its
capacity as a peak ground acceleration is ``q a0*`` and the safety index is capacity / demand.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from specimens.constants import G
from specimens.errors import ArchdemInputError

#: Behaviour factor of the linear kinematic check of unreinforced masonry mechanisms.
Q_MASONRY = 2.0
#: Confidence factors of the knowledge levels LC1, LC2, LC3.
CONFIDENCE_FACTORS = {"LC1": 1.35, "LC2": 1.2, "LC3": 1.0}
#: Accepted ranges of the confidence and behaviour factors (beyond them a typo, not a judgement).
FC_RANGE, Q_RANGE = (1.0, 3.0), (1.0, 10.0)


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

    def ground_check(self, pga: float, q: float = Q_MASONRY) -> dict:
        """The check at ground level against a site peak ground acceleration ``pga = ag S`` [m/s^2]:
        ``capacity_pga = q a0*`` [m/s^2], ``demand_pga``, ``safety_index`` = capacity / demand, ``verified``."""
        if not (math.isfinite(pga) and pga > 0):
            raise ArchdemInputError(f"site peak ground acceleration must be a positive number, got {pga!r}")
        if not (math.isfinite(q) and Q_RANGE[0] <= q <= Q_RANGE[1]):
            raise ArchdemInputError(f"behaviour factor q must be a number from {Q_RANGE[0]:g} to {Q_RANGE[1]:g}, got {q!r}")
        cap = q * self.a0_star
        return {"q": q, "capacity_pga": cap, "demand_pga": pga, "safety_index": cap / pga, "verified": cap >= pga}

    def describe(self) -> dict:
        return {"alpha0": self.alpha0, "M_star": self.M_star, "e_star": self.e_star, "a0_star": self.a0_star,
                "FC": self.FC, "mass": self.mass}


def linear_kinematic(mech, FC: float = CONFIDENCE_FACTORS["LC1"]) -> LinearKinematic:
    """The linear kinematic analysis of ``mech`` (module doc) at confidence factor ``FC`` >= 1."""
    if not (isinstance(FC, (int, float)) and math.isfinite(FC) and FC_RANGE[0] <= FC <= FC_RANGE[1]):
        raise ArchdemInputError(f"confidence factor FC must be a number from {FC_RANGE[0]:g} to {FC_RANGE[1]:g}, "
                                f"got {FC!r}")
    m = np.asarray(mech.masses, dtype=float)
    dx = mech.velocity_map(0.0)[:, 0]
    den = float(np.sum(m * dx * dx))
    if not den > 0:
        raise ArchdemInputError("the mechanism moves no mass horizontally: no participating mass")
    M_star = float(np.sum(m * dx)) ** 2 / den
    e_star = M_star / float(m.sum())
    alpha0 = float(mech.lam)
    return LinearKinematic(alpha0, M_star, e_star, alpha0 * G / (e_star * FC), float(FC), float(m.sum()))
