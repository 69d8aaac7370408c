"""Natural frequencies and mode shapes of a block assembly on compliant joints
(docs/physics/modes.md).

Each body has the in-plane degrees of freedom of its centroid ``q_i = (u_x, u_y, theta)``. A joint
between bodies ``a`` and ``b`` (or a body and the ground) is a bed of springs over its contact:
normal stiffness ``k_n`` and shear stiffness ``k_s`` per unit area [Pa/m], out-of-plane width ``w``.
With ``delta(p) = x_b(p) - x_a(p)`` the relative displacement of the joint's two faces at ``p``::

    E = 1/2 w integral over the contact [ k_n (n . delta)^2 + k_s (t . delta)^2 ] ds

is exact at second order with two Gauss points (``delta`` is linear along the joint); by default the
springs are lumped at the contact's two ends instead, as the DEM engines' corner contacts carry them. **Gravity**
acts through the springs' preload: the assembly first settles under its weight (``K q0 = F``) and
the springs' forces ``f(s)`` at rest turn with the bodies; at second order a body turning by
``theta`` moves its point ``p`` by ``-theta^2 / 2 (p - c)``, which adds ``-f . (p - c_b)`` (and
``+f . (p - c_a)``) to the joint's ``theta theta`` stiffness: for a block on its base, ``-W h``.
The modes solve ``K phi = omega^2 M phi`` with ``M = diag(m, m, I_z)`` per body.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from specimens.constants import G
from foundation.errors import ArchdemInputError

#: Where a joint's springs sit, as points and weights on [0, 1]: a continuous bed (two Gauss points, exact
#: for its quadratic integrand), or lumped at the contact's two ends as the DEM engines' corner contacts are.
SPRINGS = {"bed": ((0.5 - 0.5 / math.sqrt(3.0), 0.5), (0.5 + 0.5 / math.sqrt(3.0), 0.5)),
           "ends": ((0.0, 0.5), (1.0, 0.5))}
#: Poisson's ratio of the blocks when none is given (concrete, masonry units).
POISSON = 0.2


def ks_over_kn(poisson: float = POISSON) -> float:
    """Shear over normal joint stiffness of the same block length: (5/6) G / E, G = E / (2 (1 + nu))."""
    return 5.0 / 6.0 / (2.0 * (1.0 + poisson))


#: Shear over normal joint stiffness when only k_n is given.
KS_OVER_KN = ks_over_kn()


def stiffness_per_area(name: str, v) -> float:
    """``v`` as a positive joint stiffness per unit area [Pa/m], or a one-line input error naming ``name``."""
    if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
        raise ArchdemInputError(f"{name} must be a positive stiffness per unit area [Pa/m], got {v!r}")
    return float(v)


def _B(p: np.ndarray, c: np.ndarray) -> np.ndarray:
    """(2, 3): displacement of the material point ``p`` of a body with centroid ``c`` per (u_x, u_y, theta)."""
    r = p - c
    return np.array([[1.0, 0.0, -r[1]], [0.0, 1.0, r[0]]])


def joint_frames(structure):
    """Per joint: ``(joint, w, p0, p1, n, t)`` — the width of the narrower body [m], the intrados and extrados
    ends of its contact [m], its unit normal from body ``a`` to ``b`` and the tangent ``J n``."""
    bodies = structure.bodies
    for j in structure.joints:
        p0, p1 = (np.asarray(p, float) for p in j.contact_points)
        w = min(bodies[k].width for k in (j.a, j.b) if k >= 0)
        n = np.asarray(j.normal, float)
        yield j, w, p0, p1, n, np.array([-n[1], n[0]])


def _joint_terms(structure, kn: float, ks: float, springs: str = "ends"):
    """Per joint: width, the spring matrix D (2x2) and the Gauss points with their weights [m]."""
    for j, w, p0, p1, n, t in joint_frames(structure):
        L = float(np.linalg.norm(p1 - p0))
        D = kn * np.outer(n, n) + ks * np.outer(t, t)
        pts = [(p0 + x * (p1 - p0), wt * L) for x, wt in SPRINGS[springs]]
        yield j, w, D, pts


def stiffness(structure, kn: float, ks: float, springs: str = "ends") -> tuple[np.ndarray, np.ndarray]:
    """``(K, K_g)``: the joints' elastic stiffness and the geometric stiffness of their preload under
    gravity (3 per body, SI)."""
    nb = len(structure.bodies)
    c = [np.asarray(b.centroid, float) for b in structure.bodies]
    K = np.zeros((3 * nb, 3 * nb))
    terms = list(_joint_terms(structure, kn, ks, springs))
    for j, w, D, pts in terms:
        for p, ds in pts:
            B = np.zeros((2, 3 * nb))
            if j.b >= 0:
                B[:, 3 * j.b:3 * j.b + 3] += _B(p, c[j.b])
            if j.a >= 0:
                B[:, 3 * j.a:3 * j.a + 3] -= _B(p, c[j.a])
            K += w * ds * B.T @ D @ B
    F = np.zeros(3 * nb)
    F[1::3] = [-b.mass * G for b in structure.bodies]
    try:
        q0 = np.linalg.solve(K, F)
    except np.linalg.LinAlgError:
        raise ArchdemInputError("the assembly is not held by its joints (singular stiffness)") from None
    Kg = np.zeros_like(K)
    for j, w, D, pts in terms:
        for p, ds in pts:
            d = np.zeros(2)
            for k, sgn in ((j.b, 1.0), (j.a, -1.0)):
                if k >= 0:
                    d += sgn * _B(p, c[k]) @ q0[3 * k:3 * k + 3]
            f = w * ds * D @ d  # the springs' force at rest (gradient of their energy in delta)
            if j.b >= 0:
                Kg[3 * j.b + 2, 3 * j.b + 2] -= f @ (p - c[j.b])
            if j.a >= 0:
                Kg[3 * j.a + 2, 3 * j.a + 2] += f @ (p - c[j.a])
    return K, Kg


def mass_matrix(structure) -> np.ndarray:
    return np.diag(np.ravel([[b.mass, b.mass, b.I_z] for b in structure.bodies]))


@dataclass(frozen=True)
class Modes:
    """``frequencies_hz`` ascending, ``shapes`` (3 n_bodies, n_modes) mass-normalised, ``kn``, ``ks``;
    ``unstable``: modes whose stiffness is negative (gravity beats the joints), not counted."""

    frequencies_hz: np.ndarray
    shapes: np.ndarray
    kn: float
    ks: float
    unstable: int
    springs: str = "ends"

    def describe(self, count: int | None = None) -> dict:
        n = len(self.frequencies_hz) if count is None else count
        return {"frequencies_hz": self.frequencies_hz[:n].tolist(), "kn": self.kn, "ks": self.ks,
                "springs": self.springs, "n_modes": int(len(self.frequencies_hz)), "unstable": self.unstable}


def modes(structure, kn: float, ks: float | None = None, springs: str = "ends") -> Modes:
    """The natural frequencies and mode shapes of ``structure`` (an assembly, on piers or not, a frame
    or a single block) at rest under gravity on joints of stiffness ``kn``, ``ks`` [Pa/m] (``ks``
    default ``KS_OVER_KN kn``), their springs at the contact ends (``"ends"``, as the DEM's) or spread
    over it (``"bed"``)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from scipy.linalg import eigh

    kn = stiffness_per_area("normal joint stiffness kn", kn)
    ks = KS_OVER_KN * kn if ks is None else stiffness_per_area("shear joint stiffness ks", ks)
    if springs not in SPRINGS:
        raise ArchdemInputError(f"joint springs {springs!r} is not one of {', '.join(SPRINGS)}")
    K, Kg = stiffness(structure, kn, ks, springs)
    lam, phi = eigh(K + Kg, mass_matrix(structure))
    bad = int(np.sum(lam < 0))
    ok = lam >= 0
    return Modes(np.sqrt(lam[ok]) / (2.0 * math.pi), phi[:, ok], kn, ks, bad, springs)
