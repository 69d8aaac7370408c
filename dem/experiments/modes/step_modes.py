"""The modes step: natural frequencies of every specimen on the reference study's joints
(docs/physics/modes.md)."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

from analytic.compliant.modes import modes
from dem.common.campaign import CampaignContext, write_csv
from dem.common.joints import STUDY_JOINTS
from dem.core.contact import normal_stiffness, study_joints
from dem.core.model import from_assembly
from dem.core.settings import Settings
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.modes.figure import save_mode_shapes
from specimens.blocks import discretise

#: Frequencies listed per specimen in the table (all 3 per body are in the CSV's JSON column).
MODES_LISTED = 6


@dataclass(frozen=True)
class SpecimenModes(Result):
    """One specimen's natural frequencies on its joints: its row of the modes table, declared once."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("id", "str"), Column("Sh", "float"), Column("Sd", "float"), Column("kn_Pa_per_m", "float", "Pa/m"),
        *(Column(f"f{k}_Hz", "float", "Hz") for k in range(1, MODES_LISTED + 1)),
        Column("unstable", "int"), Column("all_Hz", "json", "Hz"),
    ))

    id: str
    Sh: float
    Sd: float
    kn: float  # the joints' normal stiffness [Pa/m]
    frequencies_hz: tuple[float, ...]
    unstable: int  # modes gravity makes unstable, not counted

    def rows(self) -> list[dict]:
        f = self.frequencies_hz
        return [{"id": self.id, "Sh": round(self.Sh, 3), "Sd": round(self.Sd, 3), "kn_Pa_per_m": self.kn,
                 **{f"f{k + 1}_Hz": f[k] if k < len(f) else None for k in range(MODES_LISTED)},
                 "unstable": self.unstable, "all_Hz": [round(x, 3) for x in f]}]


def step_modes(ctx: CampaignContext, d: Path) -> dict:
    """First natural frequencies of each specimen (its blocks on the campaign's compliant joints, else on its
    Table 5.1 joints), and the first mode shapes of one specimen per rise."""

    rows, figures, drawn = [], [], set()
    for s in ctx.specimens:
        c = ctx.contact_of(s)
        asm = discretise(s.arch, config=ctx.config, **({"contact": c} if c != 1.0 else {}))
        kn = normal_stiffness(Settings(**(ctx.law_of(s) or study_joints(s.id))), from_assembly(asm))
        res = modes(asm, kn)
        rows += SpecimenModes(s.id, s.arch.Sh, s.arch.Sd, kn, tuple(float(x) for x in res.frequencies_hz),
                              res.unstable).rows()
        sh = round(s.arch.Sh, 3)
        if sh not in drawn:
            drawn.add(sh)
            png = d / f"modes_{s.id}.png"
            save_mode_shapes(asm, res, png, title=f"{s.id}, k_n {kn:.3g} Pa/m")
            figures.append({"path": f"modes/{png.name}", "caption": f"{s.id}: the first mode shapes"})
    write_csv(d / "modes.csv", rows, SpecimenModes.SCHEMA)
    lo = min(r["f1_Hz"] for r in rows)
    hi = max(r["f1_Hz"] for r in rows)
    return {
        "summary": f"Natural frequencies of the {ctx.config} blocks on compliant joints at rest under gravity (springs at "
                   "the joints' ends, k_s = 0.347 k_n; k_n "
                   + ("of the campaign's joints)." if ctx.joints and ctx.joints != STUDY_JOINTS else "of the study's Table 5.1)."),
        "tables": [{"name": "modes", "title": "Natural frequencies [Hz]", "csv": "modes/modes.csv"}],
        "figures": figures,
        "findings": [f"First natural frequency {lo:.1f}-{hi:.1f} Hz over {len(rows)} specimens: far above the "
                     "2-10 Hz pulses, so the arches respond to them as rigid blocks until they rock."],
    }
