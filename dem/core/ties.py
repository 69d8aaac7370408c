"""Steel ties in the DEM: an elastic-perfectly-plastic tension member between two bodies
(docs/physics/assessment.md#8-tie-rods).

A tie anchored at ``p_a`` on body ``a`` and ``p_b`` on body ``b`` (arch frame, at rest) pulls the two
anchors together with ``F = P + k (L - L0 - e_p)`` clipped to ``[0, F_y]``: ``k = E A / L0`` its axial
stiffness, ``P`` its prestress, ``e_p`` the plastic elongation it has taken (grown whenever ``F``
would exceed the yield force ``F_y``); it never pushes. The engines ask for the forces before each
of their steps and apply them at the anchors' current positions.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Young's modulus of the tie's steel [Pa].
STEEL_MODULUS = 200e9


@dataclass(frozen=True)
class TieSpec:
    """A tie between bodies ``a`` and ``b`` of a model: anchors ``p_a``, ``p_b`` (3,) [m] at rest, axial
    ``stiffness`` [N/m], ``yield_force`` [N], ``prestress`` [N]."""

    a: int
    b: int
    p_a: np.ndarray
    p_b: np.ndarray
    stiffness: float
    yield_force: float
    prestress: float = 0.0

    @property
    def rest_length(self) -> float:
        return float(np.linalg.norm(np.asarray(self.p_b, float) - np.asarray(self.p_a, float)))


def tie_spec(link, area: float, prestress: float = 0.0, modulus: float = STEEL_MODULUS) -> TieSpec:
    """The DEM tie of an :class:`analytic.limit.ties.TieLink` (anchors in the plane z = 0) of cross-section
    ``area`` [m^2]: stiffness ``E A / L0``."""
    pa = np.array([float(link.p_a[0]), float(link.p_a[1]), 0.0])
    pb = np.array([float(link.p_b[0]), float(link.p_b[1]), 0.0])
    L0 = float(np.linalg.norm(pb - pa))
    return TieSpec(int(link.a), int(link.b), pa, pb, modulus * area / L0, float(link.force), float(prestress))


class TieForces:
    """The ties of a model as the engines step them: their plastic elongations and current forces."""

    def __init__(self, ties, centroids: np.ndarray) -> None:
        self.ties = tuple(ties)
        self.c0 = np.asarray(centroids, float)
        self.plastic = np.zeros(len(self.ties))
        self.force = np.array([t.prestress for t in self.ties], float)

    def anchors(self, pos: np.ndarray, R: np.ndarray, k: int) -> tuple[np.ndarray, np.ndarray]:
        """World positions of tie ``k``'s anchors for body centroids ``pos`` (n, 3) and rotations ``R`` (n, 3, 3)."""
        t = self.ties[k]
        pa = pos[t.a] + R[t.a] @ (np.asarray(t.p_a, float) - self.c0[t.a])
        pb = pos[t.b] + R[t.b] @ (np.asarray(t.p_b, float) - self.c0[t.b])
        return pa, pb

    def update(self, pos: np.ndarray, R: np.ndarray) -> list[tuple[int, np.ndarray, np.ndarray]]:
        """The forces for the next step: ``(body, world point, force (3,) [N])``, two per tie."""
        out = []
        for k, t in enumerate(self.ties):
            pa, pb = self.anchors(pos, R, k)
            d = pb - pa
            L = float(np.linalg.norm(d))
            F = t.prestress + t.stiffness * (L - t.rest_length - self.plastic[k])
            if F > t.yield_force:
                self.plastic[k] += (F - t.yield_force) / t.stiffness
                F = t.yield_force
            F = max(F, 0.0)
            self.force[k] = F
            u = d / L
            out += [(t.a, pa, F * u), (t.b, pb, -F * u)]
        return out
