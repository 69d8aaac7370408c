"""Block assemblies from drawn polygons: any planar masonry structure (docs/physics/geometry.md#16-assemblies-from-drawings).

:func:`assemble` turns named block outlines [m] (each a closed polygon, optionally with its
convex pieces) and supports into a :class:`DrawnAssembly`: one rigid body per block, joints
found where two blocks' faces (or a block's and a support's) lie on one line within ``tol`` and
overlap, partial overlaps included; outlines that come close without touching are its gaps
(:class:`Gap`), named wherever they leave blocks without support. Every analysis that reads bodies and
joints runs on it; one that needs a two-centred arch's parameters says so in one line.

Order and orientation (the rules of :func:`specimens.blocks.discretise`, so that a catalogue
arch drawn and read back is the same assembly): when the blocks form one chain from the ground
to the ground, bodies and joints are listed along it from its left foot, a joint joining the
body before it (``a``) to the one after (``b``); otherwise bodies are listed left to right by
centroid and each joint joins the lower index to the higher, a base joint the base (-1) to its
block. A joint's ends ``p_i``, ``p_e`` are ordered so that its normal, from ``a`` to ``b``, is
the direction ``p_i -> p_e`` turned clockwise (:func:`specimens.blocks.joint_normal`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Sequence

import numpy as np

from specimens.blocks import (
    Assembly,
    Block,
    Body,
    Joint,
    _make_body,
    _relieved,
    central_band,
    check_band,
    check_contact,
    joint_normal,
)
from specimens.constants import DRAWN_DENSITY
from foundation.errors import ArchdemInputError
from specimens.sections import is_convex, polygon_properties, signed_area

#: Default contact tolerance, as a fraction of the drawing's largest extent.
RELATIVE_TOLERANCE = 1e-5
#: Two outlines with no joint between them that come closer than this fraction of the thinner block's
#: thickness (twice its area over its perimeter) are a gap: most likely a joint drawn open. A fraction of
#: the blocks, not of the drawing: the block two courses up in a tall wall is a course away, not a gap.
GAP_FRACTION = 0.25
#: The configuration of a drawn assembly: its bodies are as drawn (no glued or free crown).
DRAWN_CONFIG = "drawn"
#: Most blocks a drawing may hold (each adds a body and joints to every analysis): a surveyed arch, bridge or
#: wall drawn block by block holds tens to a few hundred; thousands come from a mistake (a hatch or mesh exploded).
MAX_BLOCKS = 2000
#: Parameters of a parametric arch that a drawn assembly does not have (see DrawnAssembly.__getattr__).
ARCH_ONLY = frozenset({"Ri", "Re", "e", "t", "Sh", "Sd", "Rc", "Rp", "span", "rise", "psi_i", "psi_e", "width",
                       "point", "describe", "with_width", "apex_intrados", "apex_extrados", "U"})


@dataclass(frozen=True)
class DrawnBlock:
    """One block as drawn [m]: its outline (closed polygon, either orientation), its convex pieces
    if the drawing gives them, its out-of-plane ``depth`` [m] if the drawing gives it."""

    name: str
    outline: np.ndarray
    pieces: tuple[np.ndarray, ...] | None = None
    depth: float | None = None


def _length_text(d_m: float) -> str:
    """A short length for a message, in mm (``5.0 mm``, ``0.05 mm``)."""
    mm = 1e3 * float(d_m)
    return f"{mm:.1f} mm" if mm >= 1 else f"{mm:.2g} mm"


@dataclass(frozen=True)
class Gap:
    """Block ``a`` and ``b`` (a block's name, ``support k`` or ``the ground``: see ``kind``) come
    ``distance_m`` [m] close without touching (no joint between them); ``at``: the gap's mid-point [m]."""

    a: str
    b: str
    distance_m: float
    at: tuple[float, float]
    kind: str = "block"  # block | support | ground

    def describe(self) -> str:
        d = _length_text(self.distance_m)
        if self.kind == "ground":
            return f"block {self.a} is {d} above the ground"
        if self.kind == "support":
            return f"block {self.a} is {d} from {self.b}"
        return f"blocks {self.a} and {self.b} are {d} apart"

    def to_dict(self) -> dict:
        return {"a": self.a, "b": self.b, "distance_m": float(self.distance_m), "at": [float(v) for v in self.at],
                "kind": self.kind, "text": self.describe()}


def gaps_text(gaps: Sequence[Gap], most: int = 3) -> str:
    """The gaps in one line: ``blocks B4 and B5 are 5.0 mm apart; ...`` (the first ``most``)."""
    text = "; ".join(g.describe() for g in gaps[:most])
    return text + (f" and {len(gaps) - most} more gap(s)" if len(gaps) > most else "")


def _names_text(names: Sequence[str]) -> str:
    return ", ".join(names) if len(names) <= 6 else f"{names[0]} ... {names[-1]} ({len(names)} blocks)"


@dataclass(frozen=True)
class DrawnAssembly(Assembly):
    """An assembly read from a drawing: no parametric arch (``arch`` is None), one body per block.

    ``source``: where it came from (file, format, units, depth, density, tolerance);
    ``length_scale_m``: the length the analyses scale their numerics by [m]; ``size_m``: the
    collapse criterion's length [m]; ``chain``: the blocks form one chain from the ground to the
    ground (the four-hinge enumeration applies); ``gaps``: outlines that come close without a joint
    between them (:class:`Gap`), found when reading.
    """

    source: dict = field(default_factory=dict)
    length_scale_m: float = 1.0
    size_m: float = 1.0
    chain: bool = False
    gaps: tuple[Gap, ...] = ()

    def __getattr__(self, name: str):
        # reached only for attributes a dataclass field or property does not provide
        if name in ARCH_ONLY:
            raise ArchdemInputError(
                f"{self.source.get('file') or 'this drawing'} holds blocks, not a two-centred arch: this needs the "
                f"arch's parameters ({name}; the continuous ring, the two-bar, the calibrated contact and the "
                "imperfect-joint ensembles do); a drawing takes analytic (the LP), tilt, shake, threshold, fragility, "
                "modes, assess, draw, mesh, and rock/domain with --layout discrete")
        raise AttributeError(name)

    @property
    def length_scale(self) -> float:
        return float(self.length_scale_m)

    @property
    def size(self) -> float:
        return float(self.size_m)

    @property
    def is_chain(self) -> bool:
        return bool(self.chain)

    @property
    def crown_index(self) -> int:
        """The body named ``C``, else the one reaching highest (nearest the middle on a tie)."""
        for k, b in enumerate(self.bodies):
            if b.name == "C":
                return k
        xs = np.vstack([b.outline for b in self.bodies])
        xm = 0.5 * (xs[:, 0].min() + xs[:, 0].max())
        return min(range(len(self.bodies)),
                   key=lambda k: (-float(self.bodies[k].outline[:, 1].max()), abs(float(self.bodies[k].centroid[0]) - xm)))

    @property
    def crown_body(self) -> Body:
        return self.bodies[self.crown_index]

    def parameters(self) -> dict:
        return {"config": self.config, "drawing": dict(self.source), "density": self.density, "contact": self.contact,
                "length_scale": self.length_scale, "size": self.size,
                **({"gaps": [g.to_dict() for g in self.gaps]} if self.gaps else {}),
                **({"bands": {j.name: list(j.band) for j in self.joints}} if self.imperfect else {})}

    def parts(self) -> list[tuple[str, ...]]:
        """The blocks grouped by the joints between them (supports not counted), in body order: one
        group when every block reaches every other through joints."""
        root = list(range(len(self.bodies)))

        def find(k: int) -> int:
            while root[k] != k:
                root[k] = root[root[k]]
                k = root[k]
            return k

        for j in self.joints:
            if j.a >= 0 and j.b >= 0:
                root[find(j.a)] = find(j.b)
        groups: dict[int, list[str]] = {}
        for k, b in enumerate(self.bodies):
            groups.setdefault(find(k), []).append(b.name)
        return [tuple(g) for g in groups.values()]

    def cannot_stand(self, label: str) -> str:
        """One line saying that ``label`` (these blocks) cannot stand under its own weight, naming what
        explains it when the drawing shows it: its gaps, and the parts no joint joins."""
        why = []
        if self.gaps:
            why.append(f"{gaps_text(self.gaps)} (no joint between them)")
        parts = self.parts()
        if len(parts) > 1:
            why.append(f"its blocks stand in {len(parts)} parts that no joint joins: "
                       + " | ".join(_names_text(p) for p in parts[:4]) + (" | ..." if len(parts) > 4 else ""))
        return (f"{label} cannot stand under its own weight (no equilibrium even without sliding)"
                + (": " + "; ".join(why) if why else ""))

    def with_bands(self, bands: dict[str, tuple[float, float]], contact: float | None = None) -> "DrawnAssembly":
        """The same blocks with each named joint touching within its own band (fractions of its depth from
        ``p_i``), e.g. a realisation of :class:`specimens.imperfection.Imperfection`; ``contact``: the
        nominal fraction recorded beside them."""
        unknown = set(bands) - {j.name for j in self.joints}
        if unknown:
            raise ArchdemInputError(f"contact bands given for joints this assembly does not have: {sorted(unknown)}")
        if self.contact != 1.0 or self.imperfect:
            raise ValueError("relieve the full blocks (contact 1), not blocks relieved already")
        joints = tuple(replace(j, band=check_band(bands[j.name], j.name)) if j.name in bands else j for j in self.joints)
        blocks, bodies = _relieved(list(self.blocks), list(self.bodies), list(joints))
        return replace(self, blocks=tuple(blocks), bodies=tuple(bodies), joints=joints, imperfect=True,
                       contact=float(self.contact if contact is None else contact))

    def to_dict(self) -> dict:
        """Everything that makes this assembly, JSON-ready (full blocks, contact 1): a worker rebuilds it
        bit for bit with :func:`from_dict`, without the drawing's file."""
        if self.contact != 1.0 or self.imperfect:
            raise ValueError("to_dict describes the full blocks (contact 1)")
        return {"bodies": [{"name": b.name, "outline": b.outline.tolist(), "pieces": [p.tolist() for p in b.pieces],
                            "depth": b.width} for b in self.bodies],
                "joints": [{"name": j.name, "a": j.a, "b": j.b, "p_i": j.p_i.tolist(), "p_e": j.p_e.tolist()}
                           for j in self.joints],
                "density": self.density, "length_scale": self.length_scale_m, "size": self.size_m,
                "chain": self.chain, "source": dict(self.source),
                **({"gaps": [g.to_dict() for g in self.gaps]} if self.gaps else {})}

    def with_contact(self, contact: float) -> "DrawnAssembly":
        """The same blocks with every joint touching within its central ``contact`` fraction
        (pieces relieved at the joints; masses kept)."""
        c = check_contact(contact)
        if c == self.contact and not self.imperfect:
            return self
        if self.contact != 1.0 or self.imperfect:
            raise ValueError("relieve the full blocks (contact 1), not blocks relieved already")
        joints = tuple(replace(j, band=central_band(c)) for j in self.joints)
        blocks, bodies = _relieved(list(self.blocks), list(self.bodies), list(joints)) if c < 1 else (self.blocks, self.bodies)
        return replace(self, blocks=tuple(blocks), bodies=tuple(bodies), joints=joints, contact=c)


def from_dict(d: dict) -> DrawnAssembly:
    """The assembly :meth:`DrawnAssembly.to_dict` described (the same floats: the same model)."""
    bodies, blocks = [], []
    for k, b in enumerate(d["bodies"]):
        o = np.asarray(b["outline"], float)
        pieces = tuple(np.asarray(p, float) for p in b["pieces"])
        blocks.append(Block(b["name"], o, pieces, np.zeros((0, 2)), np.zeros((0, 2))))
        bodies.append(_make_body(k, b["name"], (b["name"],), o, pieces, polygon_properties(o), float(d["density"]),
                                 float(b["depth"])))
    joints = []
    for k, j in enumerate(d["joints"]):
        p, q = np.asarray(j["p_i"], float), np.asarray(j["p_e"], float)
        joints.append(Joint(k, j["name"], int(j["a"]), int(j["b"]), p, q, joint_normal(p, q), 0.0))
    gaps = tuple(Gap(g["a"], g["b"], float(g["distance_m"]), tuple(g["at"]), g.get("kind", "block"))
                 for g in d.get("gaps", ()))
    return DrawnAssembly(None, DRAWN_CONFIG, "drawn", 0, 0.0, float(d["density"]), 0, tuple(blocks), tuple(bodies),
                         tuple(joints), np.zeros(0), 1.0, False, None, dict(d.get("source", {})),
                         float(d["length_scale"]), float(d["size"]), bool(d["chain"]), gaps)


# ---------------------------------------------------------------------------------------------
# polygon basics
# ---------------------------------------------------------------------------------------------
def _clean(name: str, poly, tol: float) -> np.ndarray:
    """``poly`` as a counter-clockwise ``(n, 2)`` array without repeated vertices, or a one-line error."""
    p = np.asarray(poly, dtype=float)
    if p.ndim != 2 or p.shape[1] != 2 or not np.all(np.isfinite(p)):
        raise ArchdemInputError(f"block {name}: its outline must be finite (x, z) points")
    keep = [0]
    for k in range(1, len(p)):
        if np.linalg.norm(p[k] - p[keep[-1]]) > tol:
            keep.append(k)
    if len(keep) > 1 and np.linalg.norm(p[keep[-1]] - p[0]) <= tol:
        keep.pop()  # the closing vertex repeated
    p = p[keep]
    if len(p) < 3:
        raise ArchdemInputError(f"block {name} has fewer than 3 distinct vertices (zero area)")
    if _self_intersects(p, tol):
        raise ArchdemInputError(f"block {name}: its outline crosses itself")
    a = signed_area(p)
    ext = max(np.ptp(p[:, 0]), np.ptp(p[:, 1]))
    if abs(a) <= tol * ext:
        raise ArchdemInputError(f"block {name} has zero area")
    return p if a > 0 else p[::-1].copy()


def _cross2(a: np.ndarray, b: np.ndarray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _segments_cross(p1, p2, q1, q2, tol: float) -> bool:
    """Proper crossing or touching of two segments (beyond ``tol``)."""
    d1, d2 = p2 - p1, q2 - q1
    den = _cross2(d1, d2)
    if abs(den) <= 1e-14 * np.linalg.norm(d1) * np.linalg.norm(d2):
        return False  # parallel: overlap of collinear edges is caught by the area and overlap checks
    s = _cross2(q1 - p1, d2) / den
    t = _cross2(q1 - p1, d1) / den
    es, et = tol / np.linalg.norm(d1), tol / np.linalg.norm(d2)
    return -es <= s <= 1 + es and -et <= t <= 1 + et


def _self_intersects(p: np.ndarray, tol: float) -> bool:
    n = len(p)
    for i in range(n):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue  # adjacent through the closing edge
            if _segments_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n], -tol):
                return True
    return False


def _point_in(poly: np.ndarray, pt: np.ndarray) -> bool:
    """Ray casting (strictly inside for points off the boundary)."""
    x, y = float(pt[0]), float(pt[1])
    inside = False
    n = len(poly)
    for k in range(n):
        x1, y1 = poly[k]
        x2, y2 = poly[(k + 1) % n]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def convex_pieces(poly: np.ndarray) -> tuple[np.ndarray, ...]:
    """Convex pieces of a simple counter-clockwise polygon: ear-clipping triangles merged across
    their diagonals while the union stays convex (Hertel-Mehlhorn; at most 4x the fewest pieces)."""
    p = np.asarray(poly, float)
    if is_convex(p):
        return (p,)
    idx = list(range(len(p)))
    tris: list[list[int]] = []
    guard = 0
    while len(idx) > 3 and guard < 10 * len(p) ** 2:
        guard += 1
        n = len(idx)
        for k in range(n):
            a, b, c = idx[(k - 1) % n], idx[k], idx[(k + 1) % n]
            if _cross2(p[b] - p[a], p[c] - p[b]) <= 0:
                continue  # reflex or flat vertex: not an ear
            tri = p[[a, b, c]]
            if any(_point_in(tri, p[m]) for m in idx if m not in (a, b, c)):
                continue
            tris.append([a, b, c])
            idx.pop(k)
            break
        else:  # pragma: no cover - a simple polygon always has an ear
            raise ArchdemInputError("a block outline could not be split into convex pieces")
    tris.append(idx)
    parts = [t[:] for t in tris]
    merged = True
    while merged:
        merged = False
        for i in range(len(parts)):
            for j in range(i + 1, len(parts)):
                u = _merge(parts[i], parts[j])
                if u is not None and is_convex(p[u]):
                    parts[i] = u
                    parts.pop(j)
                    merged = True
                    break
            if merged:
                break
    return tuple(p[q] for q in parts)


def _merge(u: list[int], v: list[int]) -> list[int] | None:
    """The union of two index rings sharing one edge (u has a->b, v has b->a), or None."""
    nu, nv = len(u), len(v)
    for i in range(nu):
        a, b = u[i], u[(i + 1) % nu]
        for j in range(nv):
            if v[j] == b and v[(j + 1) % nv] == a:
                return u[:i + 1] + [v[(j + 2 + k) % nv] for k in range(nv - 2)] + u[i + 1:]
    return None


def _clip(subject: np.ndarray, clip: np.ndarray) -> np.ndarray:
    """Sutherland-Hodgman: the part of convex ``subject`` inside convex ``clip`` (both ccw)."""
    out = subject
    n = len(clip)
    for k in range(n):
        if len(out) == 0:
            break
        a, b = clip[k], clip[(k + 1) % n]
        d = b - a
        inp, out = out, []
        m = len(inp)
        for i in range(m):
            p, q = inp[i], inp[(i + 1) % m]
            sp, sq = _cross2(d, p - a), _cross2(d, q - a)
            if sp >= 0:
                out.append(p)
            if (sp >= 0) != (sq >= 0):
                out.append(p + (q - p) * (sp / (sp - sq)))
        out = np.array(out) if out else np.zeros((0, 2))
    return out


def overlap_area(a: Sequence[np.ndarray], b: Sequence[np.ndarray]) -> float:
    """Area [m^2] common to two unions of convex pieces."""
    tot = 0.0
    for p in a:
        for q in b:
            r = _clip(p, q)
            if len(r) >= 3:
                tot += abs(signed_area(r))
    return tot


# ---------------------------------------------------------------------------------------------
# contacts
# ---------------------------------------------------------------------------------------------
def _edges(poly: np.ndarray):
    n = len(poly)
    return [(poly[k], poly[(k + 1) % n]) for k in range(n)]


def _contact(e1, e2, tol: float, verts: np.ndarray):
    """The common part of edge ``e1`` (of A) and ``e2`` (of B) when they face each other on one line
    within ``tol``: its two end points (exact vertices where they coincide with one) and A's outward
    normal; else None."""
    p0, p1 = e1
    q0, q1 = e2
    d = p1 - p0
    L = float(np.linalg.norm(d))
    u = d / L
    nrm = np.array([u[1], -u[0]])  # outward normal of a ccw polygon's edge
    if float(np.dot(q1 - q0, u)) >= 0:
        return None  # faces of touching blocks run opposite ways
    if abs(float(np.dot(q0 - p0, nrm))) > tol or abs(float(np.dot(q1 - p0, nrm))) > tol:
        return None
    s0, s1 = float(np.dot(q1 - p0, u)), float(np.dot(q0 - p0, u))
    lo, hi = max(0.0, s0), min(L, s1)
    if hi - lo <= tol:
        return None

    def snap(s: float) -> np.ndarray:
        pt = p0 + s * u
        near = verts[np.linalg.norm(verts - pt, axis=1) <= tol]
        return near[0].copy() if len(near) else pt

    return snap(lo), snap(hi), nrm


@dataclass
class _Contact:
    a: int  # block index (the one whose edge gives the normal)
    b: int  # block index, or -1 for a support
    p: np.ndarray
    q: np.ndarray
    n: np.ndarray  # from a to b
    support: int = -1  # which support when b is -1 (-1: the ground line)


def _near_pairs(polys: list[np.ndarray], supports: list[np.ndarray], tol: float) -> list[tuple[int, int]]:
    """``(i, j)`` with i < j blocks, or j = -1 - k for support k, whose boxes meet within ``tol``."""
    lo = np.array([p.min(0) for p in polys]) - tol
    hi = np.array([p.max(0) for p in polys]) + tol
    slo = np.array([s.min(0) for s in supports]).reshape(-1, 2) - tol
    shi = np.array([s.max(0) for s in supports]).reshape(-1, 2) + tol
    out = []
    for i in range(len(polys)):
        m = np.all((lo[i + 1:] <= hi[i]) & (hi[i + 1:] >= lo[i]), axis=1)
        out += [(i, i + 1 + int(j)) for j in np.flatnonzero(m)]
        ms = np.all((slo <= hi[i]) & (shi >= lo[i]), axis=1)
        out += [(i, -1 - int(k)) for k in np.flatnonzero(ms)]
    return out


def _find_contacts(polys: list[np.ndarray], supports: list[np.ndarray], tol: float) -> list[_Contact]:
    out: list[_Contact] = []
    for i, j in _near_pairs(polys, supports, tol):
        other = polys[j] if j >= 0 else supports[-1 - j]
        verts = np.vstack([polys[i], other])
        for e1 in _edges(polys[i]):
            for e2 in _edges(other):
                c = _contact(e1, e2, tol, verts)
                if c is not None:
                    out.append(_Contact(i, j if j >= 0 else -1, c[0], c[1], c[2], -1 - j if j < 0 else -1))
    return _merge_collinear(out, tol)


def _merge_collinear(cs: list[_Contact], tol: float) -> list[_Contact]:
    """One contact per straight common face: pieces of one line between the same two blocks joined."""
    out: list[_Contact] = []
    for c in cs:
        for o in out:
            if (o.a, o.b) == (c.a, c.b) and float(o.n @ c.n) > 1 - 1e-9 and abs(float((c.p - o.p) @ o.n)) <= tol:
                u = np.array([-o.n[1], o.n[0]])
                pts = [o.p, o.q, c.p, c.q]
                s = [float((x - o.p) @ u) for x in pts]
                if max(s[2], s[3]) >= min(s[0], s[1]) - tol and min(s[2], s[3]) <= max(s[0], s[1]) + tol:
                    o.p, o.q = pts[int(np.argmin(s))], pts[int(np.argmax(s))]
                    break
        else:
            out.append(c)
    return out


# ---------------------------------------------------------------------------------------------
# gaps: outlines that come close without a joint between them
# ---------------------------------------------------------------------------------------------
def _thickness(poly: np.ndarray) -> float:
    """Twice the area over the perimeter [m]: about the smaller side of a block, whatever its shape."""
    per = float(np.linalg.norm(np.diff(np.vstack([poly, poly[:1]]), axis=0), axis=1).sum())
    return 2.0 * abs(signed_area(poly)) / per


def _closest(a: np.ndarray, b: np.ndarray) -> tuple[float, np.ndarray]:
    """Distance between two outlines that do not overlap, and the middle of the gap: the mean of the
    mid-points of every closest pair (a vertex of one, a point of the other's edge), so that two parallel
    faces give the middle of their common part, not a corner."""
    dists, mids = [], []
    for pts, poly in ((a, b), (b, a)):
        for p0, p1 in _edges(poly):
            d = p1 - p0
            t = np.clip((pts - p0) @ d / float(d @ d), 0.0, 1.0)
            foot = p0 + t[:, None] * d
            dists.append(np.linalg.norm(pts - foot, axis=1))
            mids.append(0.5 * (pts + foot))
    dist, mid = np.concatenate(dists), np.vstack(mids)
    best = float(dist.min())
    return best, mid[dist <= best * (1 + 1e-9) + 1e-15].mean(axis=0)


def _find_gaps(polys: list[np.ndarray], names: list[str], supports: list[np.ndarray], contacts: list[_Contact],
               tol: float) -> list[Gap]:
    """Pairs of outlines (block-block, block-support, block-ground line) with no joint between them that
    come closer than GAP_FRACTION of the thinner block, with nothing drawn in between."""
    thick = [_thickness(p) for p in polys]
    reach = GAP_FRACTION * max(thick)
    joined = {(c.a, c.b) for c in contacts if c.b >= 0} | {(c.a, -1 - c.support) for c in contacts if c.support >= 0}
    shapes = polys + supports
    lo = np.array([p.min(0) for p in shapes])
    hi = np.array([p.max(0) for p in shapes])

    def filled(m: np.ndarray, skip: set[int]) -> bool:
        near = np.flatnonzero(np.all((lo <= m) & (hi >= m), axis=1))
        return any(_point_in(shapes[k], m) for k in near if k not in skip)

    out: list[Gap] = []
    for i, j in _near_pairs(polys, supports, reach) if reach > tol else ():
        if (i, j) in joined:
            continue
        other = polys[j] if j >= 0 else supports[-1 - j]
        lim = GAP_FRACTION * (min(thick[i], thick[j]) if j >= 0 else thick[i])
        d, mid = _closest(polys[i], other)
        if tol < d <= lim and not filled(mid, {i, j if j >= 0 else len(polys) - 1 - j}):
            out.append(Gap(names[i], names[j], d, (float(mid[0]), float(mid[1]))) if j >= 0 else
                       Gap(names[i], f"support {-j}", d, (float(mid[0]), float(mid[1])), "support"))
    if not supports:  # the ground is the line through the lowest vertex
        y0 = min(float(p[:, 1].min()) for p in polys)
        grounded = {c.a for c in contacts if c.b < 0}
        for i, p in enumerate(polys):
            k = int(np.argmin(p[:, 1]))
            d = float(p[k, 1]) - y0
            mid = np.array([p[k, 0], y0 + 0.5 * d])
            if i not in grounded and tol < d <= GAP_FRACTION * thick[i] and not filled(mid, {i}):
                out.append(Gap(names[i], "the ground", d, (float(mid[0]), float(mid[1])), "ground"))
    return sorted(out, key=lambda g: g.distance_m)


def _gap_note(gaps: Sequence[Gap], names: Sequence[str] | None = None) -> str:
    """``" (blocks B4 and B5 are 5.0 mm apart)"``: the gaps that involve ``names`` (all: None), or ''."""
    hit = [g for g in gaps if names is None or g.a in names or (g.kind == "block" and g.b in names)]
    return f" ({gaps_text(hit)})" if hit else ""


def _ground_contacts(polys: list[np.ndarray], tol: float) -> list[_Contact]:
    """Without supports: every block edge lying on the horizontal line through the lowest vertex."""
    y0 = min(float(p[:, 1].min()) for p in polys)
    out = []
    for i, p in enumerate(polys):
        for a, b in _edges(p):
            if abs(a[1] - y0) <= tol and abs(b[1] - y0) <= tol and b[0] > a[0]:  # ccw: a bottom face runs left to right
                out.append(_Contact(i, -1, a.copy(), b.copy(), np.array([0.0, -1.0])))
    return out


# ---------------------------------------------------------------------------------------------
# the assembly
# ---------------------------------------------------------------------------------------------
def assemble(blocks: Sequence[DrawnBlock], supports: Sequence[np.ndarray] = (), density: float = DRAWN_DENSITY,
             depth: float | None = None, tol: float | None = None, joint_labels: Sequence[tuple[str, np.ndarray]] = (),
             source: dict | None = None, length_scale: float | None = None, size: float | None = None) -> DrawnAssembly:
    """The assembly of ``blocks`` [m] standing on ``supports`` (fixed polygons [m]; none: the ground is
    the horizontal line through the lowest vertex), ``density`` [kg/m^3], ``depth`` [m] for blocks
    that do not give their own; ``tol`` [m]: how far apart two faces may be and still touch
    (default RELATIVE_TOLERANCE x the largest extent); ``joint_labels``: (name, point) naming the
    joint whose mid-point is within ``tol`` of the point; ``length_scale`` / ``size`` [m]: the
    analyses' length and the collapse criterion's (default: half the largest extent; the shortest
    joint). Outlines that come close without touching are the assembly's ``gaps`` (:class:`Gap`),
    named in the refusal of a block they leave without support."""
    if not (isinstance(density, (int, float)) and math.isfinite(density) and density > 0):
        raise ArchdemInputError(f"density must be > 0 kg/m^3, got {density!r}")
    if depth is not None and not (isinstance(depth, (int, float)) and math.isfinite(depth) and depth > 0):
        raise ArchdemInputError(f"depth must be a positive length in m, got {depth!r}")
    if not blocks:
        raise ArchdemInputError("the drawing holds no blocks (closed outlines)")
    if len(blocks) > MAX_BLOCKS:
        raise ArchdemInputError(f"the drawing holds {len(blocks)} blocks, more than {MAX_BLOCKS}")
    names = [b.name for b in blocks]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ArchdemInputError(f"block name {dup[0]!r} is given to more than one block")
    allpts = np.vstack([np.asarray(b.outline, float).reshape(-1, 2) for b in blocks])
    if not np.all(np.isfinite(allpts)):
        raise ArchdemInputError("the drawing holds coordinates that are not finite numbers")
    extent = float(max(np.ptp(allpts[:, 0]), np.ptp(allpts[:, 1])))
    if not extent > 0:
        raise ArchdemInputError("the drawing's blocks have zero extent")
    tol = RELATIVE_TOLERANCE * extent if tol is None else float(tol)
    if not (math.isfinite(tol) and 0 < tol < 0.1 * extent):
        raise ArchdemInputError(f"contact tolerance must be a positive length below a tenth of the drawing, got {tol!r}")

    polys = [_clean(b.name, b.outline, tol) for b in blocks]
    pieces: list[tuple[np.ndarray, ...]] = []
    for b, poly in zip(blocks, polys):
        if b.pieces:
            ps = []
            for q in b.pieces:
                q = _clean(f"{b.name} (a piece)", q, tol)
                if not is_convex(q):
                    raise ArchdemInputError(f"block {b.name}: a piece given for it is not convex")
                ps.append(q)
            area = abs(signed_area(poly))
            if abs(sum(abs(signed_area(q)) for q in ps) - area) > 1e-6 * area:
                raise ArchdemInputError(f"block {b.name}: the pieces given for it do not make up its outline")
            pieces.append(tuple(ps))
        else:
            pieces.append(convex_pieces(poly))
    sups = [_clean(f"support {k + 1}", s, tol) for k, s in enumerate(supports)]
    sup_pieces = [convex_pieces(s) for s in sups]

    # overlaps: more than a sliver of tolerance along the shorter perimeter
    for i, j in _near_pairs(polys, sups, 0.0):
        per_i = float(np.linalg.norm(np.diff(np.vstack([polys[i], polys[i][:1]]), axis=0), axis=1).sum())
        ov = overlap_area(pieces[i], pieces[j] if j >= 0 else sup_pieces[-1 - j])
        if ov > tol * per_i:
            what = f"block {names[j]}" if j >= 0 else f"support {-j}"
            raise ArchdemInputError(f"blocks overlap: block {names[i]} and {what} share {ov:.3g} m^2")

    depths = []
    for b in blocks:
        d = b.depth if b.depth is not None else depth
        if d is None:
            raise ArchdemInputError(f"block {b.name} has no depth: give the depth (--depth) or draw it on a "
                                    "layer that states it")
        if not (math.isfinite(d) and d > 0):
            raise ArchdemInputError(f"block {b.name}: depth must be a positive length, got {d!r}")
        depths.append(float(d))

    contacts = _find_contacts(polys, sups, tol) if sups else (_find_contacts(polys, [], tol) + _ground_contacts(polys, tol))
    gaps = _find_gaps(polys, names, sups, contacts, tol)
    touched = {c.a for c in contacts} | {c.b for c in contacts}
    loose = [names[i] for i in range(len(polys)) if i not in touched]
    if loose:
        raise ArchdemInputError(f"block {loose[0]} touches no other block and no support"
                                + (f" (nor do {len(loose) - 1} more)" if len(loose) > 1 else "") + _gap_note(gaps, loose))
    if not any(c.b < 0 for c in contacts):
        raise ArchdemInputError("no block stands on a support or on the ground"
                                + _gap_note([g for g in gaps if g.kind != "block"]))
    _check_grounded(len(polys), contacts, names, gaps)

    order, links, chain = _order(polys, contacts)
    pos = {blk: k for k, blk in enumerate(order)}
    bodies, blks = [], []
    for k, i in enumerate(order):
        o = polys[i]
        blks.append(Block(names[i], o, pieces[i], np.zeros((0, 2)), np.zeros((0, 2))))
        bodies.append(_make_body(k, names[i], (names[i],), o, pieces[i], polygon_properties(o), float(density), depths[i]))
    joints = []
    for k, (c, a, b) in enumerate(links):
        ia, ib = (pos[a] if a >= 0 else -1), (pos[b] if b >= 0 else -1)
        n = c.n if (a, b) == (c.a, c.b) else -c.n  # the direction from a to b
        p, q = (c.p, c.q) if _cross2(n, c.q - c.p) > 0 else (c.q, c.p)
        joints.append(Joint(k, f"J{k}", ia, ib, p, q, joint_normal(p, q), 0.0))
    joints = _name_joints(joints, joint_labels, tol)
    lscale = 0.5 * extent if length_scale is None else float(length_scale)
    sz = min(j.length for j in joints) if size is None else float(size)
    src = dict(source or {})
    src.setdefault("tolerance_m", tol)
    return DrawnAssembly(None, DRAWN_CONFIG, "drawn", 0, 0.0, float(density), 0, tuple(blks), tuple(bodies),
                         tuple(joints), np.zeros(0), 1.0, False, None, src, float(lscale), float(sz), bool(chain),
                         tuple(gaps))


def _check_grounded(n: int, contacts: list[_Contact], names: list[str], gaps: Sequence[Gap] = ()) -> None:
    """Every block connected to the ground through joints (else the first loose group, in one line)."""
    adj: dict[int, set[int]] = {i: set() for i in range(-1, n)}
    for c in contacts:
        adj[c.a].add(c.b)
        adj[c.b].add(c.a)
    seen, stack = {-1}, [-1]
    while stack:
        for m in adj[stack.pop()]:
            if m not in seen:
                seen.add(m)
                stack.append(m)
    rest = [names[i] for i in range(n) if i not in seen]
    if rest:
        raise ArchdemInputError(f"blocks {', '.join(rest[:5])}{' ...' if len(rest) > 5 else ''} touch each other but "
                                "not the ground or a support" + _gap_note(gaps, rest))


def _order(polys: list[np.ndarray], contacts: list[_Contact]):
    """Body order, ``(contact, a, b)`` links in joint order, and whether the blocks make one chain."""
    n = len(polys)
    deg = {i: 0 for i in range(n)}
    for c in contacts:
        for x in (c.a, c.b):
            if x >= 0:
                deg[x] += 1
    base = [c for c in contacts if c.b < 0]
    pairs = {(min(c.a, c.b), max(c.a, c.b)) for c in contacts if c.b >= 0}
    is_chain = (len(base) == 2 and all(d == 2 for d in deg.values()) and len(contacts) == n + 1
                and len(pairs) == len([c for c in contacts if c.b >= 0]))
    if is_chain:
        mid = [0.5 * (c.p + c.q) for c in base]
        start = min(range(2), key=lambda k: (float(mid[k][0]), float(mid[k][1])))
        first = base[start]
        order, links, cur, used = [first.a], [(first, -1, first.a)], first.a, {id(first)}
        while True:
            nxt = next(c for c in contacts if id(c) not in used and cur in (c.a, c.b))
            used.add(id(nxt))
            other = nxt.b if nxt.a == cur else nxt.a
            links.append((nxt, cur, other))
            if other < 0:
                break
            order.append(other)
            cur = other
        if len(order) == n:
            return order, links, True
    cen = [polygon_properties(p).centroid for p in polys]
    order = sorted(range(n), key=lambda i: (float(cen[i][0]), float(cen[i][1])))
    pos = {blk: k for k, blk in enumerate(order)}

    def link(c: _Contact):
        if c.b < 0:
            return (c, -1, c.a)
        return (c, c.a, c.b) if pos[c.a] < pos[c.b] else (c, c.b, c.a)

    links = [link(c) for c in contacts]
    links.sort(key=lambda L: (pos[L[1]] if L[1] >= 0 else -1, pos[L[2]] if L[2] >= 0 else n,
                              float(0.5 * (L[0].p[0] + L[0].q[0]))))
    return order, links, False


def _name_joints(joints: list[Joint], labels: Sequence[tuple[str, np.ndarray]], tol: float) -> list[Joint]:
    """Joints named by the labels placed at their mid-points; the others keep ``J<index>``."""
    if not labels:
        return joints
    out = list(joints)
    used: set[str] = set()
    for name, pt in labels:
        pt = np.asarray(pt, float)
        hit = [k for k, j in enumerate(joints) if np.linalg.norm(0.5 * (j.p_i + j.p_e) - pt) <= max(tol, 1e-12)]
        if len(hit) == 1:
            if name in used:
                raise ArchdemInputError(f"joint label {name!r} is given to more than one joint")
            used.add(name)
            out[hit[0]] = replace(out[hit[0]], name=name)
    names = [j.name for j in out]
    dup = sorted({x for x in names if names.count(x) > 1})
    if dup:
        raise ArchdemInputError(f"joint name {dup[0]!r} names two joints (a label and a generated name)")
    return out
