"""Arch geometry: the pointed arch, its voussoirs, meshes and the specimen catalogue."""
from specimens.blocks import Assembly, Block, Body, Joint, discretise, joint_angles
from specimens.catalogue import (
    CATALOGUE,
    SPECIMEN_IDS,
    Specimen,
    full_scale_set,
    get_specimen,
)
from foundation.errors import ArchdemInputError
from specimens.exchange import read_assembly, write_assembly
from specimens.geometry import PointedArch
from specimens.piers import Piers

__all__ = [
    "Assembly", "Block", "Body", "Joint", "discretise", "joint_angles", "CATALOGUE", "SPECIMEN_IDS",
    "Specimen", "full_scale_set", "get_specimen", "ArchdemInputError", "PointedArch", "Piers",
    "read_assembly", "write_assembly",
]
