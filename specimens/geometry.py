"""The two-centred pointed arch (continuous ring).

Frame (docs/physics/geometry.md#1-frame-and-units): x horizontal, y vertical (up), origin at mid-span on the
springing line; the out-of-plane width ``width`` runs along z. The right half
(x >= 0) is the annulus centred at ``C_R = (-e, 0)``, the left half its mirror
centred at ``C_L = (+e, 0)``. Polar angles ``psi`` are measured about the centre of
the half concerned from the horizontal pointing away from the axis.

All lengths in metres, angles in radians.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from foundation.errors import ArchdemInputError
from specimens.sections import (
    Arc,
    Edge,
    SectionProperties,
    Segment,
    combine,
    mirror_edges,
    region_properties,
)


def _finite_positive(name: str, value: float, allow_zero: bool = False) -> None:
    if not isinstance(value, (int, float, np.floating, np.integer)) or not math.isfinite(value):
        raise ArchdemInputError(f"{name} must be a finite number, got {value!r}")
    if value < 0 or (value == 0 and not allow_zero):
        raise ArchdemInputError(f"{name} must be {'>= 0' if allow_zero else '> 0'}, got {value:g}")


@dataclass(frozen=True)
class PointedArch:
    """A two-centred pointed arch of constant ring thickness.

    Parameters
    ----------
    e : eccentricity of each arc centre from the symmetry axis [m] (0 = round arch)
    t : ring thickness [m]
    Rp : mean radius of each arc [m] (``Rp = Rc + e``)
    width : out-of-plane width [m]
    """

    e: float
    t: float
    Rp: float
    width: float = 0.1

    def __post_init__(self) -> None:
        _finite_positive("eccentricity e", self.e, allow_zero=True)
        _finite_positive("thickness t", self.t)
        _finite_positive("mean radius Rp", self.Rp)
        _finite_positive("width", self.width)
        if self.t >= 2 * self.Rp:
            raise ArchdemInputError(
                f"thickness t = {self.t:g} m must be smaller than twice the mean radius Rp = {self.Rp:g} m"
            )
        if self.e >= self.Ri:
            raise ArchdemInputError(
                f"eccentricity e = {self.e:g} m must be smaller than the intrados radius Ri = {self.Ri:g} m"
            )
        if self.Rc - self.t / 2 <= 0:
            raise ArchdemInputError(
                f"the intrados does not span: Rc - t/2 = {self.Rc - self.t / 2:g} m must be > 0"
            )

    # --- constructors -------------------------------------------------------------
    @classmethod
    def from_radii(cls, Ri: float, Re: float, e: float, width: float = 0.1) -> "PointedArch":
        """From intrados radius, extrados radius and eccentricity [m]."""
        _finite_positive("Ri", Ri)
        _finite_positive("Re", Re)
        if Re <= Ri:
            raise ArchdemInputError(f"extrados radius Re = {Re:g} m must exceed intrados radius Ri = {Ri:g} m")
        return cls(e=e, t=Re - Ri, Rp=(Ri + Re) / 2, width=width)

    @classmethod
    def from_ratios(cls, Sh: float, Sd: float, Rc: float, width: float = 0.1) -> "PointedArch":
        """From sharpness ``Sh = e/Rc``, slenderness ``Sd = t/Rp`` and round radius ``Rc`` [m]."""
        _finite_positive("sharpness Sh", Sh, allow_zero=True)
        _finite_positive("slenderness Sd", Sd)
        _finite_positive("Rc", Rc)
        e = Sh * Rc
        Rp = Rc + e
        return cls(e=e, t=Sd * Rp, Rp=Rp, width=width)

    @classmethod
    def round(cls, Rc: float, t: float, width: float = 0.1) -> "PointedArch":
        """The semicircular arch (``e = 0``) of mean radius ``Rc`` and thickness ``t``."""
        return cls(e=0.0, t=t, Rp=Rc, width=width)

    def with_width(self, width: float) -> "PointedArch":
        return replace(self, width=width)

    def with_thickness(self, t: float) -> "PointedArch":
        """Same centres and mean radius, another thickness."""
        return replace(self, t=t)

    # --- derived quantities -------------------------------------------------------
    @property
    def Rc(self) -> float:
        """Radius of the round arch of the same span [m]."""
        return self.Rp - self.e

    @property
    def Ri(self) -> float:
        return self.Rp - self.t / 2

    @property
    def Re(self) -> float:
        return self.Rp + self.t / 2

    @property
    def Sh(self) -> float:
        """Sharpness e / Rc."""
        return self.e / self.Rc

    @property
    def Sd(self) -> float:
        """Slenderness t / Rp."""
        return self.t / self.Rp

    @property
    def psi_i(self) -> float:
        """Polar angle at which the intrados reaches the axis [rad]."""
        return math.acos(self.e / self.Ri)

    @property
    def psi_e(self) -> float:
        """Polar angle at which the extrados reaches the axis [rad]."""
        return math.acos(self.e / self.Re)

    @property
    def span(self) -> float:
        """Clear span at the springing, ``2 Rc - t`` [m]."""
        return 2 * self.Rc - self.t

    @property
    def rise(self) -> float:
        """Rise of the intrados apex above the springing, ``Ri sin(psi_i)`` [m]."""
        return self.Ri * math.sin(self.psi_i)

    @property
    def apex_intrados(self) -> np.ndarray:
        return np.array([0.0, self.Ri * math.sin(self.psi_i)])

    @property
    def apex_extrados(self) -> np.ndarray:
        return np.array([0.0, self.Re * math.sin(self.psi_e)])

    # --- points ------------------------------------------------------------------
    def centre(self, side: int) -> np.ndarray:
        """Centre of the arc of one half: ``side = +1`` right (``(-e, 0)``), ``-1`` left."""
        return np.array([-side * self.e, 0.0])

    def point(self, psi: float | np.ndarray, r: float | np.ndarray, side: int = 1) -> np.ndarray:
        """Point(s) at polar angle ``psi`` and radius ``r`` about the centre of half ``side``.

        Returns shape ``(..., 2)``.
        """
        psi = np.asarray(psi, dtype=float)
        r = np.asarray(r, dtype=float)
        x = side * (-self.e + r * np.cos(psi))
        y = r * np.sin(psi)
        return np.stack(np.broadcast_arrays(x, y), axis=-1)

    def intrados_distance(self, beta: float | np.ndarray) -> np.ndarray:
        """Distance from O of the intrados point seen in direction ``beta`` (polar about O)."""
        return _profile_distance(self.e, self.Ri, beta)

    def extrados_distance(self, beta: float | np.ndarray) -> np.ndarray:
        return _profile_distance(self.e, self.Re, beta)

    def area(self) -> float:
        """Exact area of the ring in the x-y plane [m^2] (two sectors to the axis)."""
        return 2 * region_properties(ring_half_boundary(self, 0.0, None)).area

    def describe(self) -> dict[str, float]:
        """Main dimensions, SI."""
        return {
            "Ri": self.Ri, "Re": self.Re, "e": self.e, "t": self.t, "Rp": self.Rp, "Rc": self.Rc,
            "Sh": self.Sh, "Sd": self.Sd, "span": self.span, "rise": self.rise,
            "psi_i": self.psi_i, "psi_e": self.psi_e, "width": self.width,
        }


def _profile_distance(e: float, R: float, beta: float | np.ndarray) -> np.ndarray:
    beta = np.asarray(beta, dtype=float)
    c = np.cos(beta)
    root = np.sqrt(e**2 * c**2 - e**2 + R**2)
    # right half (beta <= pi/2): centre at (-e, 0); left half mirrors
    return np.where(beta <= math.pi / 2, root - e * c, root + e * c)


def ring_half_boundary(arch: "PointedArch", psi_a: float, psi_b: float | None) -> list[Edge]:
    """Exact boundary of the right half of the ring between radial cuts ``psi_a < psi_b``.

    ``psi_b = None`` closes the region at the symmetry axis (keystone zone included).
    """
    c = (-arch.e, 0.0)
    I = lambda psi: tuple(arch.point(psi, arch.Ri))  # noqa: E731
    E = lambda psi: tuple(arch.point(psi, arch.Re))  # noqa: E731
    if psi_b is None:
        if psi_a > arch.psi_i:
            raise ValueError("psi_a beyond the intrados apex")
        return [
            Arc(c, arch.Ri, psi_a, arch.psi_i),
            Segment(tuple(arch.apex_intrados), tuple(arch.apex_extrados)),
            Arc(c, arch.Re, arch.psi_e, psi_a),
            Segment(E(psi_a), I(psi_a)),
        ]
    if not psi_a < psi_b <= arch.psi_i:
        raise ValueError("need psi_a < psi_b <= psi_i")
    return [
        Arc(c, arch.Ri, psi_a, psi_b),
        Segment(I(psi_b), E(psi_b)),
        Arc(c, arch.Re, psi_b, psi_a),
        Segment(E(psi_a), I(psi_a)),
    ]


def ring_segment_properties(arch: "PointedArch", cut_a: tuple[int, float], cut_b: tuple[int, float]) -> SectionProperties:
    """Exact properties of the continuous ring between two radial cuts.

    A cut is ``(side, psi)``: ``side = -1`` left half, ``+1`` right half, ``psi`` its polar
    angle about that half's centre (0 at the springing, up to ``psi_i``). ``cut_a`` must lie
    before ``cut_b`` going from the left springing to the right springing. Used for the
    macro-blocks of the continuous limit analysis and of the linkages.
    """
    (sa, pa), (sb, pb) = cut_a, cut_b
    parts: list[SectionProperties] = []
    if sa < 0 and sb < 0:
        if not pa < pb:
            raise ValueError("cut_a must precede cut_b")
        return region_properties(mirror_edges(ring_half_boundary(arch, pa, pb)))
    if sa > 0 and sb > 0:
        if not pb < pa:
            raise ValueError("cut_a must precede cut_b")
        return region_properties(ring_half_boundary(arch, pb, pa))
    if sa > 0 and sb < 0:
        raise ValueError("cut_a must precede cut_b")
    # across the apex: left part from pa to the axis, right part from pb to the axis
    if pa < arch.psi_i:
        parts.append(region_properties(mirror_edges(ring_half_boundary(arch, pa, None))))
    if pb < arch.psi_i:
        parts.append(region_properties(ring_half_boundary(arch, pb, None)))
    return combine(parts)
