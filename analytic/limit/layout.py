"""Four-hinge mechanism layouts shared by the limit analysis and the linkage dynamics.

A hinge sits on the intrados or the extrados of a radial cut ``(side, psi)`` of the ring
(``side = -1`` left half, ``+1`` right half; ``psi`` polar angle about that half's centre).
Hinges are listed in order along the arch from the left springing to the right one;
the three macro-blocks lie between consecutive hinges. The geometry of the cuts and
macro-blocks comes from :mod:`specimens` (one model of the arch).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from specimens.blocks import band_points, central_band
from specimens.geometry import PointedArch, ring_segment_properties
from specimens.sections import SectionProperties

Face = Literal["intrados", "extrados"]


@dataclass(frozen=True)
class Hinge:
    """A hinge at face ``face`` of the radial cut at polar angle ``psi`` [rad] of half ``side``.

    ``contact`` in (0, 1]: the joint touches within its central fraction, so the hinge sits at
    that fraction's end, ``contact x t / 2`` from the mean radius (docs/physics/limit-analysis.md#12-effective-contact).
    An extrados hinge beyond the intrados apex (``psi > psi_i``) is on the keystone-fan cut
    from the intrados apex.
    """

    side: int
    psi: float
    face: Face
    contact: float = 1.0

    def point(self, arch: PointedArch) -> np.ndarray:
        if self.contact == 1.0:
            return arch.point(self.psi, arch.Ri if self.face == "intrados" else arch.Re, self.side)
        if self.face == "extrados" and self.psi > arch.psi_i:  # the fan cut from the intrados apex
            i_pt = np.array([0.0, arch.Ri * np.sin(arch.psi_i)])
        else:
            i_pt = arch.point(self.psi, arch.Ri, self.side)
        ends = band_points(i_pt, arch.point(self.psi, arch.Re, self.side), central_band(self.contact))
        return ends[0] if self.face == "intrados" else ends[1]

    def polar_about_origin(self, arch: PointedArch) -> float:
        p = self.point(arch)
        return float(np.arctan2(p[1], p[0]))

    def swapped(self) -> "Hinge":
        """The same cut with the hinge on the opposite face."""
        return Hinge(self.side, self.psi, "extrados" if self.face == "intrados" else "intrados", self.contact)


@dataclass(frozen=True)
class MacroBlock:
    """A rigid macro-block: mass [kg], centroid [m], centroidal in-plane inertia [kg m^2]."""

    mass: float
    centroid: np.ndarray
    inertia: float


@dataclass(frozen=True)
class FourHingeLayout:
    """Four hinges (left to right) and the three macro-blocks between them."""

    hinges: tuple[Hinge, Hinge, Hinge, Hinge]
    blocks: tuple[MacroBlock, MacroBlock, MacroBlock]

    def points(self, arch: PointedArch) -> np.ndarray:
        return np.array([h.point(arch) for h in self.hinges])


def _cut_order_key(side: int, psi: float) -> float:
    """Arch coordinate increasing from the left springing to the right springing."""
    return psi if side < 0 else np.pi - psi


def continuous_macro_block(arch: PointedArch, a: Hinge, b: Hinge, density: float) -> MacroBlock:
    """Macro-block of the continuous ring between the radial cuts of hinges ``a`` and ``b``."""
    if _cut_order_key(a.side, a.psi) >= _cut_order_key(b.side, b.psi):
        raise ValueError("hinges must be given left to right")
    sec: SectionProperties = ring_segment_properties(arch, (a.side, a.psi), (b.side, b.psi))
    m = density * arch.width * sec.area
    return MacroBlock(m, sec.centroid, density * arch.width * sec.polar)


def continuous_layout(arch: PointedArch, hinges: tuple[Hinge, Hinge, Hinge, Hinge], density: float) -> FourHingeLayout:
    """Layout on the continuous ring: macro-blocks bounded by the hinges' radial cuts."""
    blocks = tuple(continuous_macro_block(arch, hinges[k], hinges[k + 1], density) for k in range(3))
    return FourHingeLayout(tuple(hinges), blocks)  # type: ignore[arg-type]
