"""Engine-neutral description of a rigid-block model: bodies, joints and the fixed base.

Frame: the arch frame of :mod:`specimens` — x horizontal, y **up**, z out of plane (the
width), origin at mid-span on the springing line. Every engine builds the model in this
frame; gravity is a vector in it (``(0, -g, 0)`` at rest, see :mod:`dem.core.loads`).

A body is a union of convex prisms (each a convex counter-clockwise polygon in x-y extruded
over ``width`` along z, centred on z = 0), with its mass, centroid and centroidal inertia in
the arch frame (:func:`dem.core.engines.inputs.principal_frame` gives the rotation to the principal
axes, which is what engines such as PyBullet want as the body frame). Joints are the interfaces the detection
reads (end points at the intrados/extrados, unit normal from body ``a`` to body ``b``;
index ``-1`` is the base).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from specimens.blocks import Assembly, discretise
from specimens.catalogue import Specimen, get_specimen
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch


@dataclass(frozen=True)
class BodySpec:
    """One rigid body: convex pieces [m], mass [kg], centroid [m], centroidal inertia [kg m^2]."""

    name: str
    pieces: tuple[np.ndarray, ...]  # convex ccw polygons (n, 2) in the arch frame
    width: float
    mass: float
    centroid: np.ndarray  # (3,), z = 0 for prisms centred on z = 0
    inertia: np.ndarray  # (3, 3) centroidal, arch frame
    outline: np.ndarray  # (n, 2) outline polygon, for drawings and detection

    def points(self) -> np.ndarray:
        """Outline points at z = 0 plus the two z faces of the outline, (m, 3) [m]: the
        points whose displacements the collapse criterion watches."""
        o = np.asarray(self.outline, dtype=float)
        hw = self.width / 2
        return np.vstack([np.c_[o, np.full(len(o), -hw)], np.c_[o, np.full(len(o), hw)]])


@dataclass(frozen=True)
class JointSpec:
    """An interface: ``a`` and ``b`` body indices (-1 = base), intrados/extrados end points (2,) of
    the part that touches (the whole joint unless the blocks are relieved)."""

    name: str
    a: int
    b: int
    p_i: np.ndarray
    p_e: np.ndarray
    normal: np.ndarray  # unit, in-plane, from a to b

    @property
    def length(self) -> float:
        return float(np.linalg.norm(np.asarray(self.p_e) - np.asarray(self.p_i)))

    @property
    def is_base(self) -> bool:
        return self.a < 0 or self.b < 0


@dataclass(frozen=True)
class BaseSpec:
    """The fixed base (support): convex prisms of depth ``width`` along z, centred on z = 0."""

    pieces: tuple[np.ndarray, ...]
    width: float


@dataclass(frozen=True)
class Model:
    """A complete engine-neutral model.

    ``size`` is the length scale of the collapse criterion [m] (the ring thickness of an arch,
    the height of a single block); ``crown`` the index of the body whose displacement is
    reported as "the crown"; ``source`` the parameters the model was built from; ``assembly``
    the :class:`specimens.blocks.Assembly` it was built from, if any (limit analysis of the same
    blocks: the tilt test's first estimate, the threshold's static onset).
    """

    name: str
    bodies: tuple[BodySpec, ...]
    joints: tuple[JointSpec, ...]
    base: BaseSpec
    size: float
    crown: int
    source: dict = field(default_factory=dict)
    assembly: Any = field(default=None, repr=False, compare=False)
    ties: tuple = ()  # dem.core.ties.TieSpec: elastic-perfectly-plastic ties between bodies

    @property
    def n_bodies(self) -> int:
        return len(self.bodies)

    @property
    def total_mass(self) -> float:
        return float(sum(b.mass for b in self.bodies))

    def joint_index(self, name: str) -> int:
        for k, j in enumerate(self.joints):
            if j.name == name:
                return k
        raise KeyError(name)


def is_relieved(model: Model) -> bool:
    """True if the model's joints touch on part of their depth (effective contact or bands)."""
    return float(model.source.get("contact", 1.0)) < 1.0 or bool(model.source.get("bands"))


def _base_pads(xmin: float, xmax: float, depth: float, margin: float, top: float = 0.0) -> np.ndarray:
    return np.array([[xmin - margin, top - depth], [xmax + margin, top - depth], [xmax + margin, top],
                     [xmin - margin, top]])


def _specs(assembly) -> tuple[tuple[BodySpec, ...], tuple[JointSpec, ...]]:
    """Body and joint specs of anything with specimens' ``bodies`` and ``joints`` (an assembly, a frame)."""
    bodies = tuple(
        BodySpec(b.name, tuple(np.asarray(p, float) for p in b.pieces), float(b.width), float(b.mass),
                 np.array([b.centroid[0], b.centroid[1], 0.0]), np.asarray(b.inertia, float),
                 np.asarray(b.outline, float))
        for b in assembly.bodies
    )
    # the detection reads each joint at the ends of its contact: where a hinge of a relieved joint turns
    joints = tuple(JointSpec(j.name, int(j.a), int(j.b), *(np.asarray(p, float) for p in j.contact_points),
                             np.asarray(j.normal, float)) for j in assembly.joints)
    return bodies, joints


def _base(assembly, margin: float, width: float) -> BaseSpec:
    """Pads under the base joints: top faces at the joints' level, ``margin`` beyond each end and deep."""
    pads = []
    for j in assembly.joints:
        if j.is_base:
            xs = sorted([float(j.p_i[0]), float(j.p_e[0])])
            pads.append(_base_pads(xs[0], xs[1], margin, margin, float(j.p_i[1])))
    return BaseSpec(tuple(pads), width)


def from_assembly(assembly, name: str | None = None, base_width_factor: float = 2.0) -> Model:
    """Model of a :class:`specimens.blocks.Assembly` (glued or free, any block shape, on piers or not).

    Bodies collide on the assembly's (possibly relieved) pieces with the full blocks' masses and
    inertias. The base is two pads whose top faces are the base joints' level (the springing line,
    or the piers' foot), each reaching one ring thickness beyond the base joint,
    ``base_width_factor`` times the widest body deep along z (so that out-of-plane motion never
    runs off the support).
    """
    arch = assembly.arch
    bodies, joints = _specs(assembly)
    t = float(assembly.size)  # the ring thickness; a drawn assembly's own length (specimens.drawn)
    base = _base(assembly, t, base_width_factor * max(b.width for b in bodies))
    crown = assembly.crown_index
    src = ({"kind": "arch", "arch": {k: float(v) for k, v in arch.describe().items()}} if arch is not None
           else {"kind": "drawing"}) | assembly.parameters()
    return Model(name or "arch", bodies, joints, base, t, crown, src, assembly)


def frame_model(frame, name: str = "frame", base_width_factor: float = 2.0) -> Model:
    """Model of a :class:`specimens.frame.Frame` (lintel on two piers); the collapse criterion's
    length is the piers' height, as a single block's is its height (a pier overturns once its top
    has moved about its width: a shorter length would call a recoverable rocking a collapse)."""
    bodies, joints = _specs(frame)
    size = 2.0 * float(frame.h)
    base = _base(frame, size, base_width_factor * max(b.width for b in bodies))
    return Model(name, bodies, joints, base, size, 1, {"kind": "frame", **frame.parameters()}, frame)


def as_model(target: Any, config: str = "glued", name: str | None = None, **discretise_kw) -> Model:
    """The model of ``target``: a catalogue id (``"Sh06-Sd015"``), a :class:`specimens.catalogue.Specimen`,
    a :class:`specimens.geometry.PointedArch` (cut by :func:`specimens.blocks.discretise` with ``config``
    and ``discretise_kw``), an :class:`specimens.blocks.Assembly`, or a :class:`Model` (returned as is).
    ``name`` defaults to the specimen id, or ``"arch"``."""
    if isinstance(target, Model):
        return target
    if isinstance(target, str):
        target = get_specimen(target)
    if isinstance(target, Specimen):
        name, target = name or target.id, target.arch
    if isinstance(target, PointedArch):
        target = discretise(target, config=config, **discretise_kw)
    if not isinstance(target, Assembly):
        raise ArchdemInputError(f"expected a specimen id, Specimen, PointedArch, Assembly or Model, got {type(target).__name__}")
    return from_assembly(target, name=name)


def single_block(b: float, h: float, width: float = 0.1, density: float = 500.0) -> Model:
    """The model of :func:`specimens.frame.single_block`: a rectangular block ``b`` (along x) by ``h``
    (along y) by ``width`` [m] — full dimensions here — on a flat base.

    Its base joint ``B0`` runs from the left corner (``p_i``) to the right corner (``p_e``).
    """
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.frame import single_block as block

    for nm, v in (("block base b", b), ("block height h", h), ("block width", width), ("density", density)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ArchdemInputError(f"{nm} must be a positive number, got {v!r}")
    bodies, joints = _specs(block(b / 2, h / 2, density, width))
    L = 4 * max(b, h)
    base = BaseSpec((_base_pads(-L / 2, L / 2, max(b, h), 0.0),), 4 * width)
    # no assembly: a block's tilt test starts with the ramp scan (docs/validation.md#3-single-block), not from an LP
    return Model("block", bodies, joints, base, h, 0,
                 {"kind": "block", "b": b, "h": h, "width": width, "density": density})


def side_by_side(model: Model, copies: int, gap: float | None = None) -> Model:
    """``copies`` independent copies of ``model`` offset along z (for speed benchmarks).

    Joint names get a ``#k`` suffix; the base pads are widened to carry all copies.
    """
    if copies < 1:
        raise ArchdemInputError(f"copies must be >= 1, got {copies}")
    w = model.bodies[0].width
    dz = w + (gap if gap is not None else w)
    bodies, joints = [], []
    n = model.n_bodies
    for k in range(copies):
        z = (k - (copies - 1) / 2) * dz
        for bd in model.bodies:
            c = bd.centroid.copy()
            c[2] = z
            bodies.append(BodySpec(f"{bd.name}#{k}", bd.pieces, bd.width, bd.mass, c, bd.inertia, bd.outline))
        for j in model.joints:
            joints.append(JointSpec(f"{j.name}#{k}", j.a + n * k if j.a >= 0 else -1, j.b + n * k if j.b >= 0 else -1,
                                    j.p_i, j.p_e, j.normal))
    base = BaseSpec(model.base.pieces, copies * dz + model.base.width)
    return Model(f"{model.name}x{copies}", tuple(bodies), tuple(joints), base, model.size, model.crown,
                 {**model.source, "copies": copies, "z_spacing": dz})


def body_z(body: BodySpec) -> float:
    """Out-of-plane offset of a body's prisms (non-zero only for side-by-side copies)."""
    return float(body.centroid[2])
