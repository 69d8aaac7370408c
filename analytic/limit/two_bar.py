"""Two-bar rocking-sliding model of a thick, sharp arch (docs/physics/limit-analysis.md#8-the-two-bar-sliding-model).

Two rigid halves (the left and right halves of the continuous ring, split at the symmetry
axis, each with its half of the keystone zone), each hinged at a springing corner on the base
and joined at the crown by a slider whose sliding plane is vertical (normal to the ground):
relative motion at the slider is vertical, horizontal displacement continuous. The slider
point is ``S = (Re cos(pi - g_a) + e, Re sin(pi - g_a))``, ``g_a = pi/2 - asin(e/Ri)``
(the extrados end of the left apex cut: g_a = psi_i; docs/physics/limit-analysis.md#8-the-two-bar-sliding-model).

For a horizontal load along +x both halves rotate clockwise by the same angle (horizontal
continuity at S with both hinges on y = 0); admissibility places the left hinge at the
intrados springing corner ``A`` and the right hinge at the extrados springing corner ``B``
(both base joints then open on the other face). Frictionless slider (virtual work):

    lambda_0 = sum m_j dy_j / sum m_j dx_j   (= t / (2 y_G) for the symmetric halves)

Coulomb friction ``mu`` on the slider (associative, normal force = horizontal thrust ``H`` from
the equilibrium of the two bars, friction ``mu H`` opposing the relative vertical slip) gives
``lambda_slide(mu)`` from the two moment equations about ``A`` and ``B``.
``mu_star``: the friction coefficient at which ``lambda_slide`` equals a rocking multiplier
(by default the continuous-profile four-hinge multiplier of :mod:`analytic.limit.limit_continuous`):
below it the sliding mechanism governs.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from analytic.limit.limit_continuous import continuous_collapse
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch, ring_half_boundary
from specimens.sections import mirror_edges, region_properties


@dataclass(frozen=True)
class TwoBarGeometry:
    """Two-bar linkage: hinges ``A`` (left, intrados springing), ``B`` (right, extrados springing),
    slider point ``S`` [m]; each bar's mass [kg], centroid [m] and centroidal inertia [kg m^2]."""

    A: np.ndarray
    B: np.ndarray
    S: np.ndarray
    mass_left: float
    mass_right: float
    centroid_left: np.ndarray
    centroid_right: np.ndarray
    inertia_left: float
    inertia_right: float


def two_bar_geometry(arch: PointedArch, density: float = 500.0) -> TwoBarGeometry:
    """The two-bar linkage of ``arch`` (halves split at the axis)."""
    if not (math.isfinite(density) and density > 0):
        raise ArchdemInputError(f"density must be a positive number [kg/m^3], got {density!r}")
    right = region_properties(ring_half_boundary(arch, 0.0, None))
    left = region_properties(mirror_edges(ring_half_boundary(arch, 0.0, None)))
    rho_w = density * arch.width
    g_a = math.pi / 2 - math.asin(arch.e / arch.Ri)
    S = np.array([arch.Re * math.cos(math.pi - g_a) + arch.e, arch.Re * math.sin(math.pi - g_a)])
    return TwoBarGeometry(
        A=np.array([-(arch.Rc - arch.t / 2), 0.0]),
        B=np.array([arch.Rc + arch.t / 2, 0.0]),
        S=S,
        mass_left=rho_w * left.area, mass_right=rho_w * right.area,
        centroid_left=left.centroid, centroid_right=right.centroid,
        inertia_left=rho_w * left.polar, inertia_right=rho_w * right.polar,
    )


def _system(geo: TwoBarGeometry) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Moment equations about A (left bar) and B (right bar), per unit g, in (H, F, lambda).

    Forces on the left bar at S from the right bar: (-H, +F) (H > 0 compression, F = mu H
    upward friction); on the right bar the opposite. Rows: a_H H + a_F F + a_l lambda = r.
    """
    A, B, S = geo.A, geo.B, geo.S
    mL, mR, GL, GR = geo.mass_left, geo.mass_right, geo.centroid_left, geo.centroid_right
    # left: (S-A) x (-H, F) + (GL-A) x (lam mL, -mL) = 0 ; (g factored out of H, F)
    rowL = np.array([S[1] - A[1], S[0] - A[0], -mL * (GL[1] - A[1])])
    rhsL = mL * (GL[0] - A[0])
    # right: (S-B) x (H, -F) + (GR-B) x (lam mR, -mR) = 0
    rowR = np.array([-(S[1] - B[1]), -(S[0] - B[0]), -mR * (GR[1] - B[1])])
    rhsR = mR * (GR[0] - B[0])
    return rowL, rowR, np.array([rhsL, rhsR])


def lambda_slide(arch: PointedArch, mu: float, density: float = 500.0) -> float:
    """Multiplier of the two-bar mechanism with Coulomb friction ``mu`` at the slider."""
    if not (mu >= 0 and math.isfinite(mu)):
        raise ArchdemInputError(f"slider friction mu must be a finite number >= 0, got {mu!r}")
    rowL, rowR, rhs = _system(two_bar_geometry(arch, density))
    # unknowns H, lambda with F = mu H
    M = np.array([[rowL[0] + mu * rowL[1], rowL[2]], [rowR[0] + mu * rowR[1], rowR[2]]])
    H, lam = np.linalg.solve(M, rhs)
    return float(lam)


def lambda_two_bar(arch: PointedArch, density: float = 500.0) -> float:
    """Multiplier of the frictionless two-bar model (virtual work; independent of density)."""
    geo = two_bar_geometry(arch, density)
    # clockwise rotation theta = 1 of both bars about A and B
    dx = geo.mass_left * (geo.centroid_left[1] - geo.A[1]) + geo.mass_right * (geo.centroid_right[1] - geo.B[1])
    dy = -geo.mass_left * (geo.centroid_left[0] - geo.A[0]) - geo.mass_right * (geo.centroid_right[0] - geo.B[0])
    return float(dy / dx)


def slider_thrust(arch: PointedArch, mu: float, density: float = 500.0) -> float:
    """Horizontal thrust H [N] at the slider at the sliding limit with friction ``mu``."""
    rowL, rowR, rhs = _system(two_bar_geometry(arch, density))
    M = np.array([[rowL[0] + mu * rowL[1], rowL[2]], [rowR[0] + mu * rowR[1], rowR[2]]])
    H, _ = np.linalg.solve(M, rhs)
    return float(H * G)


def mu_star(arch: PointedArch, lam_rock: float | None = None, density: float = 500.0) -> float:
    """Rocking/sliding friction threshold: ``lambda_slide(mu_star) = lam_rock``.

    ``lam_rock`` defaults to the continuous-profile four-hinge multiplier
    (:func:`analytic.limit.limit_continuous.continuous_collapse`). Closed form: with ``lambda`` fixed
    the two moment equations are linear in ``H`` and ``F = mu H``; ``mu_star = F / H``.
    Returns ``0.0`` if the frictionless slider already reaches ``lam_rock`` and ``inf`` if no
    friction coefficient does.
    """
    if lam_rock is None:
        lam_rock = continuous_collapse(arch, density=density).lam
    rowL, rowR, rhs = _system(two_bar_geometry(arch, density))
    M = np.array([[rowL[0], rowL[1]], [rowR[0], rowR[1]]])
    b = rhs - lam_rock * np.array([rowL[2], rowR[2]])
    try:
        H, F = np.linalg.solve(M, b)
    except np.linalg.LinAlgError:
        return math.inf
    if H <= 0:
        return math.inf
    return max(0.0, float(F / H))
