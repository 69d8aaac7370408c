"""The tilt test of a block assembly on compliant joints, by statics (docs/physics/modes.md §5).

The second model of the DEM's compliant tilt: the same joints (``k_n w L / 2`` at each end of a joint's
contact, no tension; the joint's shear ``k_s w L`` at its centre while either end is pressed, far stiffer
than the normal springs as the engines' glued friction), the bodies' finite rotations, gravity of constant
magnitude turned by the tilt ``alpha`` (``lambda = tan alpha``). Equilibrium is the minimum of the total
potential energy, followed from the rest state upwards; the assembly collapses at the largest ``alpha``
with a stable equilibrium (positive definite tangent stiffness), bisected. With small displacements this
load would be the rigid limit load (the lower-bound theorem); what moves it is the joints' deformation:
the arch leans on its springs and its hinges' lever arms shrink.

For a spring point ``p`` of a joint between bodies ``a`` and ``b`` (``R`` a body's rotation, ``c`` its
centroid, ``u`` its displacement)::

    delta = [u_b + (R_b - I)(p - c_b)] - [u_a + (R_a - I)(p - c_a)]     (x_b(p) - x_a(p))
    g_n = (R_a n) . delta,  g_t = (R_a t) . delta                      (in a's turned frame)
    E = sum over ends 1/2 k_n w L/2 min(g_n, 0)^2 + [an end pressed] 1/2 k_s w L g_t(centre)^2
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize

from analytic.compliant.modes import joint_frames, stiffness_per_area
from specimens.constants import G
from foundation.errors import ArchdemInputError

#: Shear over normal stiffness standing for the engines' friction, rigid until it slips (lambda is the same to
#: 1e-4 from 1 to 1e4; far above, the energy's round-off hides the minimum).
RIGID_SHEAR = 10.0
#: Relative residual (of the largest weight) at which Newton's method has converged.
RESIDUAL_TOL = 1e-9
#: Iterations of the trust-region search per tilt.
MAX_SEARCH = 500
#: Fresh starts of a trust-region search that stalls before the equilibrium or the collapse.
RESTARTS = 5
#: Relative residual at which the trust-region search hands over to Newton's polish.
SEARCH_TOL = 1e-4
#: Rotation of a body [rad] beyond which the assembly has left its equilibrium (a mechanism moving).
MAX_ROTATION = 0.05
#: Relative width of the bracket on lambda at which the bisection stops.
LAMBDA_TOL = 1e-5
#: Steps in lambda by which the tilt rises from rest until the assembly collapses, then bisected.
LAMBDA_STEP = 0.02

_J = np.array([[0.0, -1.0], [1.0, 0.0]])


@dataclass(frozen=True)
class _Point:
    """A spring point of a joint: bodies ``a``, ``b``, position ``p`` [m], the joint's normal and tangent."""

    a: int
    b: int
    p: np.ndarray
    n0: np.ndarray
    t0: np.ndarray


@dataclass(frozen=True)
class _Joint:
    ends: tuple[_Point, _Point]  # intrados, extrados ends: the normal springs, k_n w L / 2 each [N/m]
    mid: _Point  # the contact's centre: the shear spring, k_s w L [N/m]
    kn: float
    ks: float


def _joints(structure, kn: float, ks: float) -> list[_Joint]:
    out = []
    for j, w, p0, p1, n0, t0 in joint_frames(structure):
        L = float(np.linalg.norm(p1 - p0))
        pts = [_Point(j.a, j.b, p, n0, t0) for p in (p0, p1, 0.5 * (p0 + p1))]
        out.append(_Joint((pts[0], pts[1]), pts[2], kn * w * L / 2, ks * w * L))
    return out


def _turned(theta: float, r: np.ndarray) -> np.ndarray:
    """``(R(theta) - I) r`` without the cancellation of ``R r - r`` at small angles."""
    s, h = math.sin(theta), -2.0 * math.sin(0.5 * theta) ** 2  # h = cos - 1
    return np.array([h * r[0] - s * r[1], s * r[0] + h * r[1]])


def _gap(e: _Point, q: np.ndarray, c: list[np.ndarray], e0: np.ndarray):
    """``(g, dofs, grad, hess)`` of one gap over the six (or three) dofs of the end's bodies, ordered (a, b)."""
    a, b = e.a, e.b
    delta = np.zeros(2)  # x_b(p) - x_a(p)
    if b >= 0:
        rb = e.p - c[b]
        turn_b = _turned(q[3 * b + 2], rb)
        xb_rot = rb + turn_b  # R_b r_b
        delta += q[3 * b:3 * b + 2] + turn_b
    if a >= 0:
        ra = e.p - c[a]
        turn_a = _turned(q[3 * a + 2], ra)
        ea = e0 + _turned(q[3 * a + 2], e0)  # R_a e0
        delta -= q[3 * a:3 * a + 2] + turn_a
        d = delta + ra + turn_a  # x_b - c_a - u_a
    else:
        ea = e0
    g = ea @ delta
    idx, grad = [], []
    if a >= 0:
        idx += [3 * a, 3 * a + 1, 3 * a + 2]
        grad += [-ea[0], -ea[1], (_J @ ea) @ d]
    if b >= 0:
        idx += [3 * b, 3 * b + 1, 3 * b + 2]
        grad += [ea[0], ea[1], ea @ (_J @ xb_rot)]
    n = len(idx)
    H = np.zeros((n, n))
    if a >= 0:
        Je = _J @ ea
        H[2, 2] = -ea @ d
        H[0:2, 2] = H[2, 0:2] = -Je
        if b >= 0:
            H[3:5, 2] = H[2, 3:5] = Je
            H[2, 5] = H[5, 2] = ea @ xb_rot
    if b >= 0:
        H[n - 1, n - 1] = -ea @ xb_rot
    return g, idx, np.array(grad), H


def _system(joints: list[_Joint], q: np.ndarray, c: list[np.ndarray], tangent: bool = True):
    """The joints' energy [J], its gradient and tangent stiffness, and the joint ends' normal gaps [m]
    (intrados, extrados per joint)."""
    K = np.zeros((q.size, q.size))
    f = np.zeros(q.size)
    energy = 0.0
    gaps = np.empty(2 * len(joints))
    for i, jt in enumerate(joints):
        pressed = False
        for k, e in enumerate(jt.ends):
            gn, idx, dn, Hn = _gap(e, q, c, e.n0)
            gaps[2 * i + k] = gn
            if gn > 0:  # open (a closed, unloaded end counts as touching: the rest state starts there)
                continue
            pressed = True
            energy += 0.5 * jt.kn * gn * gn
            f[idx] += jt.kn * gn * dn
            if tangent:
                K[np.ix_(idx, idx)] += jt.kn * (np.outer(dn, dn) + gn * Hn)
        if pressed:  # the joint's shear, at its centre: a hinge turning about either end does not strain it
            gt, idx, dt, Ht = _gap(jt.mid, q, c, jt.mid.t0)
            energy += 0.5 * jt.ks * gt * gt
            f[idx] += jt.ks * gt * dt
            if tangent:
                K[np.ix_(idx, idx)] += jt.ks * (np.outer(dt, dt) + gt * Ht)
    return energy, f, K, gaps


@dataclass(frozen=True)
class ElasticTilt:
    """``lam``: tan of the largest tilt the assembly stands on its joints; ``hinges``: the joints open at
    one end there, ``(name, "intrados"|"extrados")`` of the end still pressed (the mechanism's last hinge
    opens as it collapses); ``displacement``: the bodies' ``(u_x, u_y, theta)`` there [m, rad];
    ``kn``, ``ks`` [Pa/m]."""

    lam: float
    hinges: tuple[tuple[str, str], ...]
    displacement: np.ndarray
    kn: float
    ks: float


def _newton(joints, c, F, q, scale, iterations: int = 10):
    """Newton's method from ``q``: ``(q, gaps, stiffness)`` once converged, ``None`` otherwise."""
    for _ in range(iterations):
        _, f, K, gaps = _system(joints, q, c)
        r = f - F
        if np.max(np.abs(r)) < RESIDUAL_TOL * scale:
            return q, gaps, K
        try:
            q = q - np.linalg.solve(K, r)
        except np.linalg.LinAlgError:
            return None
    return None


def _stable(K: np.ndarray) -> bool:
    try:
        np.linalg.cholesky(K)
    except np.linalg.LinAlgError:
        return False
    return True


def _equilibrium(joints, c, F, q0, scale):
    """The stable equilibrium under the loads ``F`` reached from ``q0``, or ``None`` (the assembly collapses).

    Newton's method first; where it fails, the minimum of the total potential energy by a trust-region
    method, whose steps cannot jump over the barrier that holds the assembly, polished by Newton's method
    (below SEARCH_TOL the energy's decrease is lost in round-off). A search that runs away, or a polish
    that cycles across a joint end opening and closing (the next hinge's onset, where the assembly
    becomes a mechanism), is a collapse."""
    found = _newton(joints, c, F, q0, scale)
    if found is not None and _stable(found[2]):
        return found[:2]
    cache = {}

    def get(q):
        key = q.tobytes()
        if key not in cache:
            e, f, K, _ = _system(joints, q, c)
            cache.clear()
            cache[key] = (e - F @ q, f - F, K)
        return cache[key]

    def stop(intermediate_result):
        if np.max(np.abs(intermediate_result.x[2::3])) > MAX_ROTATION:
            raise StopIteration

    q = q0
    for _ in range(RESTARTS):  # a search stuck on a kink of the energy (a joint end just opening) starts again there
        res = minimize(lambda q: get(q)[0], q, jac=lambda q: get(q)[1], hess=lambda q: get(q)[2], method="trust-exact",
                       callback=stop, options={"gtol": SEARCH_TOL * scale, "maxiter": MAX_SEARCH,
                                               "initial_trust_radius": 1e-6})
        q = res.x
        if np.max(np.abs(q[2::3])) > MAX_ROTATION:
            return None, None
        if res.success:
            break
        if not _stable(get(q)[2]):  # stalled where the assembly has become a mechanism: the kink of its last hinge
            return None, None
    else:  # neither at rest nor running away: the energy's round-off hides its minimum
        raise ArchdemInputError(f"the statics lost its precision on these joints ({res.message.lower().rstrip('.')}); "
                                "the joints are too stiff for the assembly's weight")
    found = _newton(joints, c, F, res.x, scale)
    if found is None or not _stable(found[2]):
        return None, None
    return found[:2]


class _Path:
    """The tilt's equilibrium path of one structure on its joints."""

    def __init__(self, structure, kn, ks) -> None:
        self.kn = stiffness_per_area("normal joint stiffness kn", kn)
        self.ks = RIGID_SHEAR * self.kn if ks is None else stiffness_per_area("shear joint stiffness ks", ks)
        self.joints = _joints(structure, self.kn, self.ks)
        self.c = [np.asarray(b.centroid, float) for b in structure.bodies]
        self.m = np.array([b.mass for b in structure.bodies])
        self.scale = float(self.m.max() * G)
        q, gaps = self.solve(0.0, np.zeros(3 * len(self.c)))
        if q is None:
            raise ArchdemInputError("the assembly does not stand on its joints under its own weight")
        self.rest = (q, gaps)

    def solve(self, lam: float, q0: np.ndarray):
        alpha = math.atan(lam)
        F = np.zeros(3 * len(self.c))
        F[0::3] = self.m * G * math.sin(alpha)
        F[1::3] = -self.m * G * math.cos(alpha)
        return _equilibrium(self.joints, self.c, F, q0, self.scale)


def elastic_state(structure, kn: float, lam: float, ks: float | None = None) -> np.ndarray:
    """The bodies' displacements ``(u_x, u_y, theta)`` [m, rad] from the drawn geometry at the tilt ``lam``
    on joints ``kn``, ``ks`` [Pa/m] (as :func:`elastic_tilt`), followed up from rest; an input error if the
    assembly has collapsed below ``lam``."""
    path = _Path(structure, kn, ks)
    q = path.rest[0]
    for level in np.linspace(0.0, lam, max(2, int(math.ceil(abs(lam) / LAMBDA_STEP)) + 1))[1:]:
        q, _ = path.solve(float(level), q)
        if q is None:
            raise ArchdemInputError(f"the assembly collapses on these joints below lambda {lam:g}")
    return q.reshape(-1, 3)


def elastic_tilt(structure, kn: float, ks: float | None = None, lam_max: float = 2.0) -> ElasticTilt:
    """The collapse tilt ``lambda = tan alpha`` of ``structure`` on no-tension joints of normal stiffness
    ``kn`` and shear stiffness ``ks`` [Pa/m] (default ``RIGID_SHEAR kn``, as the engines' friction), with
    the bodies' finite rotations; the rigid limit load as ``kn`` grows."""
    path = _Path(structure, kn, ks)
    lo, hi, (q_lo, gaps_lo) = 0.0, None, path.rest
    while hi is None:  # march up to the first tilt without a stable equilibrium, then bisect
        trial = lo + LAMBDA_STEP
        if trial > lam_max:
            raise ArchdemInputError(f"the assembly stands beyond lambda {lam_max:g}")
        q, gaps = path.solve(trial, q_lo)
        if q is None:
            hi = trial
        else:
            lo, q_lo, gaps_lo = trial, q, gaps
    while hi - lo > LAMBDA_TOL * hi:
        mid = 0.5 * (lo + hi)
        q, gaps = path.solve(mid, q_lo)
        if q is None:
            hi = mid
        else:
            lo, q_lo, gaps_lo = mid, q, gaps
    hinges = []
    for k, j in enumerate(structure.joints):
        gi, ge = gaps_lo[2 * k], gaps_lo[2 * k + 1]
        if (gi > 0) != (ge > 0):
            hinges.append((j.name, "intrados" if gi <= 0 else "extrados"))
    return ElasticTilt(lo, tuple(hinges), q_lo.reshape(-1, 3), path.kn, path.ks)
