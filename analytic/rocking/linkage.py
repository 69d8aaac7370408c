"""Four-bar (rocking arch) and two-bar (sliding arch) linkages (docs/physics/dynamics.md#3-the-four-bar-linkage, #4).

**Four-bar**: hinges H1..H4 left to right, H1 and H4 on the fixed parts; block 1 (H1-H2) turns
about H1 by ``sense * phi``, block 3 (H3-H4) about H4, block 2 (H2-H3) is the coupler. Position
analysis in closed form (H3 = intersection of the circles about H2 and H4, on the side of line
H2-H4 it occupies at rest: the assembly branch continuous from rest); velocity and acceleration
analysis in closed form (two 2x2 linear systems). ``sense`` is chosen so that gravity resists
``phi > 0``. Material regions are intervals of the arch coordinate ``u`` of
:mod:`analytic.limit.limit_continuous` (so impacts between different layouts refine them).

**Two-bar**: the halves of :func:`analytic.limit.two_bar.two_bar_geometry`, hinged at springing
corners A (left) and B (right), joined at the crown point S by a vertical slider (equal
horizontal displacement of S on both bars; relative rotation free). Closed form:
``x_S`` of the right bar ``= B_x + r_x cos(t) - r_y sin(t)`` solved for ``t`` on the branch of rest.

The geometry sits in the frame of :mod:`specimens.geometry`. Mechanisms opened by a positive
ground acceleration move towards -x (``direction = +1``); :func:`arch_four_bar` and
:func:`arch_two_bar` mirror the layout when asked for the other direction.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import Sequence

import numpy as np
from scipy.optimize import brentq

from analytic.limit.layout import FourHingeLayout, Hinge, MacroBlock
from analytic.limit.limit_continuous import (
    RingCuts,  # the cut family of the continuous analysis
    continuous_collapse,
)
from analytic.limit.limit_discrete import FACES, enumerate_mechanisms, macro_block_of_bodies
from analytic.limit.two_bar import two_bar_geometry
from analytic.rocking.mechanism import BodyState, Mechanism, RigidField, field_of, rotating_body
from specimens.blocks import Assembly, discretise
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from specimens.sections import region_properties

Pt = tuple[float, float]


def _cross(ax: float, ay: float, bx: float, by: float) -> float:
    return ax * by - ay * bx


# ---------------------------------------------------------------------------------------------
# ring material (exact region properties between cuts of the arch coordinate u)
# ---------------------------------------------------------------------------------------------
def _ring(arch: PointedArch, contact: float = 1.0):
    return RingCuts(arch, contact)


@lru_cache(maxsize=4096)
def ring_moments(arch: PointedArch, density: float, u0: float, u1: float) -> tuple[float, float, float, float]:
    """``(m, S_x, S_y, J_O)`` of the ring between cuts ``u0 < u1`` (kg, kg m, kg m^2 about O)."""
    sec = region_properties(_ring(arch).edges(u0, u1))
    m = density * arch.width * sec.area
    c = sec.centroid
    J = density * arch.width * sec.polar + m * float(c @ c)
    return m, m * float(c[0]), m * float(c[1]), J


# ---------------------------------------------------------------------------------------------
# four-bar
# ---------------------------------------------------------------------------------------------
class _RingLinkage(Mechanism):
    """What the four-bar and the two-bar share: rigid bodies that are regions of an arch ring
    (``regions`` = cut-coordinate pairs, with ``arch`` and ``density``) or plain rigid bodies
    (``masses``, ``centroids``, ``inertias``) for the impact fields."""

    def rest_fields(self) -> tuple[RigidField, ...]:
        return tuple(RigidField(r, *field_of(s)) for r, s in zip(self.regions, self.body_states(0.0)))

    def region_moments(self, region) -> tuple[float, float, float, float]:
        if isinstance(region, tuple) and self.arch is not None:
            return ring_moments(self.arch, self.density, float(region[0]), float(region[1]))
        k = self.regions.index(region)
        m, c = self.masses[k], self.centroids[k]
        return m, m * c[0], m * c[1], self.inertias[k] + m * (c[0] ** 2 + c[1] ** 2)


@dataclass(frozen=True, eq=False)
class FourBar(_RingLinkage):
    """Four-bar linkage with three rigid macro-blocks attached to its links.

    ``points``: H1..H4 [m]; ``others``: the other end point of each hinge's cut and ``normals``
    the cut normals pointing left to right (admissibility); ``masses`` [kg], ``centroids`` [m],
    ``inertias`` [kg m^2] of the blocks; ``sense``: +1 if block 1 turns counter-clockwise for
    ``phi > 0``; ``regions``: material regions of the blocks; ``arch``/``density``/``hinges``
    when built on a ring (enables impact candidates).
    """

    points: tuple[Pt, Pt, Pt, Pt]
    masses: tuple[float, float, float]
    centroids: tuple[Pt, Pt, Pt]
    inertias: tuple[float, float, float]
    sense: int = 1
    others: tuple[Pt, Pt, Pt, Pt] | None = None
    normals: tuple[Pt, Pt, Pt, Pt] | None = None
    regions: tuple = ("block1", "block2", "block3")
    arch: PointedArch | None = None
    density: float = 500.0
    hinges: tuple[Hinge, Hinge, Hinge, Hinge] | None = None
    name: str = "four-bar"
    g: float = G
    joints: tuple[tuple[str, str], ...] = ()  # (joint name, face) of each hinge, when built on a discrete structure

    def __post_init__(self) -> None:
        (x1, y1), (x2, y2), (x3, y3), (x4, y4) = self.points
        object.__setattr__(self, "_L2", math.hypot(x3 - x2, y3 - y2))
        object.__setattr__(self, "_L3", math.hypot(x3 - x4, y3 - y4))
        object.__setattr__(self, "_branch", 1.0 if _cross(x4 - x2, y4 - y2, x3 - x2, y3 - y2) >= 0 else -1.0)
        if self._L2 <= 0 or self._L3 <= 0 or math.hypot(x2 - x1, y2 - y1) <= 0:
            raise ArchdemInputError("four-bar hinges must be distinct points")

    @property
    def label(self) -> str:
        return self.name

    def _positions(self, phi: float):
        (x1, y1), (x2, y2), (x3, y3), (x4, y4) = self.points
        th1 = self.sense * phi
        c, s = math.cos(th1), math.sin(th1)
        rx, ry = x2 - x1, y2 - y1
        p2x, p2y = x1 + c * rx - s * ry, y1 + s * rx + c * ry
        dx, dy = x4 - p2x, y4 - p2y
        d = math.hypot(dx, dy)
        L2, L3 = self._L2, self._L3
        a = (L2 * L2 - L3 * L3 + d * d) / (2 * d)
        h2 = L2 * L2 - a * a
        return th1, (p2x, p2y), (dx, dy, d, a, h2)

    def _h2(self, phi: float) -> float:
        return self._positions(phi)[2][4]

    def body_states(self, phi: float) -> list[BodyState]:
        (x1, y1), (x2, y2), (x3, y3), (x4, y4) = self.points
        th1, (p2x, p2y), (dx, dy, d, a, h2) = self._positions(phi)
        # beyond the toggle (only reached by trial stages of the integrator past phi_limit) the
        # linkage is held at the toggle position
        h = math.sqrt(max(h2, 0.0))
        ux, uy = dx / d, dy / d
        b = self._branch
        p3x = p2x + a * ux - b * h * uy
        p3y = p2y + a * uy + b * h * ux
        # rotations of the coupler and of link 3 from rest
        r23x, r23y = p3x - p2x, p3y - p2y
        r43x, r43y = p3x - x4, p3y - y4
        th2 = math.atan2(_cross(x3 - x2, y3 - y2, r23x, r23y), (x3 - x2) * r23x + (y3 - y2) * r23y)
        th3 = math.atan2(_cross(x3 - x4, y3 - y4, r43x, r43y), (x3 - x4) * r43x + (y3 - y4) * r43y)
        # velocities per unit phi': w2 r23 - w3 r43 = -w1 r12
        w1 = float(self.sense)
        r12x, r12y = p2x - x1, p2y - y1
        det = _cross(r23x, r23y, -r43x, -r43y) or 1e-300
        bx, by = -w1 * r12x, -w1 * r12y
        w2 = _cross(bx, by, -r43x, -r43y) / det
        w3 = _cross(r23x, r23y, bx, by) / det
        # accelerations: al2 r23 - al3 r43 = J^-1 (-a2 + w2^2 r23 - w3^2 r43), a2 = -w1^2 r12
        cx = w1 * w1 * r12x + w2 * w2 * r23x - w3 * w3 * r43x
        cy = w1 * w1 * r12y + w2 * w2 * r23y - w3 * w3 * r43y
        jx, jy = cy, -cx
        al2 = _cross(jx, jy, -r43x, -r43y) / det
        al3 = _cross(r23x, r23y, jx, jy) / det
        v2 = (-w1 * r12y, w1 * r12x)
        a2 = (-w1 * w1 * r12x, -w1 * w1 * r12y)
        (g1, g2, g3) = self.centroids
        return [
            rotating_body((x1, y1), g1, th1, w1, 0.0),
            rotating_body((p2x, p2y), g2, th2, w2, al2, v2, a2, p0=(x2, y2)),
            rotating_body((x4, y4), g3, th3, w3, al3),
        ]

    def geometric_limit(self) -> float:
        """0.95 x the first rotation at which the coupler aligns with link 3 (toggle), or pi/2."""
        return 0.95 * _first_root(self._h2, math.pi / 2)

    # --- admissibility and impacts ------------------------------------------------------
    def rotation_rates(self) -> tuple[float, float, float]:
        s = self.body_states(0.0)
        return s[0].dtheta, s[1].dtheta, s[2].dtheta

    @property
    def admissible(self) -> bool:
        if self.others is None or self.normals is None:
            return True
        t1, t2, t3 = self.rotation_rates()
        rel = (t1, t2 - t1, t3 - t2, -t3)
        ok = True
        for r, H, Q, n in zip(rel, self.points, self.others, self.normals):
            op = r * _cross(Q[0] - H[0], Q[1] - H[1], n[0], n[1])
            ref = max(abs(x) for x in rel) * math.hypot(Q[0] - H[0], Q[1] - H[1])
            ok &= op >= -1e-9 * ref
        dV = self.dpotential(0.0)
        return bool(ok and dV > 0)

    def impact_candidates(self) -> list["FourBar"]:
        """Face-swapped layout first; on a ring also the mirrored layout (always admissible by
        symmetry) and the face patterns of the layouts sharing the hinges' cuts."""
        if self.hinges is None or self.arch is None:
            return [self.face_swapped()]
        U = _ring(self.arch).U
        cuts = [U - r for reg in reversed(self.regions) for r in reg[::-1]][::2] + [U - self.regions[0][0]]
        mirror = arch_four_bar(self.arch, _mirror_hinges(self.hinges), self.density, direction=None,
                               name=_base_name(self.name) + " (mirror)", cuts=cuts)
        return [self.face_swapped(), mirror]

    def more_impact_candidates(self) -> list["FourBar"]:
        """The costlier candidates, searched only when the face-swapped layout is not admissible."""
        return alternative_four_bars(self) if self.arch is not None and self.hinges is not None else []

    def summary(self) -> dict:
        out = super().summary()
        if self.joints:
            out["hinges"] = [{"joint": j, "face": f} for j, f in self.joints]
        elif self.hinges is not None:
            out["hinges"] = [{"face": h.face} for h in self.hinges]
        for h, p in zip(out.get("hinges", []), self.points):
            h["angle_rad"] = polar_angle(p)
        return out

    def same_as(self, other: Mechanism) -> bool:
        """Same linkage (hinge points, blocks and sense)."""
        return (isinstance(other, FourBar) and np.allclose(self.points, other.points, rtol=0, atol=1e-12)
                and np.allclose(self.centroids, other.centroids, rtol=0, atol=1e-12) and self.sense == other.sense)

    def face_swapped(self) -> "FourBar":
        """Each hinge moved to the other face of its cut; same blocks, sense re-oriented."""
        if self.others is None:
            raise ValueError("face swap needs the other end of every hinge's cut")
        hinges = tuple(h.swapped() for h in self.hinges) if self.hinges is not None else None
        joints = tuple((j, "extrados" if f == "intrados" else "intrados") for j, f in self.joints)
        fb = replace(self, points=self.others, others=self.points, hinges=hinges, sense=1,
                     name=_swap_name(self.name), joints=joints)
        return _orient(fb)


def _base_name(name: str) -> str:
    for suffix in (" (swapped)", " (mirror)", " (max-energy)"):
        if name.endswith(suffix):
            return name[:-len(suffix)]
    return name


def _swap_name(name: str) -> str:
    return name[:-len(" (swapped)")] if name.endswith(" (swapped)") else name + " (swapped)"


def _first_root(f, hi: float, n: int = 200) -> float:
    """First zero of ``f`` in (0, hi] (``f(0) > 0``), or ``hi``."""
    grid = np.linspace(0.0, hi, n + 1)
    prev = 0.0
    for p in grid[1:]:
        try:
            v = f(float(p))
        except ValueError:
            v = -1.0
        if v <= 0:
            try:
                return float(brentq(f, prev, float(p), xtol=1e-13))
            except ValueError:
                return prev
        prev = float(p)
    return float(hi)


def _orient(fb: FourBar) -> FourBar:
    """Choose ``sense`` so that gravity resists ``phi > 0``."""
    if fb.dpotential(0.0) < 0:
        fb = replace(fb, sense=-fb.sense)
    return fb


def _mirror_hinges(hinges) -> tuple[Hinge, ...]:
    return tuple(Hinge(-h.side, h.psi, h.face, h.contact) for h in reversed(hinges))


def mirror_layout(layout: FourHingeLayout) -> FourHingeLayout:
    """The layout mirrored about the symmetry axis (hinges and blocks re-ordered left to right)."""
    blocks = tuple(MacroBlock(b.mass, np.array([-b.centroid[0], b.centroid[1]]), b.inertia)
                   for b in reversed(layout.blocks))
    return FourHingeLayout(_mirror_hinges(layout.hinges), blocks)  # type: ignore[arg-type]


def four_bar(points: Sequence[Pt], blocks: Sequence[MacroBlock], others: Sequence[Pt] | None = None,
             normals: Sequence[Pt] | None = None, name: str = "four-bar") -> FourBar:
    """A four-bar from hinge points (4, 2) [m] and three macro-blocks (oriented by gravity)."""
    P = tuple((float(p[0]), float(p[1])) for p in points)
    fb = FourBar(P, tuple(float(b.mass) for b in blocks),
                 tuple((float(b.centroid[0]), float(b.centroid[1])) for b in blocks),
                 tuple(float(b.inertia) for b in blocks),
                 others=None if others is None else tuple((float(p[0]), float(p[1])) for p in others),
                 normals=None if normals is None else tuple((float(p[0]), float(p[1])) for p in normals),
                 name=name)
    return _orient(fb)


def arch_four_bar(arch: PointedArch, layout: FourHingeLayout | Sequence[Hinge], density: float = 500.0,
                  direction: int | None = 1, name: str = "four-bar", cuts: Sequence[float] | None = None) -> FourBar:
    """The four-bar of a hinge layout on the continuous ring of ``arch``.

    ``layout``: a :class:`FourHingeLayout` (its macro-blocks are used) or four hinges (blocks
    from the ring). ``direction``: +1 (opened by a positive ground acceleration, moving to -x),
    -1, or None (as given); the layout is mirrored if needed. ``cuts``: the arch coordinates
    ``u`` of the four cuts (:mod:`analytic.limit.limit_continuous`), needed when an intrados hinge sits at
    the apex on a keystone-fan cut (the hinge alone does not say how the keystone is shared);
    by default from the hinges.
    """
    if cuts is None and isinstance(layout, CutLayout):
        cuts = layout.cuts
    if isinstance(layout, FourHingeLayout):
        hinges, blocks = tuple(layout.hinges), tuple(layout.blocks)
    else:
        hinges, blocks = tuple(layout), None
    if len(hinges) != 4:
        raise ArchdemInputError("a four-bar needs four hinges")
    contacts = {h.contact for h in hinges}
    if len(contacts) != 1:
        raise ArchdemInputError(f"the four hinges must share one effective contact, got {sorted(contacts)}")
    ring = _ring(arch, contacts.pop())  # hinges at the ends of each cut's contact (docs/physics/limit-analysis.md#12-effective-contact)
    u = [ring.u_of_hinge(h) for h in hinges] if cuts is None else [float(c) for c in cuts]
    if len(u) != 4:
        raise ArchdemInputError("a four-bar needs four cuts")
    if any(b <= a for a, b in zip(u[:-1], u[1:])):
        raise ArchdemInputError("hinges must be given left to right at distinct cuts")
    I, E = ring.contact_ends(np.array(u))
    n = ring.normal(np.array(u))
    pts = [E[k] if h.face == "extrados" else I[k] for k, h in enumerate(hinges)]
    oth = [I[k] if h.face == "extrados" else E[k] for k, h in enumerate(hinges)]
    regions = tuple((float(u[k]), float(u[k + 1])) for k in range(3))
    if blocks is None:
        blocks = []
        for (u0, u1) in regions:
            m, Sx, Sy, J = ring_moments(arch, density, u0, u1)
            c = np.array([Sx / m, Sy / m])
            blocks.append(MacroBlock(m, c, J - m * float(c @ c)))
    fb = four_bar(pts, blocks, oth, n, name)
    fb = replace(fb, regions=regions, arch=arch, density=float(density), hinges=hinges)
    if direction is not None and fb.direction != direction:
        mu = [ring.U - c for c in reversed(u)]
        return arch_four_bar(arch, _mirror_hinges(hinges), density, direction=None, name=name, cuts=mu)
    return fb


def alternative_four_bars(before: FourBar, n_grid: int = 33, keep: int = 3) -> list[FourBar]:
    """Admissible four-hinge mechanisms of the ring opening opposite to ``before`` that keep the most
    kinetic energy through an impact from ``before`` (docs/physics/dynamics.md#5-impact), best first.

    Exhaustive over cuts on a grid of ``n_grid`` arch coordinates (plus the cuts of ``before``), both
    alternating face patterns, vectorised: the material is split into grid pieces with exact
    properties, and ``Psi_a^T M Psi_b`` is summed piece by piece. The ``keep`` best are rebuilt
    exactly (their ``e`` is recomputed by :func:`analytic.rocking.impact.energy_restitution`).
    """
    if before.arch is None:
        return []
    arch, rho = before.arch, before.density
    ring = _ring(arch, before.hinges[0].contact)
    grid = np.unique(np.concatenate([np.linspace(0.0, ring.U, n_grid),
                                     [r for reg in before.regions for r in reg]]))
    P = len(grid) - 1
    mom = np.array([ring_moments(arch, rho, float(grid[i]), float(grid[i + 1])) for i in range(P)])
    m, Sx, Sy, J = mom.T
    v = np.zeros((P, 2))
    w = np.zeros(P)
    mids = 0.5 * (grid[:-1] + grid[1:])
    for f in before.rest_fields():
        inside = (mids > f.region[0]) & (mids < f.region[1])
        v[inside] = f.v_o
        w[inside] = f.omega
    JS = np.column_stack([-Sy, Sx])
    A = m[:, None] * v + w[:, None] * JS
    B = np.sum(v * JS, axis=1) + w * J
    cum = lambda x: np.concatenate([np.zeros((1,) + x.shape[1:]), np.cumsum(x, axis=0)])  # noqa: E731
    cm, cSx, cSy, cJ, cA, cB = cum(m), cum(Sx), cum(Sy), cum(J), cum(A), cum(B)
    I, E = ring.contact_ends(grid)
    nrm = ring.normal(grid)
    combos = np.array(list(itertools.combinations(range(P + 1), 4)), dtype=int)
    best: list[tuple[float, np.ndarray, tuple[str, ...]]] = []
    for pattern in (("extrados", "intrados", "extrados", "intrados"), ("intrados", "extrados", "intrados", "extrados")):
        ext = np.array([f == "extrados" for f in pattern])
        H = np.where(ext[None, :, None], E[combos], I[combos])
        Q = np.where(ext[None, :, None], I[combos], E[combos])
        nn = nrm[combos]
        d12, d23, d43 = H[:, 1] - H[:, 0], H[:, 2] - H[:, 1], H[:, 2] - H[:, 3]
        cr = lambda a, b: a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]  # noqa: E731
        det = cr(d43, d23)
        ok = np.abs(det) > 1e-9 * np.linalg.norm(d12, axis=-1) * np.linalg.norm(d43, axis=-1)
        det = np.where(ok, det, 1.0)
        th = np.column_stack([np.ones(len(combos)), cr(d12, d43) / det, cr(d12, d23) / det])
        Jp = lambda p: np.stack([-p[..., 1], p[..., 0]], axis=-1)  # noqa: E731
        uo = np.stack([-th[:, 0, None] * Jp(H[:, 0]),
                       th[:, 0, None] * Jp(H[:, 1] - H[:, 0]) - th[:, 1, None] * Jp(H[:, 1]),
                       -th[:, 2, None] * Jp(H[:, 3])], axis=1)  # (N, 3, 2)
        lo, hi = combos[:, :3], combos[:, 1:]
        bm, bSx, bSy, bJ = cm[hi] - cm[lo], cSx[hi] - cSx[lo], cSy[hi] - cSy[lo], cJ[hi] - cJ[lo]
        bA, bB = cA[hi] - cA[lo], cB[hi] - cB[lo]
        dV = np.sum(bm * uo[..., 1] + th * bSx, axis=1)
        sig = np.where(dV < 0, -1.0, 1.0)
        th, uo = th * sig[:, None], uo * sig[:, None, None]
        S = np.sum(bm * uo[..., 0] - th * bSy, axis=1)
        direction = np.where(S < 0, 1, -1)
        rel = np.column_stack([th[:, 0], th[:, 1] - th[:, 0], th[:, 2] - th[:, 1], -th[:, 2]])
        opening = rel * cr(Q - H, nn)
        ref = np.abs(rel).max(1, keepdims=True) * np.linalg.norm(Q - H, axis=-1).max(1, keepdims=True)
        adm = ok & np.all(opening >= -1e-9 * ref, axis=1) & (direction == -before.direction) & (np.abs(dV) > 0)
        aa = np.sum(bm * np.sum(uo * uo, -1) + 2 * th * (uo[..., 0] * -bSy + uo[..., 1] * bSx) + th * th * bJ, axis=1)
        ab = np.sum(np.sum(uo * bA, -1) + th * bB, axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(adm & (aa > 0), ab / aa, 0.0)
            e = np.where(ratio < 0, -ratio * np.sqrt(np.abs(aa) / before.M0), 0.0)
        for k in np.argsort(-e)[:keep]:
            if e[k] > 0:
                best.append((float(e[k]), grid[combos[k]], pattern))
    best.sort(key=lambda b: -b[0])
    out = []
    for e, u, pattern in best[:keep]:
        hinges = tuple(ring.hinge(float(x), f) for x, f in zip(u, pattern))
        try:
            fb = arch_four_bar(arch, hinges, rho, direction=None, name=_base_name(before.name) + " (max-energy)",
                               cuts=[float(x) for x in u])
        except (ArchdemInputError, ValueError, ZeroDivisionError):
            continue
        if fb.admissible and fb.direction == -before.direction:
            out.append(fb)
    return out


OPPENHEIM_ANGLES = (0.196, 1.374, 2.159, 2.945)  # polar angles about O [rad], docs/physics/limit-analysis.md#9-fixed-hinge-layouts


def hinges_at_angles(arch: PointedArch, betas) -> tuple[Hinge, Hinge, Hinge, Hinge]:
    """Four hinges at the profile points seen from O at polar angles ``betas`` [rad] (0 = right
    springing), alternating extrados / intrados / extrados / intrados from the left, each on the
    radial cut through its point (for a pointed arch: through the centre of that half)."""
    vals = sorted((float(v) for v in betas), reverse=True)  # left to right
    faces = ("extrados", "intrados", "extrados", "intrados")
    out = []
    for beta, face in zip(vals, faces):
        r = float(arch.extrados_distance(beta) if face == "extrados" else arch.intrados_distance(beta))
        p = np.array([r * math.cos(beta), r * math.sin(beta)])
        side = 1 if p[0] >= 0 else -1
        q = p - arch.centre(side)
        out.append(Hinge(side, float(math.atan2(q[1], side * q[0])), face))  # type: ignore[arg-type]
    return tuple(out)  # type: ignore[return-value]


def oppenheim_hinges(arch: PointedArch) -> tuple[Hinge, Hinge, Hinge, Hinge]:
    """The fixed Oppenheim layout (docs/physics/limit-analysis.md#9-fixed-hinge-layouts): hinges seen from O at 0.196, 1.374, 2.159 and
    2.945 rad (see :func:`hinges_at_angles`)."""
    return hinges_at_angles(arch, OPPENHEIM_ANGLES)


def parse_hinge_angles(arch: PointedArch, text: str) -> tuple[Hinge, Hinge, Hinge, Hinge]:
    """Four polar angles about O [rad], ``"b1,b2,b3,b4"`` (any order), as the Oppenheim pattern."""
    try:
        vals = [float(x) for x in text.split(",")]
    except ValueError:
        raise ArchdemInputError(f"--layout: expected 'minimised', 'oppenheim' or four angles 'b1,b2,b3,b4', got {text!r}") from None
    if len(vals) != 4 or not all(0 <= v <= math.pi for v in vals) or len(set(vals)) != 4:
        raise ArchdemInputError(f"--layout needs four distinct polar angles in [0, pi] rad, got {text!r}")
    return hinges_at_angles(arch, vals)


@dataclass(frozen=True)
class CutLayout(FourHingeLayout):
    """A :class:`FourHingeLayout` that also carries the arch coordinates ``cuts`` of its four cuts."""

    cuts: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)


def minimised_layout(arch: PointedArch, density: float = 500.0, contact: float = 1.0) -> CutLayout:
    """The minimum-multiplier layout of the continuous ring (docs/physics/limit-analysis.md#4-continuous-ring), with its cuts;
    ``contact``: the effective contact of the cuts."""
    res = continuous_collapse(arch, density=density, contact=contact)
    if res.layout is None:
        raise ArchdemInputError(f"no admissible four-hinge mechanism found for this arch ({res.message})")
    return CutLayout(res.layout.hinges, res.layout.blocks, tuple(float(x) for x in res.u))  # type: ignore[arg-type]


def minimised_four_bar(arch: PointedArch, density: float = 500.0, direction: int = 1,
                       name: str = "four-bar (minimised)", contact: float = 1.0) -> FourBar:
    """The four-bar of the minimum-multiplier layout of the continuous ring (docs/physics/limit-analysis.md#4-continuous-ring)
    with effective contact ``contact``."""
    return arch_four_bar(arch, minimised_layout(arch, density, contact), density, direction=direction, name=name)


def governing_four_bar(arch: PointedArch, density: float = 500.0, contact: float = 1.0, piers=None,
                       **discretise_kw) -> FourBar:
    """The four-bar of the arch's governing mechanism, opened by a positive ground acceleration: the
    continuous ring's minimum, or on ``piers`` the discrete mechanism through them (the assembly cut
    with ``discretise_kw``). A drawn assembly (:mod:`specimens.drawn`) in place of ``arch``: its own
    minimum discrete mechanism."""
    if isinstance(arch, Assembly):
        return mechanism_four_bar(discretise(arch, density=density, contact=contact, piers=piers, **discretise_kw),
                                  direction=1)
    if piers is None:
        return minimised_four_bar(arch, density, direction=1, contact=contact)

    return mechanism_four_bar(discretise(arch, density=density, contact=contact, piers=piers, **discretise_kw), direction=1)


def mechanism_four_bar(structure, direction: int | None = 1, name: str = "four-bar (discrete)") -> FourBar:
    """The four-bar of the minimum discrete mechanism of ``structure`` (an assembly, on piers or
    not, or a :class:`specimens.frame.Frame`): hinges at the ends of the joints' contact, bars
    through the bodies between them, piers included (docs/physics/dynamics.md#3-the-four-bar-linkage).
    Impacts swap every hinge to the other end of its joint. ``direction`` +1/-1 orients the
    mechanism so that that sign of ground acceleration opens it (None: as found)."""
    # a positive ground acceleration loads the blocks along -x
    kin = enumerate_mechanisms(structure, load_sign=-1 if direction == 1 else 1)
    if not kin.joints:
        raise ArchdemInputError(f"no admissible four-hinge mechanism found ({kin.message})")
    fb = four_bar_through(structure, kin.hinges, name=name)
    if direction is not None and fb.direction != direction:  # pragma: no cover - fixed by the load's sign
        raise AssertionError(f"the discrete four-bar opens for {fb.direction:+d}, not {direction:+d}")
    return fb


def polar_angle(p: Pt) -> float:
    """Polar angle [rad] about O (the springing line's midpoint) of a point: 0 at the right springing,
    pi at the left, negative in the right pier and above pi in the left one."""
    a = math.atan2(float(p[1]), float(p[0]))
    return a + 2 * math.pi if a < -math.pi / 2 else a


@dataclass(frozen=True, eq=False)
class RigidRotation(Mechanism):
    """One rigid body (``body_mass`` [kg], ``centroid`` [m], centroidal ``body_inertia`` [kg m^2]) turning about a
    fixed ``pivot`` [m]: the mechanism of a structure that opens at a single joint (an arch held
    monolithic by strips rocking on one springing). ``sense`` +1: counter-clockwise for ``phi > 0``."""

    pivot: Pt
    body_mass: float
    centroid: Pt
    body_inertia: float
    sense: int = 1
    name: str = "rigid rotation"
    joints: tuple[tuple[str, str], ...] = ()
    g: float = G

    @property
    def masses(self) -> tuple[float, ...]:  # type: ignore[override]
        return (self.body_mass,)

    @property
    def inertias(self) -> tuple[float, ...]:  # type: ignore[override]
        return (self.body_inertia,)

    @property
    def label(self) -> str:
        return self.name

    def body_states(self, phi: float) -> list[BodyState]:
        return [rotating_body(self.pivot, self.centroid, self.sense * phi, float(self.sense), 0.0)]

    def geometric_limit(self) -> float:
        return math.pi / 2

    def rest_fields(self) -> tuple[RigidField, ...]:
        return (RigidField("body", *field_of(self.body_states(0.0)[0])),)

    def impact_candidates(self) -> list[Mechanism]:
        return []

    def summary(self) -> dict:
        return {**super().summary(), "hinges": [{"joint": n, "face": f, "angle_rad": polar_angle(self.pivot)}
                                                for n, f in self.joints]}


def four_bar_through(structure, hinges, name: str = "four-bar") -> FourBar:
    """The four-bar of ``structure`` (an assembly) through four given hinges ``((joint, face), ...)``
    left to right: hinge points at the ends of the joints' contact, bars through the bodies between
    them, oriented so that gravity resists the opening (a single hinge: the whole structure turns
    about it, :class:`RigidRotation`)."""
    by_name = {j.name: j for j in structure.joints}
    joints = [by_name[n] for n, _ in hinges]
    if len(joints) == 1:  # one joint opens: the whole structure turns about it
        (j,), (_, f) = joints, hinges[0]
        mb = macro_block_of_bodies(structure, 0, len(structure.bodies) - 1)
        P = j.contact_points[FACES.index(f)]
        rr = RigidRotation((float(P[0]), float(P[1])), float(mb.mass), (float(mb.centroid[0]), float(mb.centroid[1])),
                           float(mb.inertia), name=name.replace("four-bar", "rigid rotation"), joints=tuple(hinges))
        return rr if rr.dpotential(0.0) > 0 else replace(rr, sense=-1)
    lo = [j.b for j in joints[:3]]
    hi = [j.a for j in joints[1:]]
    if len(joints) != 4 or min(lo) < 0 or any(h < q for q, h in zip(lo, hi)):
        raise ArchdemInputError(f"not a four-hinge mechanism left to right: {hinges!r}")
    points = [j.contact_points[FACES.index(f)] for j, (_, f) in zip(joints, hinges)]
    others = [j.contact_points[1 - FACES.index(f)] for j, (_, f) in zip(joints, hinges)]
    blocks = [macro_block_of_bodies(structure, q, h) for q, h in zip(lo, hi)]
    return replace(four_bar(points, blocks, others, [j.normal for j in joints], name=name), joints=tuple(hinges))


# ---------------------------------------------------------------------------------------------
# two-bar
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class TwoBar(_RingLinkage):
    """Two bars hinged at ``A`` (left bar) and ``B`` (right bar), joined at ``S`` by a vertical slider.

    ``masses``/``centroids``/``inertias``: left bar then right bar; ``sense``: +1 if the left bar
    turns counter-clockwise for ``phi > 0``.
    """

    A: Pt
    B: Pt
    S: Pt
    masses: tuple[float, float]
    centroids: tuple[Pt, Pt]
    inertias: tuple[float, float]
    sense: int = 1
    regions: tuple = ("left", "right")
    arch: PointedArch | None = None
    density: float = 500.0
    name: str = "two-bar"
    g: float = G

    @property
    def label(self) -> str:
        return self.name

    def _right_angle(self, phi: float) -> tuple[float, float, float]:
        (ax, ay), (bx, by), (sx, sy) = self.A, self.B, self.S
        thL = self.sense * phi
        c, s = math.cos(thL), math.sin(thL)
        X = ax + c * (sx - ax) - s * (sy - ay)
        rx, ry = sx - bx, sy - by
        rho, beta = math.hypot(rx, ry), math.atan2(ry, rx)
        k = (X - bx) / rho
        return thL, k, beta

    def _margin(self, phi: float) -> float:
        return 1.0 - abs(self._right_angle(phi)[1])

    def body_states(self, phi: float) -> list[BodyState]:
        (ax, ay), (bx, by), (sx, sy) = self.A, self.B, self.S
        thL, k, beta = self._right_angle(phi)
        k = min(1.0, max(-1.0, k))  # held at the limit beyond it (trial stages only)
        thR = (math.acos(k) - beta) if beta >= 0 else (-math.acos(k) - beta)
        wL = float(self.sense)
        cL, sL = math.cos(thL), math.sin(thL)
        rLx, rLy = cL * (sx - ax) - sL * (sy - ay), sL * (sx - ax) + cL * (sy - ay)
        cR, sR = math.cos(thR), math.sin(thR)
        rRx, rRy = cR * (sx - bx) - sR * (sy - by), sR * (sx - bx) + cR * (sy - by)
        rRy = rRy or 1e-300
        wR = wL * rLy / rRy
        alR = (wL * wL * rLx - wR * wR * rRx) / rRy
        return [rotating_body(self.A, self.centroids[0], thL, wL, 0.0),
                rotating_body(self.B, self.centroids[1], thR, wR, alR)]

    def geometric_limit(self) -> float:
        """0.95 x the rotation at which S on the right bar turns horizontal about B, or pi/2."""
        return 0.95 * _first_root(self._margin, math.pi / 2)

    def mirrored(self) -> "TwoBar":
        mx = lambda p: (-p[0], p[1])  # noqa: E731
        tb = TwoBar(mx(self.B), mx(self.A), mx(self.S), (self.masses[1], self.masses[0]),
                    (mx(self.centroids[1]), mx(self.centroids[0])), (self.inertias[1], self.inertias[0]),
                    1, self.regions, self.arch, self.density, _swap_name(self.name), self.g)
        return _orient(tb)

    def impact_candidates(self) -> list["TwoBar"]:
        """After an impact the mirrored two-bar opens the other way."""
        return [self.mirrored()]

    def same_as(self, other: Mechanism) -> bool:
        return (isinstance(other, TwoBar) and np.allclose([self.A, self.B, self.S], [other.A, other.B, other.S],
                                                          rtol=0, atol=1e-12) and self.sense == other.sense)


def arch_two_bar(arch: PointedArch, density: float = 500.0, direction: int = 1) -> TwoBar:
    """The two-bar model of ``arch`` (geometry of :mod:`analytic.limit.two_bar`), opened by a ground
    acceleration of sign ``direction``."""
    geo = two_bar_geometry(arch, density)
    ring = _ring(arch)
    half = ring.U / 2
    tup = lambda p: (float(p[0]), float(p[1]))  # noqa: E731
    tb = TwoBar(tup(geo.A), tup(geo.B), tup(geo.S), (geo.mass_left, geo.mass_right),
                (tup(geo.centroid_left), tup(geo.centroid_right)), (geo.inertia_left, geo.inertia_right),
                1, ((0.0, float(half)), (float(half), float(ring.U))), arch, float(density), "two-bar")
    tb = _orient(tb)
    if tb.direction != direction:
        tb = tb.mirrored()
        tb = replace(tb, name="two-bar")
    return tb
