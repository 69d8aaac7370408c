"""Discretisation of a pointed arch into voussoirs, crown and rigid bodies (docs/physics/geometry.md#4-discretisation).

Naming, from the left springing to the right springing:

* joints ``L0`` (left base), ``L1`` ... ``Ln``, ``Rn`` ... ``R1``, ``R0`` (right base); the joint
  ``Lk``/``Rk`` lies at polar angle ``psi_k = k D`` of its half;
* blocks ``L1`` ... ``Ln`` (voussoir ``Lk`` between joints ``L(k-1)`` and ``Lk``), ``C`` (crown),
  ``Rn`` ... ``R1``;
* bodies: in the ``free`` configuration one body per block; in the ``glued`` one the
  voussoirs ``Ln`` and ``Rn`` are bonded to the crown (body ``C``) and joints ``Ln``/``Rn`` vanish.

Bodies and joints are listed left to right; a joint joins body ``a`` (left) and body ``b``
(right), ``-1`` meaning the base; its ``normal`` is the unit tangent of the arch at the joint,
pointing from ``a`` to ``b``.

Block shapes: ``linearised`` (flat faces through the joint corners, the default: the
specimens were sawn) or ``curved`` (arcs polygonised with ``segments`` chords per voussoir).
Non-convex blocks are described as compounds of convex pieces, never as their hull.

Effective contact ``contact`` c in (0, 1] (docs/physics/geometry.md#12-effective-contact): every
joint touches only within its central ``c x`` depth. The convex pieces (what engines collide and
meshes export) are relieved by a chamfer at each joint corner; outlines, masses and inertias stay
those of the full sawn blocks.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import Literal, Mapping

import numpy as np

from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from specimens.piers import Piers
from specimens.sections import (
    SectionProperties,
    is_convex,
    polygon_properties,
    signed_area,
)

Shape = Literal["linearised", "curved"]
Config = Literal["glued", "free"]
DEFAULT_DENSITY = 500.0  # kg/m^3, autoclaved aerated concrete (docs/physics/geometry.md#7-mass-properties)
DEFAULT_VOUSSOIRS = 8


@dataclass(frozen=True)
class Block:
    """One sawn block: outline (counter-clockwise, ``(n, 2)`` m) and its convex pieces (relieved
    at the joints when they touch on part of their depth)."""

    name: str
    outline: np.ndarray
    pieces: tuple[np.ndarray, ...]
    intrados: np.ndarray  # intrados polyline, left to right
    extrados: np.ndarray  # extrados polyline, left to right


@dataclass(frozen=True)
class Body:
    """A rigid body of the assembly: one block, or several bonded blocks (glued crown).

    Mass properties are exact for the body's own (polygonal) outline; ``inertia`` is the
    centroidal 3x3 tensor [kg m^2] in the frame x (horizontal), y (up), z (out of plane).
    ``pieces`` are the convex pieces it collides on: the outline's, relieved at the joints when
    they touch on part of their depth (the masses stay the outline's).
    """

    index: int
    name: str
    blocks: tuple[str, ...]
    outline: np.ndarray
    pieces: tuple[np.ndarray, ...]
    section: SectionProperties
    mass: float
    inertia: np.ndarray
    width: float  # out-of-plane depth of the prism [m]: the arch's, or the piers'
    com: np.ndarray | None = None  # centre of mass [m] when a carried load moves it off the section's centroid

    @property
    def centroid(self) -> np.ndarray:
        """Centre of mass [m] (the outline's centroid unless the body carries a load)."""
        return self.section.centroid if self.com is None else self.com

    @property
    def area(self) -> float:
        return self.section.area

    @property
    def I_z(self) -> float:
        """In-plane (about z) centroidal moment of inertia [kg m^2]."""
        return float(self.inertia[2, 2])


@dataclass(frozen=True)
class Joint:
    """An interface between two bodies (or a body and the base, index ``-1``).

    ``p_i`` / ``p_e``: end points at the intrados / extrados [m]; ``normal``: unit vector
    from body ``a`` to body ``b``; ``psi``: polar angle of the radial cut [rad]; ``band``: the
    part of the joint that touches, as fractions of its depth from ``p_i`` (0) to ``p_e`` (1).
    """

    index: int
    name: str
    a: int
    b: int
    p_i: np.ndarray
    p_e: np.ndarray
    normal: np.ndarray
    psi: float
    band: tuple[float, float] = (0.0, 1.0)

    @property
    def contact(self) -> float:
        """Fraction of the joint's depth that touches."""
        return self.band[1] - self.band[0]

    @property
    def contact_points(self) -> tuple[np.ndarray, np.ndarray]:
        """Intrados and extrados ends of the joint's contact band [m]."""
        return band_points(self.p_i, self.p_e, self.band)

    @property
    def is_base(self) -> bool:
        return self.a < 0 or self.b < 0

    @property
    def length(self) -> float:
        return float(np.linalg.norm(self.p_e - self.p_i))

    @property
    def tangent(self) -> np.ndarray:
        """Unit vector along the joint from the intrados end to the extrados end."""
        d = self.p_e - self.p_i
        return d / np.linalg.norm(d)

    @property
    def side(self) -> int:
        """-1 for a joint on the left half (or left pier), +1 on the right."""
        return -1 if self.name.startswith("L") else 1

    @property
    def in_pier(self) -> bool:
        """True for a joint of a pier (``LPk``/``RPk``): horizontal, not a radial cut of the ring."""
        return self.name[1:2] == "P"


@dataclass(frozen=True)
class Assembly:
    """The discretised arch: bodies and joints of one configuration."""

    arch: PointedArch
    config: Config
    shape: Shape
    n_voussoirs: int
    crown_fraction: float
    density: float
    segments: int
    blocks: tuple[Block, ...]
    bodies: tuple[Body, ...]
    joints: tuple[Joint, ...]
    joint_angles: np.ndarray = field(repr=False)
    contact: float = 1.0
    imperfect: bool = False  # per-joint contact bands (``discretise(bands=...)``) instead of ``contact``
    piers: Piers | None = None

    @property
    def length_scale(self) -> float:
        """A length of the structure [m] that scales the analyses' numerics (the arch's mean radius)."""
        return float(self.arch.Rp)

    @property
    def n_bodies(self) -> int:
        return len(self.bodies)

    @property
    def total_mass(self) -> float:
        # fsum: correctly rounded on every Python (builtin sum compensates from 3.12 on, not on 3.11)
        return math.fsum(b.mass for b in self.bodies)

    @cached_property
    def centroid(self) -> np.ndarray:
        m = np.array([b.mass for b in self.bodies])
        return (m[:, None] * np.array([b.centroid for b in self.bodies])).sum(0) / m.sum()

    def joint(self, name: str) -> Joint:
        for j in self.joints:
            if j.name == name:
                return j
        raise KeyError(name)

    def body(self, name: str) -> Body:
        for b in self.bodies:
            if b.name == name:
                return b
        raise KeyError(name)

    @property
    def crown_body(self) -> Body:
        return self.body("C")

    @property
    def crown_index(self) -> int:
        """Index of the body whose displacement is reported as the crown's."""
        return next(k for k, b in enumerate(self.bodies) if b.name == "C")

    @property
    def size(self) -> float:
        """The collapse criterion's length [m]: the ring thickness."""
        return float(self.arch.t)

    @property
    def is_chain(self) -> bool:
        """Bodies and joints alternate along one chain from base to base (the four-hinge enumeration applies)."""
        return True

    def parameters(self) -> dict:
        """The discretisation parameters, for result files."""
        return {
            "config": self.config, "shape": self.shape, "n_voussoirs": self.n_voussoirs,
            "crown_fraction": self.crown_fraction, "density": self.density, "segments": self.segments,
            "contact": self.contact,
            **({"bands": {j.name: list(j.band) for j in self.joints}} if self.imperfect else {}),
            **({"piers": self.piers.describe(self.arch)} if self.piers is not None else {}),
        }


def joint_normal(p_i: np.ndarray, p_e: np.ndarray) -> np.ndarray:
    """Unit normal of the joint ``p_i``-``p_e``: the direction ``p_i -> p_e`` turned clockwise (every
    joint's ends are ordered so that this points from body ``a`` to body ``b``)."""
    d = np.asarray(p_e, float) - np.asarray(p_i, float)
    return np.array([d[1], -d[0]]) / float(np.linalg.norm(d))


def check_contact(contact: float) -> float:
    """``contact`` as a float in (0, 1], or a one-line input error."""
    try:
        c = float(contact)
    except (TypeError, ValueError):
        raise ArchdemInputError(f"effective contact must be a number in (0, 1], got {contact!r}") from None
    if not (math.isfinite(c) and 0 < c <= 1):
        raise ArchdemInputError(f"effective contact must be a fraction of the joint depth in (0, 1], got {contact!r}")
    if c < MIN_EFFECTIVE_CONTACT:
        raise ArchdemInputError(f"effective contact {c:g} is below {MIN_EFFECTIVE_CONTACT:g}: joints touching on less "
                                "than that no longer carry an arch")
    return c


#: Least effective contact accepted (no catalogue arch stands below about 0.4; 0.05 only catches typos).
MIN_EFFECTIVE_CONTACT = 0.05


def central_band(contact: float) -> tuple[float, float]:
    """The band (fractions of the depth) of a joint touching over its central ``contact`` fraction."""
    return (0.0, 1.0) if contact == 1.0 else (0.5 * (1.0 - contact), 0.5 * (1.0 + contact))


def check_band(band, name: str = "joint") -> tuple[float, float]:
    """``band`` as ``(lo, hi)`` with ``0 <= lo < hi <= 1``, or a one-line input error."""
    try:
        lo, hi = (float(x) for x in band)
    except (TypeError, ValueError):
        raise ArchdemInputError(f"contact band of {name} must be two numbers (lo, hi), got {band!r}") from None
    if not (0.0 <= lo < hi <= 1.0):
        raise ArchdemInputError(f"contact band of {name} must satisfy 0 <= lo < hi <= 1, got ({lo:g}, {hi:g})")
    return lo, hi


def band_points(p_i: np.ndarray, p_e: np.ndarray, band: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Ends of the part ``band`` (fractions from ``p_i``) of the joint ``p_i``-``p_e`` [m]."""
    p_i, p_e = np.asarray(p_i, float), np.asarray(p_e, float)
    if band == (0.0, 1.0):
        return p_i, p_e
    d = p_e - p_i
    return p_i + band[0] * d, p_i + band[1] * d


#: Greatest share of a block edge a relief chamfer may take (the two ends of an edge keep a gap).
RELIEF_EDGE_SHARE = 0.45


def _relieve(piece: np.ndarray, joint: Joint) -> np.ndarray:
    """``piece`` with the corners of ``joint``'s face chamfered to its contact points (unchanged
    if the face is not an edge of the piece).

    Each corner P is replaced by the contact end A on the joint and a point B on the other edge
    at P as far from P as A is (a 45 degree relief; at most RELIEF_EDGE_SHARE of that edge); a
    corner the band reaches is kept.
    """
    n = len(piece)
    tol = 1e-9 * max(1.0, float(np.abs(piece).max()))
    idx = [next((k for k in range(n) if np.linalg.norm(piece[k] - p) < tol), None) for p in (joint.p_i, joint.p_e)]
    if None in idx or (idx[0] - idx[1]) % n not in (1, n - 1):
        return piece
    ends = dict(zip(idx, joint.contact_points))
    depth = dict(zip(idx, (joint.band[0] * joint.length, (1.0 - joint.band[1]) * joint.length)))
    out: list[np.ndarray] = []
    for k in range(n):
        if k not in ends or depth[k] == 0.0:
            out.append(piece[k])
            continue
        prev_is_joint = (k - 1) % n in ends
        q = piece[(k + 1) % n] if prev_is_joint else piece[(k - 1) % n]
        edge = q - piece[k]
        b = piece[k] + min(depth[k], RELIEF_EDGE_SHARE * np.linalg.norm(edge)) * edge / np.linalg.norm(edge)
        out.extend([ends[k], b] if prev_is_joint else [b, ends[k]])
    return np.array(out)


def joint_angles(arch: PointedArch, n_voussoirs: int = DEFAULT_VOUSSOIRS, crown_fraction: float = 1.0) -> np.ndarray:
    """Polar angles ``psi_k``, k = 0..n, of the joints of one half [rad].

    Each half is cut into ``n + crown_fraction/2`` equal angular parts at the intrados; the
    crown takes ``crown_fraction/2`` of a part on each side (spec default: 1, so the crown
    is as wide as a voussoir at the intrados).
    """
    D = arch.psi_i / (n_voussoirs + crown_fraction / 2)
    return D * np.arange(n_voussoirs + 1)


def _chain(arch: PointedArch, R: float, psi_a: float, psi_b: float, shape: Shape, segments: int) -> np.ndarray:
    """Points of the right-half profile of radius ``R`` from ``psi_a`` to ``psi_b``."""
    n = 1 if shape == "linearised" else segments
    return arch.point(np.linspace(psi_a, psi_b, n + 1), R)


def _mirror(p: np.ndarray) -> np.ndarray:
    q = np.array(p, dtype=float, copy=True)
    q[..., 0] *= -1
    return q


def _ccw(poly: np.ndarray) -> np.ndarray:
    poly = np.asarray(poly, dtype=float)
    return poly if signed_area(poly) > 0 else poly[::-1].copy()


def _dedupe(points: list[np.ndarray]) -> np.ndarray:
    pts = np.vstack(points)
    keep = [0]
    for k in range(1, len(pts)):
        if np.linalg.norm(pts[k] - pts[keep[-1]]) > 1e-12:
            keep.append(k)
    return pts[keep]


def _right_blocks(arch: PointedArch, psi: np.ndarray, shape: Shape, segments: int):
    """Right-half voussoirs (k = 1..n) and the right half of the crown, ordered by psi.

    Each as (intrados chain, extrados chain, convex pieces), chains in increasing psi.
    """
    out = []
    for k in range(1, len(psi)):
        ci = _chain(arch, arch.Ri, psi[k - 1], psi[k], shape, segments)
        ce = _chain(arch, arch.Re, psi[k - 1], psi[k], shape, segments)
        pieces = [_ccw(np.array([ci[j], ci[j + 1], ce[j + 1], ce[j]])) for j in range(len(ci) - 1)]
        out.append((ci, ce, pieces))
    # crown half: from the last joint to the axis
    pn = psi[-1]
    aI, aE = arch.apex_intrados, arch.apex_extrados
    if shape == "linearised":
        ci = np.array([arch.point(pn, arch.Ri), aI])
        ce = np.array([arch.point(pn, arch.Re), aE])
        pieces = [_ccw(np.array([ci[0], ci[1], ce[1], ce[0]]))]
    else:
        m = max(1, int(math.ceil(segments * (arch.psi_i - pn) / max(psi[1] - psi[0], 1e-12))))
        s = np.linspace(pn, arch.psi_i, m + 1)
        ci = arch.point(s, arch.Ri)
        ce_main = arch.point(s, arch.Re)
        pieces = [_ccw(np.array([ci[j], ci[j + 1], ce_main[j + 1], ce_main[j]])) for j in range(m)]
        # keystone corner: beyond the radial cut through the intrados apex, up to the axis
        m2 = max(2, int(math.ceil(segments * (arch.psi_e - arch.psi_i) / max(psi[1] - psi[0], 1e-12))))
        tail = arch.point(np.linspace(arch.psi_i, arch.psi_e, m2 + 1), arch.Re)
        tail[-1] = aE  # exact apex
        pieces.append(_ccw(np.vstack([aI[None, :], tail])))
        ci[-1] = aI
        ce = np.vstack([ce_main, tail[1:]])
    out.append((ci, ce, pieces))
    return out


def discretise(
    arch: PointedArch,
    n_voussoirs: int = DEFAULT_VOUSSOIRS,
    crown_fraction: float = 1.0,
    shape: Shape = "linearised",
    config: Config = "glued",
    density: float = DEFAULT_DENSITY,
    segments: int = 4,
    contact: float = 1.0,
    bands: Mapping[str, tuple[float, float]] | None = None,
    piers: Piers | None = None,
) -> Assembly:
    """Cut ``arch`` into ``n_voussoirs`` voussoirs per side plus a crown (docs/physics/geometry.md#4-discretisation).

    ``density`` in kg/m^3; ``segments`` = chords per voussoir for the curved shape; ``contact``:
    the central fraction of every joint's depth that touches (1 = the full joint); ``bands``:
    joint name -> ``(lo, hi)``, the touching part of that joint instead (fractions of its depth
    from the intrados end), e.g. an imperfect realisation (:mod:`specimens.imperfection`);
    ``piers``: the arch stands on two :class:`~specimens.piers.Piers` instead of the rigid base
    (docs/physics/geometry.md#14-arches-on-piers).

    A drawn assembly (:mod:`specimens.drawn`) passed as ``arch`` is returned as drawn, with
    ``contact`` applied; ``config`` does not apply to it, and the cutting options are refused.
    """
    if isinstance(arch, Assembly):
        return _as_drawn(arch, n_voussoirs, crown_fraction, shape, density, segments, contact, bands, piers)
    if not isinstance(n_voussoirs, (int, np.integer)) or n_voussoirs < 1:
        raise ArchdemInputError(f"number of voussoirs per side must be an integer >= 1, got {n_voussoirs!r}")
    if not (math.isfinite(crown_fraction) and crown_fraction > 0):
        raise ArchdemInputError(f"crown width fraction must be > 0, got {crown_fraction!r}")
    if shape not in ("linearised", "curved"):
        raise ArchdemInputError(f"block shape must be 'linearised' or 'curved', got {shape!r}")
    if config not in ("glued", "free"):
        raise ArchdemInputError(f"configuration must be 'glued' or 'free', got {config!r}")
    if not (math.isfinite(density) and density > 0):
        raise ArchdemInputError(f"density must be > 0 kg/m^3, got {density!r}")
    if segments < 1:
        raise ArchdemInputError(f"segments per voussoir must be >= 1, got {segments!r}")
    if config == "glued" and n_voussoirs < 2:
        raise ArchdemInputError("the glued configuration needs at least 2 voussoirs per side")
    contact = check_contact(contact)
    bands = {str(k): check_band(v, str(k)) for k, v in (bands or {}).items()}
    if piers is not None:
        if not isinstance(piers, Piers):
            raise ArchdemInputError(f"piers must be a specimens.piers.Piers, got {type(piers).__name__}")
        piers.check(arch)

    psi = joint_angles(arch, n_voussoirs, crown_fraction)
    n = n_voussoirs
    right = _right_blocks(arch, psi, shape, segments)

    # blocks left to right: L1..Ln, C, Rn..R1; chains left to right
    blocks: list[Block] = []
    for k in range(1, n + 1):  # left voussoirs: mirror of right k, psi increasing = left to right
        ci, ce, pieces = right[k - 1]
        ci_l, ce_l = _mirror(ci), _mirror(ce)
        outline = _ccw(np.vstack([ci_l, ce_l[::-1]]))
        blocks.append(Block(f"L{k}", outline, tuple(_ccw(_mirror(p)) for p in pieces), ci_l, ce_l))
    ci, ce, pieces = right[n]
    crown_i = _dedupe([_mirror(ci), ci[::-1]])
    crown_e = _dedupe([_mirror(ce), ce[::-1]])
    crown_outline = _ccw(np.vstack([crown_i, crown_e[::-1]]))
    crown_pieces = tuple(_ccw(_mirror(p)) for p in pieces) + tuple(pieces)
    blocks.append(Block("C", crown_outline, crown_pieces, crown_i, crown_e))
    for k in range(n, 0, -1):
        ci, ce, pieces = right[k - 1]
        outline = _ccw(np.vstack([ci[::-1], ce]))
        blocks.append(Block(f"R{k}", outline, tuple(pieces), ci[::-1].copy(), ce[::-1].copy()))

    for b in blocks:
        for p in b.pieces:
            if not is_convex(p):  # pragma: no cover - a geometry bug, not user input
                raise AssertionError(f"piece of block {b.name} is not convex")

    # bodies
    groups: list[list[int]]
    if config == "free":
        groups = [[i] for i in range(len(blocks))]
    else:
        groups = [[i] for i in range(n - 1)] + [[n - 1, n, n + 1]] + [[i] for i in range(n + 2, 2 * n + 1)]
    bodies: list[Body] = []
    for idx, g in enumerate(groups):
        members = [blocks[i] for i in g]
        ci = _dedupe([m.intrados for m in members])
        ce = _dedupe([m.extrados for m in members])
        outline = _ccw(np.vstack([ci, ce[::-1]]))
        sec = polygon_properties(outline)
        name = "C" if any(m.name == "C" for m in members) else members[0].name
        bodies.append(_make_body(idx, name, tuple(m.name for m in members), outline,
                                 tuple(p for m in members for p in m.pieces), sec, density, arch.width))

    # joints left to right
    body_of_block = {blocks[i].name: bi for bi, g in enumerate(groups) for i in g}
    joints: list[Joint] = []

    def add(name: str, a: int, b: int, side: int, k: int) -> None:
        p_i = arch.point(psi[k], arch.Ri, side)
        p_e = arch.point(psi[k], arch.Re, side)
        # from the end points (not sin/cos of psi): a drawing of these blocks read back has the same normals
        joints.append(Joint(len(joints), name, a, b, p_i, p_e, joint_normal(p_i, p_e), float(psi[k]),
                            bands.get(name, central_band(contact))))

    left_names = [f"L{k}" for k in range(1, n + 1)] + ["C"]
    for k in range(0, n + 1):  # joint Lk between block L(k) (or base) and L(k+1) (or crown)
        a = -1 if k == 0 else body_of_block[f"L{k}"]
        b = body_of_block[left_names[k]]
        if a != b:
            add(f"L{k}", a, b, -1, k)
    right_names = ["C"] + [f"R{k}" for k in range(n, 0, -1)]
    for k in range(n, -1, -1):
        a = body_of_block[right_names[n - k]]
        b = -1 if k == 0 else body_of_block[f"R{k}"]
        if a != b:
            add(f"R{k}", a, b, +1, k)

    if piers is not None:
        blocks, bodies, joints = _on_piers(arch, piers, blocks, bodies, joints, density,
                                           lambda name: bands.get(name, central_band(contact)))
    unknown = set(bands) - {j.name for j in joints}
    if unknown:
        raise ArchdemInputError(f"contact bands given for joints this assembly does not have: {sorted(unknown)}")
    if any(j.band != (0.0, 1.0) for j in joints):
        blocks, bodies = _relieved(blocks, bodies, joints)
    return Assembly(arch, config, shape, int(n_voussoirs), float(crown_fraction), float(density), int(segments),
                    tuple(blocks), tuple(bodies), tuple(joints), psi, contact, bool(bands), piers)


def _as_drawn(asm: Assembly, n_voussoirs, crown_fraction, shape, density, segments, contact, bands, piers) -> Assembly:
    """A drawn assembly handed to :func:`discretise`: its blocks are cut already."""
    if not hasattr(asm, "with_contact"):
        raise ArchdemInputError("discretise takes a PointedArch or a drawn assembly, not an assembly cut already")
    given = [name for name, v, d in (("the number of voussoirs", n_voussoirs, DEFAULT_VOUSSOIRS),
                                     ("a crown width", crown_fraction, 1.0), ("a block shape", shape, "linearised"),
                                     ("segments", segments, 4), ("contact bands", bands, None), ("piers", piers, None))
             if not (v is d or v == d)]
    if given:
        raise ArchdemInputError(f"a drawn assembly is cut as drawn: {given[0]} does not apply to it")
    if density not in (DEFAULT_DENSITY, asm.density):
        raise ArchdemInputError(f"the drawn assembly was read with density {asm.density:g} kg/m^3; give the density "
                                "when reading the drawing")
    return asm.with_contact(contact)


def _on_piers(arch: PointedArch, piers: Piers, blocks: list[Block], bodies: list[Body], joints: list[Joint],
              density: float, band_of) -> tuple[list[Block], list[Body], list[Joint]]:
    """The ring's blocks, bodies and joints set on ``piers`` (docs/physics/geometry.md#14-arches-on-piers).

    Bodies along the chain: left pier courses bottom to top (``LP1`` ... ``LPN``), the ring, right
    pier courses top to bottom (``RPN`` ... ``RP1``); joints ``LP0`` (left pier base) ... ``LP(N-1)``,
    the ring's (``L0``/``R0`` now on the pier tops), ``RP(N-1)`` ... ``RP0`` (right pier base). A
    pier joint ``LPk``/``RPk`` is the bed joint on top of course k (k = 0: the ground); its
    intrados end is on the pier's inner face, its normal points along the chain (up on the left).
    """
    N, nr = piers.courses, len(bodies)
    xi = piers.inner_x(arch)
    xo = xi + piers.width
    ys = np.linspace(-piers.height, 0.0, N + 1)
    depth = piers.depth_for(arch)

    def course(side: int, k: int) -> tuple[Block, np.ndarray]:
        x0, x1 = sorted((side * xi, side * xo))
        outline = np.array([[x0, ys[k - 1]], [x1, ys[k - 1]], [x1, ys[k]], [x0, ys[k]]])
        inner = np.array([[side * xi, ys[k - 1]], [side * xi, ys[k]]])
        outer = np.array([[side * xo, ys[k - 1]], [side * xo, ys[k]]])
        name = f"{'L' if side < 0 else 'R'}P{k}"
        return Block(name, outline, (outline,), inner, outer), outline

    left = [course(-1, k) for k in range(1, N + 1)]
    right = [course(+1, k) for k in range(N, 0, -1)]

    def pier_body(idx: int, blk: Block, outline: np.ndarray) -> Body:
        body = _make_body(idx, blk.name, (blk.name,), outline, (outline,), polygon_properties(outline), density, depth)
        if piers.load and blk.name[2:] == str(N):  # the top course carries the load at its top's centre
            side = -1.0 if blk.name[0] == "L" else 1.0
            body = _with_point_mass(body, piers.load / G, np.array([side * (xi + xo) / 2, 0.0]))
        return body

    new_bodies = [pier_body(i, *left[i]) for i in range(N)]
    new_bodies += [replace(b, index=b.index + N) for b in bodies]
    new_bodies += [pier_body(N + nr + i, *right[i]) for i in range(N)]
    left_top, right_top = N - 1, N + nr

    def shift(j: Joint) -> Joint:
        a = left_top if j.a < 0 and j.side < 0 else (right_top if j.a < 0 else j.a + N)
        b = left_top if j.b < 0 and j.side < 0 else (right_top if j.b < 0 else j.b + N)
        return replace(j, a=a, b=b)

    def pier_joint(name: str, a: int, b: int, side: int, k: int) -> Joint:
        p_i, p_e = np.array([side * xi, ys[k]]), np.array([side * xo, ys[k]])
        return Joint(0, name, a, b, p_i, p_e, np.array([0.0, -float(side)]), 0.0, band_of(name))

    new_joints = [pier_joint(f"LP{k}", k - 1 if k else -1, k, -1, k) for k in range(N)]
    new_joints += [shift(j) for j in joints]
    # right pier body of course k sits at N + nr + (N - k)
    new_joints += [pier_joint(f"RP{k}", N + nr + N - k - 1, N + nr + N - k if k else -1, +1, k)
                   for k in range(N - 1, -1, -1)]
    new_joints = [replace(j, index=i) for i, j in enumerate(new_joints)]
    new_blocks = [b for b, _ in left] + list(blocks) + [b for b, _ in right]
    return new_blocks, new_bodies, new_joints


def _relieved(blocks: list[Block], bodies: list[Body], joints: list[Joint]) -> tuple[list[Block], list[Body]]:
    """Blocks and bodies with every joint face relieved (pieces only; outlines and masses kept)."""
    def relieve(piece: np.ndarray) -> np.ndarray:
        for j in joints:
            piece = _relieve(piece, j)
        return piece

    new_blocks = [replace(b, pieces=tuple(relieve(p) for p in b.pieces)) for b in blocks]
    for b in new_blocks:
        for p in b.pieces:
            if not is_convex(p):  # pragma: no cover - a geometry bug, not user input
                raise AssertionError(f"relieved piece of block {b.name} is not convex")
    by_name = {b.name: b for b in new_blocks}
    new_bodies = [replace(b, pieces=tuple(p for m in b.blocks for p in by_name[m].pieces)) for b in bodies]
    return new_blocks, new_bodies


def _with_point_mass(body: Body, m: float, p: np.ndarray) -> Body:
    """``body`` carrying a point mass ``m`` [kg] at ``p`` [m] (z = 0): mass, centre of mass and
    inertia about it by the parallel-axis theorem."""
    M = body.mass + m
    c = (body.mass * body.centroid + m * p) / M

    def shift(mass: float, d: np.ndarray) -> np.ndarray:
        d3 = np.array([d[0], d[1], 0.0])
        return mass * (float(d3 @ d3) * np.eye(3) - np.outer(d3, d3))

    inertia = body.inertia + shift(body.mass, body.centroid - c) + shift(m, p - c)
    return replace(body, mass=float(M), inertia=inertia, com=c)


def _make_body(index, name, block_names, outline, pieces, sec: SectionProperties, density: float, width: float) -> Body:
    mass = density * width * sec.area
    # prism of depth `width` along z, centred on z = 0
    rho_w = density * width
    Ixx = rho_w * sec.Ixx + mass * width**2 / 12.0
    Iyy = rho_w * sec.Iyy + mass * width**2 / 12.0
    Izz = rho_w * sec.polar
    Ixy = -rho_w * sec.Ixy
    inertia = np.array([[Ixx, Ixy, 0.0], [Ixy, Iyy, 0.0], [0.0, 0.0, Izz]])
    return Body(index, name, block_names, outline, pieces, sec, float(mass), inertia, float(width))
