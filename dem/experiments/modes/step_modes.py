"""The modes step: natural frequencies of every specimen on the reference study's joints
(docs/physics/modes.md)."""
from __future__ import annotations

import json
from pathlib import Path

from analytic.compliant.modes import modes
from dem.common.campaign import CampaignContext, write_csv
from dem.common.joints import STUDY_JOINTS
from dem.core.contact import normal_stiffness, study_joints
from dem.core.model import from_assembly
from dem.core.settings import Settings
from dem.experiments.modes.figure import save_mode_shapes
from specimens.blocks import discretise

#: Frequencies listed per specimen in the table (all 3 per body are in the CSV's JSON column).
MODES_LISTED = 6


def step_modes(ctx: CampaignContext, d: Path) -> dict:
    """First natural frequencies of each specimen (its blocks on the campaign's compliant joints, else on its
    Table 5.1 joints), and the first mode shapes of one specimen per rise."""

    rows, figures, drawn = [], [], set()
    for s in ctx.specimens:
        c = ctx.contact_of(s)
        asm = discretise(s.arch, config=ctx.config, **({"contact": c} if c != 1.0 else {}))
        kn = normal_stiffness(Settings(**(ctx.law_of(s) or study_joints(s.id))), from_assembly(asm))
        res = modes(asm, kn)
        f = res.frequencies_hz
        rows.append({"id": s.id, "Sh": round(s.arch.Sh, 3), "Sd": round(s.arch.Sd, 3), "kn_Pa_per_m": kn,
                     **{f"f{k + 1}_Hz": float(f[k]) for k in range(min(MODES_LISTED, len(f)))},
                     "unstable": res.unstable, "all_Hz": json.dumps([round(float(x), 3) for x in f])})
        sh = round(s.arch.Sh, 3)
        if sh not in drawn:
            drawn.add(sh)
            png = d / f"modes_{s.id}.png"
            save_mode_shapes(asm, res, png, title=f"{s.id}, k_n {kn:.3g} Pa/m")
            figures.append({"path": f"modes/{png.name}", "caption": f"{s.id}: the first mode shapes"})
    write_csv(d / "modes.csv", rows)
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
