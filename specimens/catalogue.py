"""The catalogue of the 11 reduced-scale AAC specimens and the full-scale parametric set.

docs/physics/geometry.md#9-the-specimen-catalogue (and #10). All catalogue arches have ``Rc = 0.200 m`` and width 0.100 m.
"""
from __future__ import annotations

from dataclasses import dataclass

from specimens.blocks import discretise
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch

SPECIMEN_WIDTH = 0.100  # m

# id, Ri, Re, e  [mm]
_TABLE = [
    ("Sh02-Sd015", 222, 258, 40),
    ("Sh02-Sd020", 216, 264, 40),
    ("Sh02-Sd025", 210, 270, 40),
    ("Sh06-Sd010", 304, 336, 120),
    ("Sh06-Sd015", 296, 344, 120),
    ("Sh06-Sd020", 288, 352, 120),
    ("Sh06-Sd025", 280, 360, 120),
    ("Sh1-Sd010", 380, 420, 200),
    ("Sh1-Sd015", 370, 430, 200),
    ("Sh1-Sd020", 360, 440, 200),
    ("Sh1-Sd025", 350, 450, 200),
]


@dataclass(frozen=True)
class Specimen:
    """A catalogue specimen: its id and arch (SI units)."""

    id: str
    arch: PointedArch


CATALOGUE: tuple[Specimen, ...] = tuple(
    Specimen(sid, PointedArch.from_radii(Ri / 1000, Re / 1000, e / 1000, width=SPECIMEN_WIDTH))
    for sid, Ri, Re, e in _TABLE
)
SPECIMEN_IDS: tuple[str, ...] = tuple(s.id for s in CATALOGUE)


def get_specimen(specimen_id: str) -> Specimen:
    """The catalogue specimen ``specimen_id`` (exact id, e.g. ``Sh06-Sd015``)."""
    for s in CATALOGUE:
        if s.id == specimen_id:
            return s
    raise ArchdemInputError(f"unknown specimen {specimen_id!r}; valid ids: {', '.join(SPECIMEN_IDS)}")


def select_specimens(spec: str) -> list[Specimen]:
    """``all`` or a comma-separated list of ids."""
    if spec.strip() == "all":
        return list(CATALOGUE)
    ids = [s.strip() for s in spec.split(",")]
    if not all(ids):
        raise ArchdemInputError(f"specimens: give 'all' or ids separated by commas, got {spec!r}")
    return [get_specimen(s) for s in ids]


FULL_SCALE_SPANS = (5.0, 10.0, 20.0)  # 2 Rc [m]
FULL_SCALE_SH = (0.2, 0.6, 1.0)
FULL_SCALE_SD = (0.10, 0.15, 0.20, 0.25)


def full_scale_set(
    spans: tuple[float, ...] = FULL_SCALE_SPANS,
    sharpness: tuple[float, ...] = (0.0,) + FULL_SCALE_SH,
    slenderness: tuple[float, ...] = FULL_SCALE_SD,
    width: float = 1.0,
) -> list[Specimen]:
    """The parametric set of full-scale arches (docs/physics/geometry.md#10-the-full-scale-parametric-set): span = 2 Rc.

    Default: 3 spans x 4 sharpness values (round arch included) x 4 slenderness values = 48.
    """
    out = []
    for span in spans:
        for sh in sharpness:
            for sd in slenderness:
                arch = PointedArch.from_ratios(sh, sd, span / 2, width=width)
                out.append(Specimen(f"L{span:g}-Sh{sh:g}-Sd{sd:g}", arch))
    return out


def catalogue_rows() -> list[dict]:
    """One row per catalogue specimen, SI units (the JSON schema of ``archdem specimens``: the
    keys in ``JSON_KEYS``)."""
    rows = []
    for s in CATALOGUE:
        a = s.arch
        glued = discretise(a, config="glued")
        free = discretise(a, config="free")
        rows.append({
            "id": s.id, "Ri": a.Ri, "Re": a.Re, "e": a.e, "t": a.t, "Sh": a.Sh, "Sd": a.Sd,
            "span": a.span, "rise": a.rise, "mass": glued.total_mass,
            "n_blocks": len(free.blocks),
            "n_bodies_free": free.n_bodies, "n_bodies_glued": glued.n_bodies,
        })
    return rows


JSON_KEYS = ("id", "Ri", "Re", "e", "t", "Sh", "Sd", "span", "rise", "mass", "n_blocks")


def catalogue_table(rows: list[dict]) -> list[str]:
    """The lines of ``archdem specimens``: a header with the units, then one line per row of
    :func:`catalogue_rows` (lengths in mm, mass in kg, bodies free/glued)."""
    out = [f"{'id':<11} {'Ri':>6} {'Re':>6} {'e':>6} {'t':>6} {'Sh':>5} {'Sd':>5} {'span':>6} {'rise':>6} {'mass':>6} "
           f"{'bodies':>11}",
           f"{'':<11} {'[mm]':>6} {'[mm]':>6} {'[mm]':>6} {'[mm]':>6} {'':>5} {'':>5} {'[mm]':>6} {'[mm]':>6} {'[kg]':>6} "
           f"{'free/glued':>11}"]
    return out + [f"{r['id']:<11} {r['Ri']*1e3:6.0f} {r['Re']*1e3:6.0f} {r['e']*1e3:6.0f} {r['t']*1e3:6.0f} "
                  f"{r['Sh']:5.2f} {r['Sd']:5.3f} {r['span']*1e3:6.0f} {r['rise']*1e3:6.1f} {r['mass']:6.3f} "
                  f"{r['n_bodies_free']:>5}/{r['n_bodies_glued']:<5}" for r in rows]


#: The reference study's DEM joints per specimen (its Table 5.1): normal stiffness k_N [Pa/m, read per
#: unit joint area: docs/physics/modes.md#4-reading-the-studys-joint-table], the rotational-impact
#: frequency omega_r [rad/s] and the stiffness-proportional Rayleigh coefficient beta_R [s] it used.
STUDY_JOINTS: dict[str, tuple[float, float, float]] = {
    "Sh02-Sd015": (4.8e8, 305.0, 3.28e-3),
    "Sh02-Sd020": (4.82e8, 472.7, 2.12e-3),
    "Sh02-Sd025": (4.83e8, 665.3, 1.5e-3),
    "Sh06-Sd010": (4.3e8, 204.4, 4.89e-3),
    "Sh06-Sd015": (4.34e8, 383.0, 2.61e-3),
    "Sh06-Sd020": (4.38e8, 601.9, 1.66e-3),
    "Sh06-Sd025": (4.44e8, 859.8, 1.16e-3),
    "Sh1-Sd010": (3.9e8, 240.0, 4.17e-3),
    "Sh1-Sd015": (4e8, 574.8, 1.74e-3),
    "Sh1-Sd020": (4.1e8, 726.4, 1.38e-3),
    "Sh1-Sd025": (4.2e8, 1054.3, 9.49e-4),
}
