"""The rectangular rocking block (docs/physics/dynamics.md#2-the-rocking-block), the validation model of the linkage dynamics.

Half-width ``b``, half-height ``h`` [m], standing on y = 0 with its centroid at ``(0, h)``.
``pivot = -1`` rocks about the left base corner ``(-b, 0)`` (counter-clockwise, towards -x,
opened by a positive ground acceleration), ``pivot = +1`` about the right corner. ``phi`` is
the rotation magnitude. ``R = sqrt(b^2 + h^2)``, ``alpha = atan(b / h)``; Housner's frequency
parameter ``p = sqrt(m g R / I_O)`` (``= sqrt(3 g / 4 R)``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

from analytic.rocking.mechanism import BodyState, Mechanism, RigidField, field_of, rotating_body
from specimens.constants import G
from foundation.errors import ArchdemInputError


@dataclass(frozen=True)
class RockingBlock(Mechanism):
    """Rectangular block of half-width ``b`` and half-height ``h`` [m] rocking about a base corner."""

    b: float
    h: float
    pivot: int = -1
    density: float = 500.0
    width: float = 0.1
    g: float = G

    def __post_init__(self) -> None:
        for name, v in (("half-width b", self.b), ("half-height h", self.h), ("density", self.density),
                        ("width", self.width)):
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ArchdemInputError(f"block {name} must be a positive number, got {v!r}")
        if self.pivot not in (-1, 1):
            raise ArchdemInputError(f"block pivot must be -1 (left corner) or +1 (right corner), got {self.pivot!r}")

    @property
    def m(self) -> float:
        return self.density * self.width * 4 * self.b * self.h

    @property
    def masses(self) -> tuple[float, ...]:  # type: ignore[override]
        return (self.m,)

    @property
    def inertias(self) -> tuple[float, ...]:  # type: ignore[override]
        return (self.m * (self.b ** 2 + self.h ** 2) / 3.0,)

    @property
    def R(self) -> float:
        return math.hypot(self.b, self.h)

    @property
    def alpha(self) -> float:
        return math.atan2(self.b, self.h)

    @property
    def housner_p(self) -> float:
        """``sqrt(3 g / 4 R)`` [rad/s]."""
        return math.sqrt(3 * self.g / (4 * self.R))

    @property
    def label(self) -> str:
        return f"block b={self.b:g} h={self.h:g} pivot={'left' if self.pivot < 0 else 'right'}"

    def body_states(self, phi: float) -> list[BodyState]:
        s = -self.pivot  # rotation sense: +1 counter-clockwise about the left corner
        return [rotating_body((self.pivot * self.b, 0.0), (0.0, self.h), s * phi, float(s), 0.0)]

    def geometric_limit(self) -> float:
        return math.pi / 2

    def rest_fields(self) -> tuple[RigidField, ...]:
        v, w = field_of(self.body_states(0.0)[0])
        return (RigidField("block", v, w),)

    def region_moments(self, region: object) -> tuple[float, float, float, float]:
        """``(m, S_x, S_y, J_O)`` of a region (only ``"block"``): mass, first moments, inertia about O."""
        if region != "block":
            raise KeyError(region)
        m = self.m
        return m, 0.0, m * self.h, self.inertias[0] + m * self.h ** 2

    def same_as(self, other) -> bool:
        return isinstance(other, RockingBlock) and (self.b, self.h, self.pivot) == (other.b, other.h, other.pivot)

    def impact_candidates(self) -> tuple["RockingBlock"]:
        """After an impact the block rocks about the other corner."""
        return (replace(self, pivot=-self.pivot),)


def rocking_frame_equivalent(b: float, h: float, gamma: float, density: float = 500.0,
                             width: float = 0.1) -> tuple[RockingBlock, float]:
    """The closed-form rocking frame (docs/physics/dynamics.md#11-the-rocking-frame): piers of
    half-width ``b`` and half-height ``h`` [m] carrying a lintel of ``gamma`` times their mass move
    as the block of the same slenderness scaled by ``(1 + 3 gamma) / (1 + 2 gamma)``, with the
    impact velocity ratio ``[1 - 3/2 sin^2 alpha + 3 gamma cos 2 alpha] / (1 + 3 gamma)``.
    Returns ``(block, restitution)``."""
    if not (math.isfinite(gamma) and gamma >= 0):
        raise ArchdemInputError(f"frame mass ratio gamma must be a number >= 0, got {gamma!r}")
    k = (1 + 3 * gamma) / (1 + 2 * gamma)
    alpha = math.atan2(b, h)
    r = (1 - 1.5 * math.sin(alpha) ** 2 + 3 * gamma * math.cos(2 * alpha)) / (1 + 3 * gamma)
    return RockingBlock(b * k, h * k, density=density, width=width), r
