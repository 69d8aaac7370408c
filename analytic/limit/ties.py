"""Steel tie-rods across an arch or an arch on piers (docs/physics/assessment.md#8-tie-rods).

A tie at height ``height`` above the springing line (negative: in the piers) runs between the
structure's two outer faces and is anchored there, on the bodies those points belong to. It is
rigid-plastic in the limit analysis: a tension between 0 and its yield force ``A f_y`` (a tie cannot
push); in the static LP it is one more unknown between the two bodies, in the mechanism it does the
work ``A f_y dL`` where the mechanism lengthens it (none where it shortens it: it goes slack). A
prestress does not change the collapse of a rigid-plastic tie; it is kept for the record.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from foundation.errors import ArchdemInputError

#: Accepted ranges: cross-section area [m^2], yield strength [Pa].
AREA_MAX, FY_MAX = 0.1, 2000e6


@dataclass(frozen=True)
class Tie:
    """A tie at ``height`` [m] above the springing line, of cross-section ``area`` [m^2], yield strength
    ``fy`` [Pa] and ``prestress`` [N] (below its yield force)."""

    height: float
    area: float
    fy: float
    prestress: float = 0.0

    def __post_init__(self) -> None:
        if not (isinstance(self.height, (int, float)) and math.isfinite(self.height)):
            raise ArchdemInputError(f"tie height must be a finite number of metres, got {self.height!r}")
        if not (isinstance(self.area, (int, float)) and math.isfinite(self.area) and 0 < self.area <= AREA_MAX):
            raise ArchdemInputError(f"tie area must be positive, at most {AREA_MAX * 1e6:g} mm^2, got "
                                    f"{self.area * 1e6 if isinstance(self.area, (int, float)) else self.area!r} mm^2")
        if not (isinstance(self.fy, (int, float)) and math.isfinite(self.fy) and 0 < self.fy <= FY_MAX):
            raise ArchdemInputError(f"tie yield strength must be in (0, {FY_MAX / 1e6:g}] MPa, got {self.fy!r} Pa")
        if not (isinstance(self.prestress, (int, float)) and math.isfinite(self.prestress)
                and 0 <= self.prestress < self.force):
            raise ArchdemInputError(f"tie prestress must be in [0, its yield force {self.force / 1e3:.4g} kN), got "
                                    f"{self.prestress!r} N")

    @property
    def force(self) -> float:
        """Yield force ``A f_y`` [N]."""
        return self.area * self.fy

    def describe(self) -> dict:
        return {"height_m": self.height, "area_mm2": self.area * 1e6, "fy_MPa": self.fy / 1e6,
                "prestress_kN": self.prestress / 1e3, "yield_force_kN": self.force / 1e3}


@dataclass(frozen=True)
class TieLink:
    """A tension member between bodies ``a`` and ``b`` of an assembly, anchored at ``p_a`` and ``p_b``
    [m], carrying at most ``force`` [N]."""

    a: int
    b: int
    p_a: np.ndarray
    p_b: np.ndarray
    force: float

    @property
    def direction(self) -> np.ndarray:
        """Unit vector from ``p_a`` to ``p_b``: the pull on body ``a``."""
        d = np.asarray(self.p_b, float) - np.asarray(self.p_a, float)
        return d / np.linalg.norm(d)


def _crossings(outline: np.ndarray, y: float) -> list[float]:
    """x of the points where the horizontal line at ``y`` crosses a closed polygon."""
    xs = []
    for p, q in zip(outline, np.roll(outline, -1, axis=0)):
        if (p[1] - y) * (q[1] - y) <= 0 and p[1] != q[1]:
            xs.append(float(p[0] + (y - p[1]) * (q[0] - p[0]) / (q[1] - p[1])))
    return xs


def tie_link(structure, tie: Tie) -> TieLink:
    """The tie's anchors: the outermost points of the structure's bodies at the tie's height, left and
    right, and the bodies they belong to. Refused in one line when the height is not within the structure."""
    pts = np.vstack([b.outline for b in structure.bodies])
    lo, hi = float(pts[:, 1].min()), float(pts[:, 1].max())
    if tie.height >= hi:
        raise ArchdemInputError(f"tie height {tie.height:g} m is at or above the crown ({hi:.4g} m)")
    if tie.height <= lo:
        raise ArchdemInputError(f"tie height {tie.height:g} m is at or below the structure's base ({lo:.4g} m)")
    # a height on a bed joint belongs to the body below it (a pier's top course), else to the one above
    eps = 1e-9 * (hi - lo)
    for y in (tie.height - eps, tie.height + eps):
        left, right = (math.inf, -1), (-math.inf, -1)
        for k, b in enumerate(structure.bodies):
            for x in _crossings(np.asarray(b.outline, float), y):
                if x < left[0]:
                    left = (x, k)
                if x > right[0]:
                    right = (x, k)
        if left[1] >= 0 and right[1] >= 0 and left[0] < 0 < right[0] and left[1] != right[1]:
            return TieLink(left[1], right[1], np.array([left[0], y]), np.array([right[0], y]), tie.force)
    raise ArchdemInputError(f"tie height {tie.height:g} m does not cross the structure from one side to the other")


def mechanism_body(structure, hinges, body: int) -> int | None:
    """Which body of the mechanism through ``hinges`` (:func:`analytic.rocking.linkage.four_bar_through`) carries
    the assembly's ``body``; None where it stays on the ground."""
    by_name = {j.name: j for j in structure.joints}
    joints = [by_name[n] for n, _ in hinges]
    if len(joints) == 1:
        return 0
    lo = [j.b for j in joints[:3]]
    hi = [j.a for j in joints[1:]]
    for k, (q, h) in enumerate(zip(lo, hi)):
        if q <= body <= h:
            return k
    return None


def elongation_rate(mechanism, structure, hinges, link: TieLink, phi: float) -> float:
    """``dL / dphi`` [m/rad] of the tie at the mechanism's rotation ``phi``."""
    states = mechanism.body_states(phi)
    rest = mechanism.body_states(0.0)

    def point(body: int, p0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        k = mechanism_body(structure, hinges, body)
        if k is None:
            return np.asarray(p0, float), np.zeros(2)
        s, s0 = states[k], rest[k]
        c, sn = math.cos(s.theta), math.sin(s.theta)
        r0 = np.asarray(p0, float) - np.array([s0.x, s0.y])
        r = np.array([c * r0[0] - sn * r0[1], sn * r0[0] + c * r0[1]])
        return np.array([s.x, s.y]) + r, np.array([s.dx - s.dtheta * r[1], s.dy + s.dtheta * r[0]])

    pa, va = point(link.a, link.p_a)
    pb, vb = point(link.b, link.p_b)
    d = pb - pa
    return float(d @ (vb - va) / np.linalg.norm(d))


def tie_force(mechanism, structure, hinges, link: TieLink, phi: float) -> float:
    """Generalised force ``W'(phi)`` [J/rad] of the yielding tie resisting the mechanism (0 when it shortens)."""
    return link.force * max(0.0, elongation_rate(mechanism, structure, hinges, link, phi))
