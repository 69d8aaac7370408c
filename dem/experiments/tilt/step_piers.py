"""The piers step: one arch on piers of growing height, limit analysis beside the DEM tilt test
(docs/physics/geometry.md#14-arches-on-piers): taller piers, lower lambda, hinges moving into the piers."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import ClassVar

from matplotlib.figure import Figure

from analytic.limit.limit_discrete import solve_lp
from dem.common.campaign import CampaignContext, pct, studies_dir, write_csv
from dem.experiments.contract import COLUMNS_ARE_FIELDS, Result, Schema
from dem.experiments.tilt.case import DEM_CASE, make_case
from dem.studies.sweep import case_key, run_study
from specimens.blocks import discretise
from specimens.constants import NO_SLIDING_MU, REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from specimens.piers import Piers

#: Pier heights of the study, as multiples of the arch's rise (0: the bare arch on the rigid base).
PIER_HEIGHTS_QUICK = (0.0, 1.0, 1.5, 2.0)
PIER_HEIGHTS_FULL = (0.0, 0.5, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5)
#: Pier width as a multiple of the ring thickness, and courses per pier: stout abutments. Piers 2 t
#: wide in 4 courses 1.5 rises tall drift out of plane under self-weight in PyBullet (3.5 mm in
#: 0.23 s; not in MuJoCo, nor planar, nor 3 t wide): docs/validation.md#15-arches-on-piers.
PIER_WIDTH_T, PIER_COURSES = 3.0, 4
#: The study's arch when the campaign has it (a mid-catalogue pointed arch), else its first specimen.
PIERS_SPECIMEN = "Sh06-Sd015"


@dataclass(frozen=True)
class PierTilt(Result):
    """One pier height's row of the piers table: the LP (no sliding, reference friction) with its hinges, the
    DEM tilt with no sliding and its hinges."""

    SCHEMA: ClassVar[Schema] = COLUMNS_ARE_FIELDS

    pier_height_m: float = field(metadata={"unit": "m"})
    height_over_rise: float
    lambda_lp_no_sliding: float
    hinges_lp: str  # "JOINT:FACE" (face's first three letters) apart by spaces
    lambda_lp_reference: float
    lambda_dem_no_sliding: float
    err_dem_vs_lp_pct: float = field(metadata={"unit": "%"})
    hinges_dem: str  # the DEM's hinged joints apart by spaces
    mode_dem: str
    hinges_in_piers: int  # the LP's hinges in the piers' joints


def piers_plan(ctx: CampaignContext) -> tuple:
    """(specimen, pier heights [m]) of the study."""
    spec = next((s for s in ctx.specimens if s.id == PIERS_SPECIMEN), ctx.specimens[0])
    heights = PIER_HEIGHTS_QUICK if ctx.quick else PIER_HEIGHTS_FULL
    return spec, [round(k * spec.arch.rise, 6) for k in heights]


def _piers(spec, height: float):
    return None if height == 0 else Piers(height, PIER_WIDTH_T * spec.arch.t, courses=PIER_COURSES)


def step_piers(ctx: CampaignContext, d: Path) -> dict:
    """Per pier height: the LP (no sliding and reference friction) with its hinges, and the DEM tilt
    lambda with no sliding and its hinges."""

    spec, heights = piers_plan(ctx)
    contact = ctx.contact_of(spec)
    settings = ({"engine": ctx.engine} if ctx.engine != "pybullet" else {}) | ctx.law_of(spec) or None  # piers of the arch's blocks
    proto = {"kind": "hold", "tol": 0.005, "start": "lp"}  # the tilt test's own protocol
    cases = {h: make_case(spec.id, spec.arch, ctx.config, NO_SLIDING_MU, NO_SLIDING_MU, protocol=proto, settings=settings,
                          contact=contact, piers=_piers(spec, h)) for h in heights}
    res = run_study(list(cases.values()), DEM_CASE, studies_dir(ctx) / "piers.h5", workers=ctx.workers,
                    scheduler=ctx.scheduler, resume=True,
                    study_attrs={"study": "campaign-piers", "config": ctx.config, "quick": ctx.quick})
    rows = []
    for h in heights:
        asm = discretise(spec.arch, config=ctx.config, contact=contact, piers=_piers(spec, h))
        lp = solve_lp(asm, math.inf, math.inf)
        lp_ref = solve_lp(asm, REFERENCE_MU_JOINT, REFERENCE_MU_BASE)
        rec = res.by_key.get(case_key(cases[h]))
        ok = rec is not None and rec.ok
        r = rec.results if ok else {}
        dem_hinges = [n for n, st in zip(r.get("joint_names") or [], r.get("joint_states") or []) if st == "hinge"]
        lam = float(r["lambda"]) if ok else math.nan
        rows += PierTilt(h, round(h / spec.arch.rise, 4), lp.lam, " ".join(f"{j}:{f[:3]}" for j, f in lp.hinges),
                         lp_ref.lam, lam, pct(lam, lp.lam), " ".join(dem_hinges), str(r["mode"]) if ok else "failed",
                         sum(j.startswith(("LP", "RP")) for j, _ in lp.hinges)).rows()
    write_csv(d / "piers.csv", rows, PierTilt.SCHEMA)

    fig = Figure(figsize=(6.4, 4.2))
    ax = fig.subplots()
    x = [r["height_over_rise"] for r in rows]
    ax.plot(x, [r["lambda_lp_no_sliding"] for r in rows], "k-o", ms=4, label="LP, no sliding")
    ax.plot(x, [r["lambda_lp_reference"] for r in rows], "k--", lw=0.8, label="LP, reference friction")
    ax.plot(x, [r["lambda_dem_no_sliding"] for r in rows], "s", color="tab:blue", mfc="none",
            label=f"DEM tilt ({ctx.engine}), no sliding")
    for r in rows:
        if r["hinges_in_piers"]:
            ax.annotate(f"{r['hinges_in_piers']} in piers", (r["height_over_rise"], r["lambda_lp_no_sliding"]),
                        textcoords="offset points", xytext=(4, 6), fontsize=7)
    ax.set_xlabel("pier height / rise of the arch")
    ax.set_ylabel("tilt lambda")
    ax.set_title(f"{spec.id} on piers {PIER_WIDTH_T:g} t wide, {PIER_COURSES} courses")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(d / "piers.png", dpi=120)

    errs = [abs(r["err_dem_vs_lp_pct"]) for r in rows]
    first = next((r for r in rows if r["hinges_in_piers"]), None)
    findings = [
        f"lambda falls from {rows[0]['lambda_lp_no_sliding']:.3f} (the ring on a rigid base) to "
        f"{rows[-1]['lambda_lp_no_sliding']:.3f} on piers {rows[-1]['height_over_rise']:g} times the rise (LP, no sliding)"
        + (f"; hinges move into the piers from {first['height_over_rise']:g} times the rise" if first else "") + ".",
        f"The DEM tilt lambda lies within {max(errs):.1f} % of the LP at every pier height "
        f"({sum(e <= 3 for e in errs)} of {len(errs)} within 3 %).",
    ]
    return {
        "summary": ctx.joints_text() + " " + f"{spec.id} on two piers {PIER_WIDTH_T:g} ring thicknesses wide in {PIER_COURSES} courses, heights "
                   f"{', '.join(f'{k:g}' for k in x)} times the rise: static LP and DEM tilt test ({ctx.engine}) with "
                   "no sliding, and the LP at the reference friction.",
        "tables": [{"name": "piers", "title": "Tilt lambda vs pier height", "csv": "piers/piers.csv"}],
        "figures": [{"path": "piers/piers.png", "caption": "Tilt lambda vs pier height: LP and DEM"}],
        "findings": findings,
    }
