"""Real structures assessed by archdem: their geometry as reconstructed, with its provenance
(docs/physics/assessment.md#7-the-noh-gumbad-example)."""
from __future__ import annotations

from dataclasses import dataclass

from specimens.geometry import PointedArch
from specimens.piers import Piers


@dataclass(frozen=True)
class Monument:
    """A vault's ``arch`` (ring as built), bulk ``density`` [kg/m^3] and its ``configurations``:
    name -> piers (None: the ring alone on a rigid base); ``source``: where the geometry comes from."""

    name: str
    arch: PointedArch
    density: float
    configurations: dict
    source: str


#: The barrel vaults of the Noh Gumbad mosque: ring 0.65 m thick, 1.5 m wide, baked brick (1.5 t/m^3).
#: Span, rise and piers are not published; they are fitted (benchmarks/fit_noh_gumbad.py) to the
#: published multipliers and hinges of the ring alone and on half- and full-height abutments.
NOH_GUMBAD = Monument(
    name="noh-gumbad",
    arch=PointedArch(e=0.0, t=0.65, Rp=2.5330, width=1.5),
    density=1500.0,
    configurations={"ring alone": None,
                    "half-height piers": Piers(height=3.841, width=2.058),
                    "full-height piers": Piers(height=6.059, width=2.058)},
    source="fitted to the published lambda 0.421 / 0.361 / 0.239 and hinge angles (benchmarks/fit_noh_gumbad.py)",
)

MONUMENTS = {NOH_GUMBAD.name: NOH_GUMBAD}
