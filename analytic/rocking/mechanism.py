"""The generic one-degree-of-freedom mechanism (docs/physics/dynamics.md#1-one-degree-of-freedom-mechanisms).

A mechanism is a set of rigid bodies (mass ``m_j`` [kg], centroidal in-plane inertia ``I_j``
[kg m^2]) whose poses follow from one generalised coordinate ``phi`` [rad] (rotation of the
first link, ``phi = 0`` at rest, ``phi > 0`` the opening motion, resisted by gravity). A
subclass supplies the **kinematic map** :meth:`Mechanism.body_states`: for every body the
centroid position and rotation and their first and second derivatives with respect to ``phi``,
in closed form (velocity and acceleration analysis; no finite differences). From it::

    M(phi)  = sum_j m_j (x_Gj'^2 + y_Gj'^2) + I_j theta_j'^2
    M'(phi) = 2 sum_j m_j (x_Gj' x_Gj'' + y_Gj' y_Gj'') + I_j theta_j' theta_j''
    V(phi)  = g sum_j m_j y_Gj,       V'(phi) = g sum_j m_j y_Gj'
    Q(phi, t) = -a_g(t) sum_j m_j x_Gj'(phi)

and the equation of motion ``M phi'' + M'/2 phi'^2 + V' = Q``. Derived constants: onset
acceleration, critical rotation ``phi_cr`` (maximum of ``V``), frequency parameter
``omega_0 = sqrt(|V''(0)| / M(0))``, the energy barrier ``V(phi_cr) - V(0)`` and the rotation
limit of the linkage. The sign of ``sum m x'`` gives the **direction**: ``+1`` when a positive
ground acceleration drives the opening (the mechanism moves towards -x), ``-1`` otherwise.

The velocity field at rest (:meth:`Mechanism.rest_fields`) feeds the impact model
(:mod:`analytic.rocking.impact`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import NamedTuple, Sequence

import numpy as np

from specimens.constants import G

#: default rotation limit as a multiple of phi_cr (docs/physics/dynamics.md#1-one-degree-of-freedom-mechanisms)
LIMIT_FACTOR = 4.0


class BodyState(NamedTuple):
    """Pose of one body and its derivatives with respect to ``phi`` (SI; per rad, per rad^2)."""

    x: float
    y: float
    theta: float
    dx: float
    dy: float
    dtheta: float
    ddx: float
    ddy: float
    ddtheta: float


@dataclass(frozen=True)
class RigidField:
    """Rigid velocity field of one body per unit ``phi'``: ``v(p) = v_o + omega * J p``.

    ``v_o`` [m/rad] is the velocity of the body point at the origin, ``omega`` [-] its rotation
    rate; ``region`` names the material it moves (see :mod:`analytic.rocking.impact`).
    """

    region: object
    v_o: tuple[float, float]
    omega: float


class Mechanism:
    """Base class of the one-degree-of-freedom linkages.

    Subclasses are frozen dataclasses that define ``masses``, ``inertias`` (tuples),
    :meth:`body_states`, :meth:`geometric_limit` and :meth:`rest_fields`; ``g`` [m/s^2].
    """

    g: float = G
    masses: tuple[float, ...]
    inertias: tuple[float, ...]

    # --- to be supplied -------------------------------------------------------------
    def body_states(self, phi: float) -> Sequence[BodyState]:  # pragma: no cover - abstract
        raise NotImplementedError

    def geometric_limit(self) -> float:  # pragma: no cover - abstract
        """Largest rotation [rad] for which the linkage is meaningful."""
        raise NotImplementedError

    def rest_fields(self) -> tuple[RigidField, ...]:  # pragma: no cover - abstract
        raise NotImplementedError

    def impact_candidates(self) -> Sequence["Mechanism"]:  # pragma: no cover - abstract
        """Mechanisms that may take over after an impact, the default (face-swapped) one first."""
        raise NotImplementedError

    def region_moments(self, region: object) -> tuple[float, float, float, float]:  # pragma: no cover
        """``(m, S_x, S_y, J_O)`` of a material region: mass, first moments, inertia about O."""
        raise NotImplementedError

    @property
    def admissible(self) -> bool:
        """Every hinge opens on the face opposite to it (docs/physics/limit-analysis.md#3-admissibility)."""
        return True

    @property
    def label(self) -> str:
        return type(self).__name__

    # --- equation of motion --------------------------------------------------------
    def terms(self, phi: float) -> tuple[float, float, float, float]:
        """``(M, M', V', S)`` at ``phi`` with ``S = sum m x'`` (so ``Q = -a_g S``)."""
        M = dM = dVy = S = 0.0
        for s, m, I in zip(self.body_states(phi), self.masses, self.inertias):
            M += m * (s.dx * s.dx + s.dy * s.dy) + I * s.dtheta * s.dtheta
            dM += 2.0 * (m * (s.dx * s.ddx + s.dy * s.ddy) + I * s.dtheta * s.ddtheta)
            dVy += m * s.dy
            S += m * s.dx
        return M, dM, self.g * dVy, S

    def mass(self, phi: float) -> float:
        """Generalised mass ``M(phi)`` [kg m^2]."""
        return self.terms(phi)[0]

    def potential(self, phi: float) -> float:
        """``V(phi) = g sum m y_G`` [J]."""
        return self.g * sum(m * s.y for s, m in zip(self.body_states(phi), self.masses))

    def dpotential(self, phi: float) -> float:
        """``V'(phi)`` [J/rad]."""
        return self.terms(phi)[2]

    def d2potential(self, phi: float) -> float:
        """``V''(phi) = g sum m y_G''`` [J/rad^2]."""
        return self.g * sum(m * s.ddy for s, m in zip(self.body_states(phi), self.masses))

    def generalised_force(self, phi: float, a_g: float) -> float:
        """``Q = -a_g sum m x'`` [N m] for ground acceleration ``a_g`` [m/s^2]."""
        return -a_g * self.terms(phi)[3]

    def acceleration(self, phi: float, phidot: float, a_g: float) -> float:
        """``phi''`` [rad/s^2] from the equation of motion."""
        M, dM, dV, S = self.terms(phi)
        return (-a_g * S - dV - 0.5 * dM * phidot * phidot) / M

    def energy(self, phi: float, phidot: float) -> float:
        """Kinetic plus potential energy above the rest state [J]."""
        return 0.5 * self.mass(phi) * phidot * phidot + self.potential(phi) - self.V0

    # --- derived constants -------------------------------------------------------------
    @cached_property
    def V0(self) -> float:
        return self.potential(0.0)

    @cached_property
    def direction(self) -> int:
        """+1 if a positive ground acceleration opens the mechanism, else -1."""
        return 1 if self.terms(0.0)[3] < 0 else -1

    @cached_property
    def onset(self) -> float:
        """Onset ground acceleration ``V'(0) / (-sum m x'(0))`` [m/s^2] (signed)."""
        _, _, dV, S = self.terms(0.0)
        return dV / (-S)

    @cached_property
    def lam(self) -> float:
        """Onset as a multiple of g (``|onset| / g``)."""
        return abs(self.onset) / self.g

    @cached_property
    def phi_cr(self) -> float:
        """Critical rotation [rad]: first zero of ``V'`` (the linkage limit if none before it)."""
        lim = self.geometric_limit()
        if self.dpotential(0.0) <= 0:
            return 0.0
        n = 64
        grid = np.linspace(0.0, lim, n + 1)
        prev = grid[0]
        for p in grid[1:]:
            if self.dpotential(float(p)) <= 0:
                # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
                from scipy.optimize import (
                    brentq,  # imported on first use: the CLI imports this module
                )
                return float(brentq(self.dpotential, prev, float(p), xtol=1e-14, rtol=1e-13))
            prev = float(p)
        return float(lim)

    @cached_property
    def barrier(self) -> float:
        """Energy barrier ``V(phi_cr) - V(0)`` [J]."""
        return self.potential(self.phi_cr) - self.V0

    @cached_property
    def phi_limit(self) -> float:
        """Rotation limit [rad]: ``min(LIMIT_FACTOR phi_cr, geometric limit)``."""
        return float(min(LIMIT_FACTOR * self.phi_cr, self.geometric_limit()))

    @cached_property
    def M0(self) -> float:
        return self.mass(0.0)

    @cached_property
    def omega0(self) -> float:
        """Frequency parameter ``sqrt(|V''(0)| / M(0))`` [rad/s]."""
        return math.sqrt(abs(self.d2potential(0.0)) / self.M0)

    def velocity_map(self, phi: float = 0.0) -> np.ndarray:
        """``Psi``: (n_bodies, 3) centroid velocities and rotation rates per unit ``phi'``."""
        return np.array([[s.dx, s.dy, s.dtheta] for s in self.body_states(phi)])

    def mass_matrix(self) -> np.ndarray:
        """Diagonal mass matrix of the free bodies (3 per body: m, m, I)."""
        return np.diag(np.column_stack([self.masses, self.masses, self.inertias]).ravel())

    def summary(self) -> dict:
        """Main constants (SI) for result files."""
        return {"model": self.label, "onset": self.onset, "lambda": self.lam, "phi_cr": self.phi_cr,
                "omega0": self.omega0, "M0": self.M0, "barrier": self.barrier, "phi_limit": self.phi_limit,
                "direction": self.direction}


# ---------------------------------------------------------------------------------------------
# kinematic building blocks (closed form)
# ---------------------------------------------------------------------------------------------
def rotating_body(pivot: tuple[float, float], g0: tuple[float, float], theta: float, w: float, al: float,
                  pv=(0.0, 0.0), pa=(0.0, 0.0), p0: tuple[float, float] | None = None) -> BodyState:
    """State of a body whose point ``pivot`` (rest position ``p0``, default ``pivot``) moves with
    first/second derivatives ``pv``/``pa`` while the body turns by ``theta`` (rates ``w``, ``al``).

    ``g0`` is the centroid at rest. Closed form: ``G = P + R(theta) (G0 - P0)``,
    ``G' = P' + w J (G - P)``, ``G'' = P'' + al J (G - P) - w^2 (G - P)``.
    """
    px0, py0 = p0 if p0 is not None else pivot
    c, s = math.cos(theta), math.sin(theta)
    rx0, ry0 = g0[0] - px0, g0[1] - py0
    rx, ry = c * rx0 - s * ry0, s * rx0 + c * ry0
    x, y = pivot[0] + rx, pivot[1] + ry
    dx = pv[0] - w * ry
    dy = pv[1] + w * rx
    ddx = pa[0] - al * ry - w * w * rx
    ddy = pa[1] + al * rx - w * w * ry
    return BodyState(x, y, theta, dx, dy, w, ddx, ddy, al)


def field_of(state: BodyState) -> tuple[tuple[float, float], float]:
    """``(v_o, omega)`` of the rigid field whose centroid velocity is ``state.dx, dy``."""
    w = state.dtheta
    return (state.dx + w * state.y, state.dy - w * state.x), w
