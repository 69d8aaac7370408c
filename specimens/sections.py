"""Plane-section properties of regions bounded by straight segments and circular arcs.

Green's theorem turns area, first and second moments into boundary integrals.
Every edge is integrated with a 24-point Gauss-Legendre rule: exact for straight
edges (the integrands are polynomials of degree <= 4) and converged to round-off
for the short circular arcs of an arch ring (the integrands are smooth
trigonometric polynomials). No mesh sums.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence, Union

import numpy as np

_GL_X, _GL_W = np.polynomial.legendre.leggauss(24)


@dataclass(frozen=True)
class Segment:
    p0: tuple[float, float]
    p1: tuple[float, float]

    def sample(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Points and derivatives at parameters ``u`` in [0, 1]."""
        p0, p1 = np.asarray(self.p0), np.asarray(self.p1)
        d = p1 - p0
        x = p0[0] + u * d[0]
        y = p0[1] + u * d[1]
        return x, y, np.full_like(u, d[0]), np.full_like(u, d[1])


@dataclass(frozen=True)
class Arc:
    """Circular arc about ``centre`` of radius ``r`` from angle ``a0`` to ``a1`` (either sense)."""

    centre: tuple[float, float]
    r: float
    a0: float
    a1: float

    def sample(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        a = self.a0 + u * (self.a1 - self.a0)
        da = self.a1 - self.a0
        x = self.centre[0] + self.r * np.cos(a)
        y = self.centre[1] + self.r * np.sin(a)
        return x, y, -self.r * np.sin(a) * da, self.r * np.cos(a) * da


Edge = Union[Segment, Arc]


@dataclass(frozen=True)
class SectionProperties:
    """Area [m^2], centroid [m] and centroidal second moments [m^4] of a plane region.

    ``Ixx = int (y - yc)^2 dA``, ``Iyy = int (x - xc)^2 dA``, ``Ixy = int (x - xc)(y - yc) dA``.
    """

    area: float
    centroid: np.ndarray
    Ixx: float
    Iyy: float
    Ixy: float

    @property
    def polar(self) -> float:
        """Centroidal polar moment ``Ixx + Iyy`` [m^4]."""
        return self.Ixx + self.Iyy


def region_properties(edges: Sequence[Edge]) -> SectionProperties:
    """Properties of the region enclosed by a closed chain of edges (either orientation)."""
    u = 0.5 * (_GL_X + 1.0)
    w = 0.5 * _GL_W
    A = Sx = Sy = Jxx = Jyy = Jxy = 0.0
    for edge in edges:
        x, y, dx, dy = edge.sample(u)
        A += np.sum(w * 0.5 * (x * dy - y * dx))
        Sx += np.sum(w * 0.5 * x * x * dy)  # int x dA
        Sy += np.sum(w * -0.5 * y * y * dx)  # int y dA
        Jyy += np.sum(w * x**3 / 3.0 * dy)  # int x^2 dA
        Jxx += np.sum(w * -(y**3) / 3.0 * dx)  # int y^2 dA
        Jxy += np.sum(w * 0.5 * x * x * y * dy)  # int x y dA
    if A < 0:  # clockwise chain: flip every integral
        A, Sx, Sy, Jxx, Jyy, Jxy = -A, -Sx, -Sy, -Jxx, -Jyy, -Jxy
    if A <= 0:
        raise ValueError("degenerate region (zero area)")
    xc, yc = Sx / A, Sy / A
    return SectionProperties(
        area=float(A),
        centroid=np.array([xc, yc]),
        Ixx=float(Jxx - A * yc * yc),
        Iyy=float(Jyy - A * xc * xc),
        Ixy=float(Jxy - A * xc * yc),
    )


def polygon_properties(poly: np.ndarray) -> SectionProperties:
    """Exact properties of a simple polygon (vertices ``(n, 2)``, either orientation)."""
    poly = np.asarray(poly, dtype=float)
    edges = [Segment(tuple(poly[k]), tuple(poly[(k + 1) % len(poly)])) for k in range(len(poly))]
    return region_properties(edges)


def signed_area(poly: np.ndarray) -> float:
    """Shoelace signed area (positive for counter-clockwise vertices)."""
    x, y = np.asarray(poly, dtype=float).T
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def is_convex(poly: np.ndarray, tol: float = 1e-12) -> bool:
    """True if the polygon (counter-clockwise) turns left (or goes straight) at every vertex."""
    p = np.asarray(poly, dtype=float)
    a = np.roll(p, 1, axis=0)
    c = np.roll(p, -1, axis=0)
    cross = (p[:, 0] - a[:, 0]) * (c[:, 1] - p[:, 1]) - (p[:, 1] - a[:, 1]) * (c[:, 0] - p[:, 0])
    scale = max(np.ptp(p[:, 0]), np.ptp(p[:, 1])) ** 2
    return bool(np.all(cross >= -tol * scale))


def mirror_edges(edges: Sequence[Edge]) -> list[Edge]:
    """Mirror a boundary about x = 0 (right half -> left half)."""
    out: list[Edge] = []
    for ed in edges:
        if isinstance(ed, Segment):
            out.append(Segment((-ed.p0[0], ed.p0[1]), (-ed.p1[0], ed.p1[1])))
        else:
            out.append(Arc((-ed.centre[0], ed.centre[1]), ed.r, math.pi - ed.a0, math.pi - ed.a1))
    return out


def combine(parts: Sequence[SectionProperties]) -> SectionProperties:
    """Properties of the union of disjoint regions (parallel-axis theorem)."""
    A = sum(p.area for p in parts)
    c = sum(p.area * p.centroid for p in parts) / A
    Ixx = sum(p.Ixx + p.area * (p.centroid[1] - c[1]) ** 2 for p in parts)
    Iyy = sum(p.Iyy + p.area * (p.centroid[0] - c[0]) ** 2 for p in parts)
    Ixy = sum(p.Ixy + p.area * (p.centroid[0] - c[0]) * (p.centroid[1] - c[1]) for p in parts)
    return SectionProperties(float(A), np.asarray(c, dtype=float), float(Ixx), float(Iyy), float(Ixy))
