"""The rocking frame: a rigid lintel on two free-standing piers (docs/physics/geometry.md#15-the-rocking-frame).

The validation structure of arches on piers: its closed forms (static onset, equation of
motion, restitution; docs/physics/dynamics.md#11-the-rocking-frame) are known exactly. It is built
with the bodies and joints of an arch on one-course piers, named the same way: piers ``LP1`` and
``RP1``, lintel ``C``; joints ``LP0`` (left pier base), ``L0``, ``R0`` (pier tops), ``RP0``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from specimens.blocks import DEFAULT_DENSITY, Body, Joint, _make_body
from foundation.errors import ArchdemInputError
from specimens.sections import polygon_properties


@dataclass(frozen=True)
class Frame:
    """Two piers ``2b`` wide and ``2h`` tall (standing on y = -2h, tops on y = 0), ``span`` apart
    (clear), carrying a lintel ``beam_height`` deep over their full tops [m]; ``width`` out of plane."""

    b: float
    h: float
    span: float
    beam_height: float
    density: float
    beam_density: float
    width: float
    bodies: tuple[Body, ...]
    joints: tuple[Joint, ...]
    contact: float = 1.0

    @property
    def length_scale(self) -> float:
        return 2.0 * self.h

    @property
    def gamma(self) -> float:
        """Lintel mass over the two piers' mass (the frame's mass ratio)."""
        return self.bodies[1].mass / (self.bodies[0].mass + self.bodies[2].mass)

    def parameters(self) -> dict:
        return {"b": self.b, "h": self.h, "span": self.span, "beam_height": self.beam_height,
                "density": self.density, "beam_density": self.beam_density, "width": self.width}


def rocking_frame(b: float, h: float, span: float, beam_height: float, density: float = DEFAULT_DENSITY,
                  beam_density: float | None = None, width: float = 0.1) -> Frame:
    """The frame of piers ``2b`` by ``2h`` [m], clear ``span`` [m], lintel ``beam_height`` [m] deep;
    ``beam_density`` [kg/m^3] (default ``density``) sets the lintel-to-piers mass ratio."""
    beam_density = density if beam_density is None else beam_density
    for name, v in (("b", b), ("h", h), ("span", span), ("beam height", beam_height), ("density", density),
                    ("beam density", beam_density), ("width", width)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ArchdemInputError(f"frame {name} must be a positive number, got {v!r}")
    xi, xo = span / 2, span / 2 + 2 * b

    def rect(x0, x1, y0, y1):
        return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], float)

    shapes = (("LP1", rect(-xo, -xi, -2 * h, 0.0), density), ("C", rect(-xo, xo, 0.0, beam_height), beam_density),
              ("RP1", rect(xi, xo, -2 * h, 0.0), density))
    bodies = tuple(_make_body(k, name, (name,), o, (o,), polygon_properties(o), rho, width)
                   for k, (name, o, rho) in enumerate(shapes))
    up, down = np.array([0.0, 1.0]), np.array([0.0, -1.0])
    spec = (("LP0", -1, 0, -1, -2 * h, up), ("L0", 0, 1, -1, 0.0, up), ("R0", 1, 2, 1, 0.0, down),
            ("RP0", 2, -1, 1, -2 * h, down))
    joints = tuple(Joint(k, name, a, bb, np.array([s * xi, y]), np.array([s * xo, y]), n, 0.0)
                   for k, (name, a, bb, s, y, n) in enumerate(spec))
    return Frame(float(b), float(h), float(span), float(beam_height), float(density), float(beam_density),
                 float(width), bodies, joints)


@dataclass(frozen=True)
class Block:
    """A rectangular block ``2b`` wide and ``2h`` tall [m], ``width`` out of plane, on the base joint
    ``B0`` (its bottom face, from the left corner to the right)."""

    b: float
    h: float
    width: float
    bodies: tuple[Body, ...]
    joints: tuple[Joint, ...]
    contact: float = 1.0

    @property
    def length_scale(self) -> float:
        return 2.0 * self.h


def single_block(b: float, h: float, density: float = DEFAULT_DENSITY, width: float = 0.1) -> Block:
    """The block of half-width ``b`` and half-height ``h`` [m] standing on y = 0."""
    for name, v in (("half-width b", b), ("half-height h", h), ("density", density), ("width", width)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ArchdemInputError(f"block {name} must be a positive number, got {v!r}")
    o = np.array([[-b, 0.0], [b, 0.0], [b, 2 * h], [-b, 2 * h]], float)
    body = _make_body(0, "B", ("B",), o, (o,), polygon_properties(o), density, width)
    joint = Joint(0, "B0", -1, 0, np.array([-b, 0.0]), np.array([b, 0.0]), np.array([0.0, 1.0]), 0.0)
    return Block(float(b), float(h), float(width), (body,), (joint,))
