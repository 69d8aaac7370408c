"""The map step: the DEM friction map (rocking/sliding threshold mu*) against the LP (with and without
dilatancy) and the two-bar."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from dem.common.campaign import CampaignContext, studies_dir, write_csv
from dem.experiments.friction_map.run import LP_MU_TOL, MapSpec, SpecimenMap, run
from specimens.constants import REFERENCE_MU_BASE

QUICK_MAP = ("Sh02-Sd015", "Sh1-Sd025")  # quick map: the thin/round-ish and the thick/sharp end


def map_plan(ctx: CampaignContext) -> tuple[list, str, int]:
    """Specimens, friction grid and bisection rounds of the map step."""
    if ctx.quick:
        return [s for s in ctx.specimens if s.id in QUICK_MAP] or ctx.specimens[:2], "0.3,0.6,0.9,1.2", 1
    return ctx.specimens, "0.3:1.5:0.1", 3


# ------------------------------------------------------------------------------ friction map
def step_map(ctx: CampaignContext, d: Path) -> dict:
    """Rocking/sliding friction threshold of every specimen (coarse grid when quick)."""
    specs, mus, refine = map_plan(ctx)
    spec = MapSpec(specs, ctx.config, mus, REFERENCE_MU_BASE, refine=refine,
                   settings={"engine": ctx.engine} if ctx.engine != "pybullet" else None,
                   contact={s.id: ctx.contact_of(s) for s in specs},
                   law={s.id: ctx.law_of(s) for s in specs} if ctx.joints else None)
    path = studies_dir(ctx) / "map.h5"
    res = run(spec, path, workers=ctx.workers, scheduler=ctx.scheduler, resume=path.exists(), progress=True)
    write_csv(d / "map.csv", res.to_rows("summary"), SpecimenMap.SCHEMA)
    write_csv(d / "map_points.csv", res.to_rows("points"), SpecimenMap.POINTS_SCHEMA)
    figs = res.figures(d / "figures")
    rows = res.to_rows("summary")
    findings = []
    br = [r for r in rows if r["mu_star_dem"] is not None and r["mu_star_dem"] == r["mu_star_dem"]]
    if br:
        diffs = [(r["id"], r["mu_star_dem"] - r["mu_star_two_bar"]) for r in br if r["mu_star_two_bar"] is not None]
        values = ", ".join(f"{r['id']} {r['mu_star_dem']:.2f}" for r in br)
        findings.append(f"The DEM rocking/sliding threshold mu* is bracketed for {len(br)} of {len(rows)} specimens: {values}.")
        if diffs:
            above = sum(1 for _, x in diffs if x > 0)
            findings.append(f"The two-bar model's mu* is below the DEM mu* for {above} of {len(diffs)} bracketed specimens "
                            f"(mean difference DEM - two-bar {np.mean([x for _, x in diffs]):+.2f}).")
    findings += non_associative_findings(rows, res.wall_s, ctx.quick)
    for sh in sorted({r["Sh"] for r in br}):
        rs = sorted((r for r in br if r["Sh"] == sh), key=lambda r: r["Sd"])
        if len(rs) > 1:
            inc = all(b["mu_star_dem"] >= a["mu_star_dem"] for a, b in zip(rs, rs[1:]))
            values = ", ".join(f"{r['mu_star_dem']:.2f}" for r in rs)
            findings.append(f"Sh = {sh:g}: DEM mu* {'grows' if inc else 'does not grow monotonically'} with Sd ({values}).")
    for status, text in (("all_rocking", "Rocking already at the lowest friction of the grid"),
                         ("all_sliding", "Still sliding at the highest friction of the grid")):
        ids = [r["id"] for r in rows if r["dem_status"] == status]
        if ids:
            findings.append(f"{text}: {', '.join(ids)}.")
    return {
        "summary": ctx.joints_text() + " " + f"Tilt test of {len(specs)} specimens swept over block-block friction ({mus}; base {REFERENCE_MU_BASE}), mu* refined by "
                   f"bisection ({res.rounds} round(s)); analytic LP (with and without dilatancy) and two-bar "
                   "thresholds beside it. "
                   f"{res.n_cases} tilt tests, {res.n_failed} failed.",
        "tables": [{"name": "map", "title": "Friction thresholds mu* per specimen", "csv": "map/map.csv"},
                   {"name": "map_points", "title": "Tilt results of the friction sweep", "csv": "map/map_points.csv"}],
        "figures": [{"path": f"map/figures/{f.name}", "caption": f.stem.replace("_", " ")} for f in figs],
        "findings": findings,
    }


def non_associative_findings(rows: list[dict], wall_s: float, quick: bool = False) -> list[str]:
    """Findings on the mu* without dilatancy, from the map's summary rows: against the DEM's where both
    exist, against the associative LP's, and what it cost of the step's ``wall_s`` [s]."""
    out = []
    na = [r for r in rows if r.get("mu_star_na") is not None]
    both = [r for r in na if r["mu_star_dem"] is not None and r["mu_star_dem"] == r["mu_star_dem"]]
    if both:
        diffs = [r["mu_star_dem"] - r["mu_star_na"] for r in both]
        values = ", ".join(f"{r['id']} {r['mu_star_dem']:.2f} / {r['mu_star_na']:.2f}" for r in both)
        out.append(f"The non-associative mu* (limit analysis without dilatancy) is below the DEM mu* for "
                   f"{sum(x > 0 for x in diffs)} of {len(both)} specimens where both exist (mean difference DEM - "
                   f"no dilatancy {np.mean(diffs):+.2f}; DEM / no dilatancy: {values}).")
    lp = [r for r in na if r["mu_star_lp"] is not None]
    if lp:
        gap = [r["mu_star_na"] - r["mu_star_lp"] for r in lp]
        same = sum(abs(x) <= LP_MU_TOL for x in gap)
        out.append(f"Without dilatancy mu* equals the associative LP's (to the bisection tolerance {LP_MU_TOL:g}) for "
                   f"{same} of {len(lp)} specimens" + (f"; it is above it by up to {max(gap):.3f} for the others."
                                                       if same < len(lp) else "."))
    spent = sum(r.get("seconds_na") or 0.0 for r in rows)
    if spent:
        # a mixed-integer program per friction value: say what it cost beside the tilts
        share = spent / wall_s if wall_s > 0 else 1.0
        out.append(f"The references without dilatancy (mu* and lambda on the grid) took {spent:.0f} s of the step's "
                   f"{wall_s:.0f} s ({share:.0%}; {spent / len(rows):.0f} s a specimen)"
                   + (": a large share of this quick run." if quick and share > 0.25 else "."))
    return out
