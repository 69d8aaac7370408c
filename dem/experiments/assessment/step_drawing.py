"""The drawing step (optional): the shipped survey-like drawing of an arch on piers run end to end —
read, limit analysis, DEM tilt tests and the code assessment (docs/physics/geometry.md#16-assemblies-from-drawings)."""
from __future__ import annotations

import math
from pathlib import Path

from analytic.codes.assessment import index_text
from analytic.limit.limit_discrete import solve_lp
from analytic.motions.spectra import ec8
from dem.common.campaign import CampaignContext, pct, write_csv
from dem.core.model import from_assembly
from dem.core.settings import Settings
from dem.experiments.assessment.run import AssessSpec, run
from dem.experiments.tilt import tilt
from specimens.constants import NO_SLIDING_MU, REFERENCE_MU_BASE, REFERENCE_MU_JOINT, G
from specimens.drawing import save_drawing
from specimens.exchange import EXAMPLE_DRAWING, read_assembly

#: The site of the step's assessment: EN 1998-1, type 1, ground A, a_g 0.25 g (as the README's example).
DRAWING_SITE_AG_G = 0.25


def step_drawing(ctx: CampaignContext, d: Path) -> dict:
    """The drawing's blocks: LP and DEM tilt with no sliding and at the reference friction, and the
    linear and non-linear kinematic checks of its governing mechanism."""
    asm = read_assembly(EXAMPLE_DRAWING)
    label = EXAMPLE_DRAWING.stem
    model = from_assembly(asm, name=label)
    rows = []
    for case, (mj, mb) in (("no sliding", (NO_SLIDING_MU, NO_SLIDING_MU)),
                           ("reference", (REFERENCE_MU_JOINT, REFERENCE_MU_BASE))):
        lp = solve_lp(asm, math.inf if mj == NO_SLIDING_MU else mj, math.inf if mb == NO_SLIDING_MU else mb)
        r = tilt(model, Settings(engine=ctx.engine, mu_joint=mj, mu_base=mb), assembly=asm)
        rows.append({"friction": case, "mu_joint": mj, "mu_base": mb, "lambda_lp": lp.lam,
                     "hinges_lp": " ".join(f"{j}:{f[:3]}" for j, f in lp.hinges), "lambda_dem": r.lam,
                     "err_dem_vs_lp_pct": pct(r.lam, lp.lam), "mode_dem": r.mode,
                     "hinges_dem": " ".join(j.joint for j in r.joints if j.state == "hinge")})
    write_csv(d / "drawing.csv", rows)
    site = ec8(DRAWING_SITE_AG_G * G)
    res = run(AssessSpec(asm, site))
    res.write_csv(d / "drawing-assessment.csv")  # its checks as the code states them
    a = res.assessment.describe()
    save_drawing(asm, d / "drawing.png", title=f"{label}: the blocks and joints as read")
    ns = rows[0]
    findings = [f"{label}: {len(asm.bodies)} blocks, {len(asm.joints)} joints read; DEM no-sliding tilt "
                f"{ns['lambda_dem']:.4f} against the LP's {ns['lambda_lp']:.4f} ({ns['err_dem_vs_lp_pct']:+.2f} %).",
                f"Code checks at a_g {DRAWING_SITE_AG_G:g} g (EN 1998-1, ground A): safety index "
                f"{index_text(a['safety_index'])}, governed by the {a['governing_check']} check "
                f"({'verified' if a['verified'] else 'not verified'})."]
    tables = [{"name": "drawing", "title": "The drawing's tilt: LP and DEM", "csv": "drawing/drawing.csv"},
              {"name": "drawing-assessment", "title": f"The drawing's code checks (EN 1998-1, a_g {DRAWING_SITE_AG_G:g} g)",
               "csv": "drawing/drawing-assessment.csv"}]
    return {"summary": ctx.joints_text() + " " + f"The shipped drawing {EXAMPLE_DRAWING.name} (an arch on piers with "
                       f"unequal voussoirs and courses) read, its static LP and DEM tilt test ({ctx.engine}) with no "
                       "sliding and at the reference friction, and the kinematic checks of its governing mechanism.",
            "tables": tables, "figures": [{"path": "drawing/drawing.png", "caption": f"{label} as read"}],
            "findings": findings}
