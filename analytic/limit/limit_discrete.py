"""Limit analysis of the discretised arch: kinematic enumeration and static (equilibrium) LP.

docs/physics/limit-analysis.md#1-assumptions-and-load. Loads: self-weight ``-g m`` and a horizontal body force ``load_sign * lambda g m``
on every body (``load_sign = +1``: along +x). Masonry: rigid, no tension, infinitely strong in
compression; joints may hinge (rotate about a corner) and, in the LP, slide (Coulomb,
associative flow).

* :func:`enumerate_mechanisms` — every four-hinge mechanism with hinges at joint corners (base
  joints included, all 16 face patterns tried, admissibility enforced); the minimum multiplier.
* :func:`solve_lp` — maximise ``lambda`` subject to the equilibrium of every body, with contact
  forces at the two end points of every joint (``N >= 0``, ``|V| <= mu N`` as two linear
  inequalities), solved by HiGHS. The collapse mechanism is read from the LP duals (virtual
  velocities of the bodies) and each joint is classified (see :data:`JOINT_STATES`).

**Effective contact** (the assembly's ``contact`` c in (0, 1], see
:func:`specimens.blocks.discretise`): every joint touches within the central fraction c of its
length, or within its own band in an imperfect realisation (:mod:`specimens.imperfection`); the
hinges of the enumeration and the force points of the LP are the ends of that band
(``Joint.contact_points``). Masses are those of the full blocks.

The four-hinge kernel :func:`four_hinge_lambda` is shared with the continuous analysis.
"""
from __future__ import annotations

import itertools
import math
import warnings
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np
from scipy.optimize import linprog
from scipy.sparse import csr_array

from analytic.limit.layout import FourHingeLayout, Hinge, MacroBlock
from specimens.blocks import Assembly
from specimens.constants import G
from foundation.errors import ArchdemInputError

FACES = ("intrados", "extrados")

#: Joint states reported by :func:`solve_lp` (from the collapse mechanism, i.e. the LP duals):
#: ``closed`` (no relative motion), ``hinge-intrados`` / ``hinge-extrados`` (rotation about that
#: end point; the other end opens), ``sliding`` (relative tangential slip, associative dilatancy,
#: no rotation), ``hinge+sliding`` (slip and rotation about one end, see ``joint_hinge_face``),
#: ``open`` (the whole joint separates).
JOINT_STATES = ("closed", "hinge-intrados", "hinge-extrados", "sliding", "hinge+sliding", "open")


# ---------------------------------------------------------------------------------------------
# the four-hinge kernel (vectorised)
# ---------------------------------------------------------------------------------------------
def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


@dataclass(frozen=True)
class FourHingeWork:
    """Result of :func:`four_hinge_lambda` for a batch of layouts (arrays of the batch shape).

    ``theta``: rotation rates of the three macro-blocks (block 1 = +-1), oriented so that the
    horizontal loads do positive work; ``lam``: multiplier (``inf`` where not a mechanism);
    ``admissible``: every hinge opens on the face opposite to it and the horizontal work > 0.
    """

    lam: np.ndarray
    admissible: np.ndarray
    theta: np.ndarray
    work_horizontal: np.ndarray
    work_vertical: np.ndarray


def four_hinge_lambda(
    H: np.ndarray,
    Q: np.ndarray,
    n: np.ndarray,
    mass: np.ndarray,
    Sx: np.ndarray,
    Sy: np.ndarray,
    load_sign: int = 1,
    rel_tol: float = 1e-9,
) -> FourHingeWork:
    """Virtual-work multiplier of four-hinge layouts (docs/physics/limit-analysis.md#2-the-four-hinge-mechanism), vectorised over a batch.

    ``H`` (..., 4, 2): hinge points left to right; ``Q`` (..., 4, 2): the other end point of each
    hinge's joint (or cut); ``n`` (..., 4, 2): joint normals pointing left to right;
    ``mass``, ``Sx``, ``Sy`` (..., 3): mass and first moments ``sum m x``, ``sum m y`` of the
    three macro-blocks (any consistent units). ``lambda = sum m dy / (load_sign sum m dx)``.
    """
    H = np.asarray(H, float)
    d12 = H[..., 1, :] - H[..., 0, :]
    d23 = H[..., 2, :] - H[..., 1, :]
    d43 = H[..., 2, :] - H[..., 3, :]
    det = _cross(d43, d23)
    scale = np.maximum(np.abs(d12).max(-1), np.abs(d23).max(-1)) * np.abs(d43).max(-1)
    ok = np.abs(det) > 1e-12 * np.maximum(scale, 1e-300)
    det_safe = np.where(ok, det, 1.0)
    th1 = np.ones_like(det)
    th2 = _cross(d12, d43) / det_safe
    th3 = _cross(d12, d23) / det_safe
    H1, H2, H4 = H[..., 0, :], H[..., 1, :], H[..., 3, :]
    m1, m2, m3 = mass[..., 0], mass[..., 1], mass[..., 2]
    # block 1 about H1, block 3 about H4, block 2: velocity of H2 plus rotation about H2
    v1x = -th1 * (H2[..., 1] - H1[..., 1])
    v1y = th1 * (H2[..., 0] - H1[..., 0])
    Dx = (-th1 * (Sy[..., 0] - m1 * H1[..., 1])
          + m2 * v1x - th2 * (Sy[..., 1] - m2 * H2[..., 1])
          - th3 * (Sy[..., 2] - m3 * H4[..., 1]))
    Dy = (th1 * (Sx[..., 0] - m1 * H1[..., 0])
          + m2 * v1y + th2 * (Sx[..., 1] - m2 * H2[..., 0])
          + th3 * (Sx[..., 2] - m3 * H4[..., 0]))
    sDx = load_sign * Dx
    sigma = np.where(sDx < 0, -1.0, 1.0)
    theta = np.stack([th1, th2, th3], axis=-1) * sigma[..., None]
    zero = np.zeros_like(th1)
    t = theta
    rel = np.stack([t[..., 0] - zero, t[..., 1] - t[..., 0], t[..., 2] - t[..., 1], zero - t[..., 2]], axis=-1)
    opening = rel * _cross(Q - H, n)
    ref = np.abs(rel).max(-1, keepdims=True) * np.linalg.norm(Q - H, axis=-1).max(-1, keepdims=True)
    adm_h = np.all(opening >= -rel_tol * np.maximum(ref, 1e-300), axis=-1)
    wscale = np.abs(mass).sum(-1) * np.linalg.norm(d12, axis=-1)
    work_ok = np.abs(sDx) > 1e-12 * np.maximum(wscale, 1e-300)
    admissible = ok & work_ok & adm_h
    with np.errstate(divide="ignore", invalid="ignore"):
        lam = np.where(ok & work_ok, Dy / np.where(work_ok, sDx, 1.0), np.inf)
    return FourHingeWork(lam=lam, admissible=admissible, theta=theta,
                         work_horizontal=np.abs(sDx), work_vertical=Dy * sigma)


# ---------------------------------------------------------------------------------------------
# joints and contact points of an assembly
# ---------------------------------------------------------------------------------------------
def _check_sign(load_sign: int) -> int:
    if load_sign not in (1, -1):
        raise ArchdemInputError(f"load_sign must be +1 or -1, got {load_sign!r}")
    return int(load_sign)


@dataclass(frozen=True)
class ContactModel:
    """Rigid bodies and point-pair interfaces for the equilibrium LP (SI units).

    Bodies: ``mass`` (nb,), ``centroid`` (nb, 2). Interfaces: body indices ``a`` (left / below)
    and ``b`` (right / above), ``-1`` = fixed base; end points ``p1`` (intrados end), ``p2``
    (extrados end); ``normal`` unit vector from ``a`` to ``b``; friction ``mu`` (``inf`` = none).
    """

    body_names: tuple[str, ...]
    mass: np.ndarray
    centroid: np.ndarray
    joint_names: tuple[str, ...]
    a: np.ndarray
    b: np.ndarray
    p1: np.ndarray
    p2: np.ndarray
    normal: np.ndarray
    mu: np.ndarray


def contact_model(assembly: Assembly, mu_joint: float, mu_base: float) -> ContactModel:
    """The LP model of an assembly: block-block joints get ``mu_joint``, base joints ``mu_base``;
    force points at the ends of each joint's contact."""
    for name, mu in (("mu_joint", mu_joint), ("mu_base", mu_base)):
        if not (isinstance(mu, (int, float, np.floating)) and mu >= 0 and not math.isnan(mu)):
            raise ArchdemInputError(f"{name} must be a number >= 0 (inf allowed), got {mu!r}")
    p1, p2 = zip(*(j.contact_points for j in assembly.joints))
    return ContactModel(
        body_names=tuple(b.name for b in assembly.bodies),
        mass=np.array([b.mass for b in assembly.bodies]),
        centroid=np.array([b.centroid for b in assembly.bodies]),
        joint_names=tuple(j.name for j in assembly.joints),
        a=np.array([j.a for j in assembly.joints]),
        b=np.array([j.b for j in assembly.joints]),
        p1=np.array(p1), p2=np.array(p2),
        normal=np.array([j.normal for j in assembly.joints]),
        mu=np.array([float(mu_base) if j.is_base else float(mu_joint) for j in assembly.joints]),
    )


# ---------------------------------------------------------------------------------------------
# static LP
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LPResult:
    """Maximum horizontal multiplier from equilibrium (HiGHS).

    ``lam``: the multiplier (``nan`` if the LP failed, ``inf`` if unbounded);
    ``stands``: True if the structure can stand under self-weight alone (``lam >= 0``);
    ``status`` / ``message``: solver status (0 = optimal) and a readable message;
    ``joint_states``: joint name -> one of :data:`JOINT_STATES` (from the collapse mechanism);
    ``joint_hinge_face``: joint name -> "intrados"/"extrados"/"" (the closed end of a hinge);
    ``forces``: joint name -> {"N_intrados", "N_extrados", "V_intrados", "V_extrados"} [N]
    (normal positive in compression; shear along the joint tangent ``(-n_y, n_x)``);
    ``motion``: joint name -> {"open_intrados", "open_extrados", "slip"} relative virtual
    velocities of the mechanism (normalised: horizontal work of unit loads = 1, lengths / Rp).
    """

    lam: float
    status: int
    message: str
    stands: bool
    joint_states: dict[str, str]
    joint_hinge_face: dict[str, str]
    forces: dict[str, dict[str, float]]
    motion: dict[str, dict[str, float]]
    load_sign: int = 1
    mu_joint: float = math.inf
    mu_base: float = math.inf
    contact: float = 1.0
    tie_forces: tuple[float, ...] = ()

    @property
    def success(self) -> bool:
        return self.status == 0

    @property
    def hinges(self) -> tuple[tuple[str, str], ...]:
        """Joints that hinge (with or without sliding), with the face of the hinge, left to right."""
        return tuple((k, f) for k, f in self.joint_hinge_face.items() if f)


def _sparse(entries: dict[tuple[int, int], float], shape: tuple[int, int]):
    """A CSR matrix of ``entries`` without explicit zeros (what HiGHS gets from the dense matrix)."""
    keys = [k for k, v in entries.items() if v != 0.0]
    if not keys:
        return csr_array(shape)
    rows, cols = np.array(keys).T
    return csr_array((np.array([entries[k] for k in keys]), (rows, cols)), shape=shape)


def equilibrium_entries(model: ContactModel, L: float, s: int) -> tuple[dict[tuple[int, int], float], np.ndarray]:
    """The equilibrium equations of every body (rows ``3 body + (x, y, moment)``) as sparse entries over
    the columns ``N`` (``2 j + k``), ``V`` (``2 nj + 2 j + k``) and ``lambda`` (``4 nj``), forces in units
    of the total weight and lengths in ``L``; and their right-hand side (the weights)."""
    nb, nj = len(model.mass), len(model.joint_names)
    W = float(model.mass.sum())
    il = 4 * nj
    acc: dict[tuple[int, int], float] = {}
    rhs = np.zeros(3 * nb)
    c = model.centroid / L
    for j in range(nj):
        n = model.normal[j]
        tvec = np.array([-n[1], n[0]])
        for k, p in enumerate((model.p1[j] / L, model.p2[j] / L)):
            for body, sgn in ((model.b[j], 1.0), (model.a[j], -1.0)):
                if body < 0:
                    continue
                r = p - c[body]
                for col, d in ((2 * j + k, n), (2 * nj + 2 * j + k, tvec)):
                    for row, v in ((3 * body, sgn * d[0]), (3 * body + 1, sgn * d[1]),
                                   (3 * body + 2, sgn * (r[0] * d[1] - r[1] * d[0]))):
                        acc[row, col] = acc.get((row, col), 0.0) + v
    for body in range(nb):
        m = model.mass[body] / W
        acc[3 * body, il] = s * m
        rhs[3 * body + 1] = m
    return acc, rhs


def solve_contact_lp(model: ContactModel, load_sign: int = 1, length_scale: float | None = None,
                     tension: np.ndarray | None = None, ties: Sequence = ()) -> LPResult:
    """Maximise ``lambda`` for a :class:`ContactModel` (see :func:`solve_lp`); ``tension`` (n_joints, 2):
    the tensile force [N] each joint may carry at its intrados and extrados force points (strips bonded
    across it), else none; ``ties``: :class:`analytic.limit.ties.TieLink` tension members between two bodies,
    each pulling them together with a force from 0 to its ``force`` [N]."""
    s = _check_sign(load_sign)
    nb, nj = len(model.mass), len(model.joint_names)
    W = float(model.mass.sum())
    L = float(length_scale or np.ptp(np.vstack([model.p1, model.p2, model.centroid]), axis=0).max() or 1.0)
    # unknowns: N (2 nj: end 1, end 2 per joint), V (2 nj), lambda; forces in units of g * W
    nt = len(ties)
    nv = 4 * nj + 1 + nt
    iN = lambda j, k: 2 * j + k  # noqa: E731
    iV = lambda j, k: 2 * nj + 2 * j + k  # noqa: E731
    il = 4 * nj
    acc, rhs = equilibrium_entries(model, L, s)
    c = model.centroid / L
    for t, tie in enumerate(ties):
        u = tie.direction
        for body, p, sgn in ((tie.a, tie.p_a, 1.0), (tie.b, tie.p_b, -1.0)):
            r = np.asarray(p, float) / L - c[body]
            col = il + 1 + t
            for row, v in ((3 * body, sgn * u[0]), (3 * body + 1, sgn * u[1]),
                           (3 * body + 2, sgn * (r[0] * u[1] - r[1] * u[0]))):
                acc[row, col] = acc.get((row, col), 0.0) + v
    A = _sparse(acc, (3 * nb, nv))
    ub: dict[tuple[int, int], float] = {}
    n_ub = 0
    for j in range(nj):
        mu = model.mu[j]
        if not math.isfinite(mu):
            continue
        for k in range(2):
            for sv in (1.0, -1.0):
                ub[n_ub, iV(j, k)] = sv
                ub[n_ub, iN(j, k)] = -mu
                n_ub += 1
    A_ub = _sparse(ub, (n_ub, nv)) if n_ub else None
    b_ub = np.zeros(n_ub) if n_ub else None
    cost = np.zeros(nv)
    cost[il] = -1.0
    if tension is None:
        bounds = [(0, None)] * (2 * nj)
    else:  # a strip's tension lets the normal force at its end go below zero, down to -T
        bounds = [(-float(tension[j, k]) / (G * W), None) for j in range(nj) for k in range(2)]
    bounds += [(None, None)] * (2 * nj + 1)
    bounds += [(0.0, float(t.force) / (G * W)) for t in ties]
    res = linprog(cost, A_ub=A_ub, b_ub=b_ub, A_eq=A, b_eq=rhs, bounds=bounds, method="highs",
                  options={"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10})
    common = dict(load_sign=s, mu_joint=float(np.nanmax(model.mu)) if nj else math.inf,
                  mu_base=math.inf, contact=1.0)
    if res.status == 2:
        return LPResult(math.nan, 2, "infeasible: no equilibrium for any horizontal load "
                        "(the structure cannot stand under self-weight)", False, {}, {}, {}, {}, **common)
    if res.status == 3:
        return LPResult(math.inf, 3, "unbounded: no collapse under any horizontal load", True, {}, {}, {}, {}, **common)
    if res.status != 0:
        return LPResult(math.nan, int(res.status), f"LP failed: {res.message}", False, {}, {}, {}, {}, **common)
    lam = float(res.x[il])
    # the mechanism: body virtual velocities from the equality duals (u_x, u_y, omega per body)
    y = np.asarray(res.eqlin.marginals).reshape(nb, 3)
    u = -y
    hw = float(s * np.sum(model.mass / W * u[:, 0]))
    if hw < 0:
        u = -u
        hw = -hw
    if hw > 0:
        u = u / hw

    def vel(body: int, p: np.ndarray) -> np.ndarray:
        if body < 0:
            return np.zeros(2)
        r = p - c[body]
        return u[body, :2] + u[body, 2] * np.array([-r[1], r[0]])

    F = g_w = G * W
    states: dict[str, str] = {}
    faces: dict[str, str] = {}
    forces: dict[str, dict[str, float]] = {}
    motion: dict[str, dict[str, float]] = {}
    vmax = max(1e-300, float(np.abs(u).max()))
    tol = 1e-6 * vmax
    for j, name in enumerate(model.joint_names):
        n = model.normal[j]
        tvec = np.array([-n[1], n[0]])
        rel = [vel(model.b[j], p / L) - vel(model.a[j], p / L) for p in (model.p1[j], model.p2[j])]
        o1, o2 = float(rel[0] @ n), float(rel[1] @ n)
        slip = float(0.5 * (rel[0] + rel[1]) @ tvec)
        mu = model.mu[j]
        motion[name] = {"open_intrados": o1, "open_extrados": o2, "slip": slip}
        forces[name] = {"N_intrados": float(res.x[iN(j, 0)]) * F, "N_extrados": float(res.x[iN(j, 1)]) * F,
                        "V_intrados": float(res.x[iV(j, 0)]) * F, "V_extrados": float(res.x[iV(j, 1)]) * F}
        sliding = abs(slip) > tol
        base = mu * abs(slip) if (sliding and math.isfinite(mu)) else 0.0
        d1, d2 = o1 - base, o2 - base
        c1, c2 = abs(d1) <= tol, abs(d2) <= tol
        if not sliding and c1 and c2:
            st, face = "closed", ""
        elif c1 and not c2:
            st, face = ("hinge+sliding" if sliding else "hinge-intrados"), "intrados"
        elif c2 and not c1:
            st, face = ("hinge+sliding" if sliding else "hinge-extrados"), "extrados"
        elif c1 and c2:
            st, face = "sliding", ""
        else:
            st, face = "open", ""
        states[name], faces[name] = st, face
    del g_w
    msg = "optimal" if lam >= 0 else f"the structure cannot stand under self-weight (lambda = {lam:.4g} < 0)"
    return LPResult(lam, 0, msg, lam >= 0, states, faces, forces, motion, **common,
                    tie_forces=tuple(float(res.x[il + 1 + t]) * F for t in range(nt)))


def solve_lp(
    assembly: Assembly,
    mu_joint: float,
    mu_base: float,
    load_sign: int = +1,
    tension: np.ndarray | None = None,
    ties: Sequence = (),
) -> LPResult:
    """Static limit analysis of a discretised arch: the largest ``lambda`` with equilibrium.

    ``mu_joint`` (block-block) and ``mu_base`` (block-base) are Coulomb friction coefficients
    (``float('inf')`` = no sliding); the force points are the ends of each joint's contact
    (the assembly's ``contact``).
    Geometry that cannot stand under self-weight gives ``stands = False`` (``lam < 0`` or an
    infeasible LP with ``lam = nan``), never an exception. ``tension`` (n_joints, 2) [N]: what
    strips let each joint carry in tension at its intrados / extrados force point; ``ties``: tension
    members between bodies (:func:`solve_contact_lp`).
    """
    model = contact_model(assembly, mu_joint, mu_base)
    res = solve_contact_lp(model, load_sign, length_scale=assembly.length_scale, tension=tension, ties=ties)
    return LPResult(res.lam, res.status, res.message, res.stands, res.joint_states, res.joint_hinge_face,
                    res.forces, res.motion, res.load_sign, float(mu_joint), float(mu_base), float(assembly.contact),
                    res.tie_forces)


def require_standing(label: str, assembly: Assembly) -> None:
    """Refuse, in one line, an ``assembly`` that cannot stand under its own weight even without
    sliding: a test of its capacity would answer nothing."""
    if not solve_lp(assembly, math.inf, math.inf).stands:
        raise ArchdemInputError(f"{label} cannot stand under its own weight (no equilibrium even without sliding): "
                                "there is no capacity to test")


# ---------------------------------------------------------------------------------------------
# kinematic enumeration
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class KinematicResult:
    """Minimum over the admissible four-hinge mechanisms with hinges at joint corners.

    ``hinges``: four ``(joint_name, face)`` left to right; ``layout``: the discrete macro-blocks
    (masses, centroids and centroidal inertias [kg m^2] of the bodies they contain) with
    :class:`~analytic.limit.layout.Hinge` on the joints' radial cuts (the hinge *points* used are the
    ends of the joints' contact, within the corners when ``contact < 1``); ``hinge_points`` (4, 2) [m];
    ``theta``: rotation rates of the three macro-blocks (block 1 = +-1); ``n_admissible``:
    number of admissible layouts found; ``stands``: ``lam >= 0``; ``joints``: indices of the
    hinges' joints; ``blocks``: the three macro-blocks (also when a hinge is in a pier, where
    ``layout`` is None: a layout describes radial cuts of the ring).
    """

    lam: float
    hinges: tuple[tuple[str, str], ...]
    layout: FourHingeLayout | None
    hinge_points: np.ndarray
    theta: np.ndarray
    n_admissible: int
    n_layouts: int
    stands: bool
    message: str
    load_sign: int = 1
    contact: float = 1.0
    joints: tuple[int, ...] = field(default=())
    blocks: tuple[MacroBlock, ...] = field(default=())


def _macro_block(bodies: Sequence, lo: int, hi: int) -> MacroBlock:
    """Mass, centroid and centroidal in-plane inertia of bodies ``lo..hi`` (parallel axes)."""
    sel = bodies[lo:hi + 1]
    m = np.array([b.mass for b in sel])
    cs = np.array([b.centroid for b in sel])
    M = float(m.sum())
    C = (m[:, None] * cs).sum(0) / M
    inertia = float(sum(b.I_z for b in sel) + np.sum(m * np.sum((cs - C) ** 2, axis=1)))
    return MacroBlock(M, C, inertia)


def enumerate_mechanisms(assembly: Assembly, load_sign: int = +1) -> KinematicResult:
    """Minimum ``lambda`` over all admissible four-hinge mechanisms at the ends of the joints'
    contact (no sliding)."""
    f = float(assembly.contact)
    s = _check_sign(load_sign)
    joints = assembly.joints
    nj = len(joints)
    if nj < 4:
        raise ArchdemInputError("a four-hinge mechanism needs at least 4 joints")
    if not getattr(assembly, "is_chain", True):
        raise ArchdemInputError("the four-hinge enumeration needs the blocks in one chain from the ground to the ground; "
                                "this assembly is not one (the static LP takes any assembly)")
    L = assembly.length_scale
    corners = np.array([j.contact_points for j in joints]) / L  # (nj, 2 faces, 2)
    normals = np.array([j.normal for j in joints])
    m = np.array([b.mass for b in assembly.bodies])
    cxy = np.array([b.centroid for b in assembly.bodies]) / L
    M = m.sum()
    m = m / M
    P = np.concatenate([[[0.0, 0.0, 0.0]], np.cumsum(np.column_stack([m, m * cxy[:, 0], m * cxy[:, 1]]), axis=0)])
    a = np.array([j.a for j in joints])
    b = np.array([j.b for j in joints])

    combos = np.array(list(itertools.combinations(range(nj), 4)), dtype=int)  # (nc, 4)
    faces = np.array(list(itertools.product((0, 1), repeat=4)), dtype=int)  # (16, 4)
    J = np.repeat(combos, len(faces), axis=0)
    Fc = np.tile(faces, (len(combos), 1))
    H = corners[J, Fc]
    Q = corners[J, 1 - Fc]
    n = normals[J]
    lo = b[J[:, :3]]
    hi = a[J[:, 1:]]
    valid = np.all(hi >= lo, axis=1) & np.all(lo >= 0, axis=1)
    lo_c, hi_c = np.clip(lo, 0, None), np.clip(hi, 0, None)
    sums = P[hi_c + 1] - P[lo_c]  # (N, 3 blocks, 3)
    w = four_hinge_lambda(H, Q, n, sums[..., 0], sums[..., 1], sums[..., 2], load_sign=s)
    ok = w.admissible & valid & np.isfinite(w.lam)
    nadm = int(ok.sum())
    if nadm == 0:
        return KinematicResult(math.inf, (), None, np.zeros((4, 2)), np.zeros(3), 0, len(J), True,
                               "no admissible four-hinge mechanism", s, f)
    lam = np.where(ok, w.lam, np.inf)
    k = int(np.argmin(lam))
    jj, ff = J[k], Fc[k]
    hinges = tuple((joints[q].name, FACES[fc]) for q, fc in zip(jj, ff))
    blocks = tuple(_macro_block(assembly.bodies, int(lo[k, i]), int(hi[k, i])) for i in range(3))
    # a layout of radial cuts describes hinges on a parametric ring only; a pier joint is no radial cut
    layout = None if getattr(assembly, "arch", True) is None or any(joints[q].in_pier for q in jj) else FourHingeLayout(
        tuple(Hinge(joints[q].side, float(joints[q].psi), FACES[fc], f) for q, fc in zip(jj, ff)), blocks)
    lam_k = float(lam[k])
    msg = "ok" if lam_k >= 0 else f"the arch cannot stand under self-weight (lambda = {lam_k:.4g} < 0)"
    return KinematicResult(lam_k, hinges, layout, H[k] * L, w.theta[k], nadm, len(J),
                           lam_k >= 0, msg, s, f, tuple(int(q) for q in jj), blocks)


def macro_block_of_bodies(assembly: Assembly, lo: int, hi: int) -> MacroBlock:
    """Public helper: the macro-block made of bodies ``lo..hi`` (inclusive, left to right)."""
    return _macro_block(assembly.bodies, lo, hi)


def warn_if_unstable(lam: float, what: str) -> None:
    if not (lam >= 0):
        warnings.warn(f"{what}: the arch cannot stand under self-weight (lambda = {lam:.4g})", stacklevel=2)


def mechanism_lambda(assembly: Assembly, hinges) -> float:
    """Lambda of one given four-hinge mechanism ``((joint name, face), ...)`` left to right, by the
    virtual-work kernel of :func:`four_hinge_lambda`; ``inf`` if the layout is not admissible,
    ``nan`` if it does not have four hinges. Used to compare a simulated hinge set with the
    minimum of the enumeration."""
    if len(hinges) != 4:
        return float("nan")
    names = [j.name for j in assembly.joints]
    J = np.array([names.index(h) for h, _ in hinges])
    F = np.array([FACES.index(f) for _, f in hinges])
    L = assembly.length_scale
    corners = np.array([[j.p_i, j.p_e] for j in assembly.joints]) / L
    normals = np.array([j.normal for j in assembly.joints])
    m = np.array([b.mass for b in assembly.bodies])
    c = np.array([b.centroid for b in assembly.bodies]) / L
    m = m / m.sum()
    P = np.concatenate([[[0.0, 0.0, 0.0]], np.cumsum(np.column_stack([m, m * c[:, 0], m * c[:, 1]]), axis=0)])
    a = np.array([j.a for j in assembly.joints])
    b = np.array([j.b for j in assembly.joints])
    lo, hi = b[J[:3]], a[J[1:]]
    if np.any(lo < 0) or np.any(hi < lo):
        return float("inf")
    s = P[hi + 1] - P[lo]
    w = four_hinge_lambda(corners[J, F][None], corners[J, 1 - F][None], normals[J][None],
                          s[None, :, 0], s[None, :, 1], s[None, :, 2])
    return float(w.lam[0]) if bool(w.admissible[0]) else float("inf")
