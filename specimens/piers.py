"""Two equal piers under an arch's springings: the structure as built (docs/physics/geometry.md#14-arches-on-piers).

The piers stand below the springing line (y from ``-height`` to 0), so every coordinate of the
bare arch is unchanged. Each pier is a rectangle ``width`` (in plane) by ``height``, ``depth``
out of plane, cut into ``courses`` equal horizontal courses; its inner face stands ``offset``
inside the opening beyond the intrados springing, and it carries the whole springing joint.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from foundation.errors import ArchdemInputError

#: Most courses per pier (each course adds a body and a joint to every analysis).
MAX_COURSES = 50


def _length(name: str, value, allow_zero: bool = False) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ArchdemInputError(f"pier {name} must be a length in m, got {value!r}") from None
    if not math.isfinite(v) or v < 0 or (v == 0 and not allow_zero):
        raise ArchdemInputError(f"pier {name} must be a finite length {'>= 0' if allow_zero else '> 0'} m, got {value!r}")
    return v


@dataclass(frozen=True)
class Piers:
    """Two equal piers [m]: ``height`` from the ground to the springing line, in-plane ``width``,
    out-of-plane ``depth`` (None: the arch's width), ``offset`` of the pier's inner face into the
    opening beyond the intrados springing (>= 0), ``courses`` equal courses per pier; ``load``:
    superimposed load on each pier [N], e.g. the masonry above, carried as mass at the centre
    of the pier's top (weight and inertia)."""

    height: float
    width: float
    depth: float | None = None
    offset: float = 0.0
    courses: int = 1
    load: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "height", _length("height", self.height))
        object.__setattr__(self, "width", _length("width", self.width))
        if self.depth is not None:
            object.__setattr__(self, "depth", _length("depth", self.depth))
        object.__setattr__(self, "offset", _length("offset", self.offset, allow_zero=True))
        try:
            load = float(self.load)
        except (TypeError, ValueError):
            raise ArchdemInputError(f"pier load must be a force in N, got {self.load!r}") from None
        if not (math.isfinite(load) and load >= 0):
            raise ArchdemInputError(f"pier load must be a finite force >= 0 N, got {self.load!r}")
        object.__setattr__(self, "load", load)
        if isinstance(self.courses, bool) or not isinstance(self.courses, int) or not 1 <= self.courses <= MAX_COURSES:
            raise ArchdemInputError(f"pier courses must be a whole number from 1 to {MAX_COURSES}, got {self.courses!r}")

    def check(self, arch) -> None:
        """A one-line input error if these piers cannot carry ``arch`` (a :class:`~specimens.geometry.PointedArch`)."""
        if self.width < arch.t + self.offset - 1e-12 * arch.t:
            raise ArchdemInputError(
                f"pier width {self.width:g} m is narrower than the ring's springing: it must be at least the ring "
                f"thickness plus the offset, {arch.t + self.offset:g} m")
        clear = arch.Ri - arch.e
        if self.offset >= clear:
            raise ArchdemInputError(f"pier offset {self.offset:g} m closes the opening: it must be below half the "
                                    f"clear span, {clear:g} m")

    def inner_x(self, arch) -> float:
        """|x| of the piers' inner faces [m]."""
        return float(arch.Ri - arch.e - self.offset)

    def depth_for(self, arch) -> float:
        """Out-of-plane depth of the piers [m]."""
        return float(arch.width if self.depth is None else self.depth)

    def describe(self, arch=None) -> dict:
        """The pier parameters, for result files (``depth`` resolved when ``arch`` is given)."""
        depth = self.depth_for(arch) if arch is not None else self.depth
        return {"height": self.height, "width": self.width, "depth": depth, "offset": self.offset,
                "courses": self.courses, **({"load": self.load} if self.load else {})}
