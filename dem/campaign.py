"""The main job: the virtual test campaign on the specimen catalogue.

A campaign is a sequence of steps; each writes its files into ``OUT/<step>/`` (built in a
temporary directory and renamed when complete, so an interrupted step leaves nothing
half-written) and is recorded in ``OUT/campaign.json``. Running the campaign again on
the same directory resumes: finished steps are kept, not recomputed.
"""
from __future__ import annotations

import json
import shutil
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from specimens.errors import ArchdemInputError


@dataclass
class CampaignContext:
    """What every step gets: output folder, options, and the log of finished steps."""

    out: Path
    specimens: list  # list[specimens.catalogue.Specimen]
    config: str = "glued"
    engine: str = "pybullet"
    quick: bool = True
    workers: int | None = None
    log: Callable[[str], None] = print
    results: dict = field(default_factory=dict)


StepFunc = Callable[[CampaignContext, Path], dict]


def step_catalogue(ctx: CampaignContext, d: Path) -> dict:
    """Catalogue table (CSV, JSON), a drawing and the meshes of every specimen."""
    from dem.cli.specimens_cmd import JSON_KEYS, catalogue_rows
    from specimens.blocks import discretise
    from specimens.drawing import save_drawing
    from specimens.mesh import export_meshes

    ids = {s.id for s in ctx.specimens}
    rows = [r for r in catalogue_rows() if r["id"] in ids]
    _write_csv(d / "catalogue.csv", rows)
    (d / "catalogue.json").write_text(json.dumps([{k: r[k] for k in JSON_KEYS} for r in rows], indent=2))
    figures = []
    for s in ctx.specimens:
        asm = discretise(s.arch, config=ctx.config)
        png = save_drawing(asm, d / "drawings" / f"{s.id}.png", title=f"{s.id}   Sh = {s.arch.Sh:.2f}, Sd = {s.arch.Sd:.2f}")
        figures.append({"path": f"catalogue/drawings/{png.name}", "caption": f"{s.id}: blocks and joints ({ctx.config})"})
        export_meshes(asm, d / "meshes" / s.id, "glb")
        export_meshes(asm, d / "meshes" / s.id, "stl")
    heaviest = max(rows, key=lambda r: r["mass"])
    return {
        "summary": f"{len(rows)} specimens, {ctx.config} configuration; meshes (GLB and one STL per convex piece) "
                   "in catalogue/meshes/.",
        "tables": [{"name": "catalogue", "title": "Specimen catalogue (SI units)", "csv": "catalogue/catalogue.csv"}],
        "figures": figures[:3] if ctx.quick else figures,
        "findings": [f"The heaviest specimen is {heaviest['id']} ({heaviest['mass']:.2f} kg glued assembly)."],
    }


def _write_csv(path: Path, rows: list[dict]) -> None:
    import csv

    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def _pct(a: float, b: float) -> float:
    return 100.0 * (a - b) / b


def step_analytic(ctx: CampaignContext, d: Path) -> dict:
    """Limit analysis of every specimen: continuous, 80 % thickness, discrete, LP, two-bar."""
    import numpy as np

    from analytic.figures_limit import catalogue_figures
    from analytic.limit_continuous import continuous_collapse
    from analytic.limit_discrete import enumerate_mechanisms
    from analytic.summary import analyse, multiplier_series
    from specimens.blocks import discretise
    from specimens.catalogue import CATALOGUE, REFERENCE_MU_BASE, REFERENCE_MU_JOINT

    # the figures' series of the whole catalogue also gives the 80 % thickness multipliers
    series = multiplier_series(CATALOGUE)
    lam80_of = {r["id"]: r["cont08"] for r in series}
    # each profile is solved once: the series' result is reused for a specimen with that very arch
    cont_of = {r["id"]: (c.arch, r["continuous"]) for c, r in zip(CATALOGUE, series)}
    rows = []
    for s in ctx.specimens:
        arch_c, cont = cont_of.get(s.id, (None, None))
        a = analyse(s.arch, ctx.config, REFERENCE_MU_JOINT, REFERENCE_MU_BASE,
                    continuous=cont if arch_c == s.arch else None)
        other = "free" if ctx.config == "glued" else "glued"
        lam_other = enumerate_mechanisms(discretise(s.arch, config=other)).lam
        lam80 = lam80_of[s.id] if s.id in lam80_of else continuous_collapse(s.arch, effective_thickness=0.8).lam
        sliding = [j for j, v in a["joints_lp"].items() if "sliding" in v["state"]]
        rows.append({
            "id": s.id, "Sh": round(s.arch.Sh, 6), "Sd": round(s.arch.Sd, 6),
            "lambda_continuous": a["lambda_continuous"], "lambda_continuous_80pct": lam80,
            f"lambda_discrete_{ctx.config}": a["lambda_discrete"], f"lambda_discrete_{other}": lam_other,
            "lambda_lp_reference_friction": a["lambda_lp"], "lambda_two_bar": a["lambda_two_bar"],
            "mu_star_two_bar": a["mu_star"],
            "hinges_discrete": " ".join(f"{h['joint']}:{h['face'][0]}" for h in a["hinges_discrete"]),
            "hinges_continuous_rad": " ".join(f"{h['half'][0].upper()}{h['angle_rad']:.3f}{h['face'][0]}"
                                              for h in a["hinges_continuous"]),
            "lp_sliding_joints": " ".join(sliding),
        })
    _write_csv(d / "analytic.csv", rows)
    figs = catalogue_figures(d / "figures", full_scale=True, rows=series)
    keep = [f for f in figs if "mechanism" not in f.name] + [f for f in figs if "mechanism" in f.name][:2]
    figures = [{"path": f"analytic/figures/{f.name}", "caption": f.stem.replace("_", " ")} for f in keep]
    # findings computed from the rows
    lc = np.array([r["lambda_continuous"] for r in rows])
    ld = np.array([r[f"lambda_discrete_{ctx.config}"] for r in rows])
    gap = 100 * (ld - lc) / ld
    k = int(np.argmax(gap))
    findings = [
        f"Continuous-profile lambda is below the discrete one for {int(np.sum(lc <= ld + 1e-12))} of {len(rows)} "
        f"specimens; the largest gap is {gap[k]:.1f} % ({rows[k]['id']}).",
    ]
    by_sh: dict[float, list] = {}
    for r in rows:
        by_sh.setdefault(r["Sh"], []).append(r)
    mono = [sh for sh, rs in by_sh.items() if len(rs) > 1 and
            all(b["lambda_continuous"] > a["lambda_continuous"] for a, b in zip(sorted(rs, key=lambda r: r["Sd"]), sorted(rs, key=lambda r: r["Sd"])[1:]))]
    if len(by_sh) > 0:
        findings.append(f"lambda grows with slenderness Sd at fixed sharpness for Sh = {', '.join(f'{x:g}' for x in sorted(mono)) or 'none'}"
                        f" (of {', '.join(f'{x:g}' for x in sorted(by_sh))}).")
    base = sum(1 for r in rows if any(h.split(':')[0] in ('L0', 'R0') for h in r["hinges_discrete"].split()))
    findings.append(f"The discrete mechanism has a hinge at a springing (base joint) in {base} of {len(rows)} specimens.")
    red = np.array([_pct(r["lambda_continuous_80pct"], r["lambda_continuous"]) for r in rows])
    findings.append(f"An 80 % effective thickness lowers the continuous lambda by {-red.max():.0f}-{-red.min():.0f} %.")
    slid = [r["id"] for r in rows if r["lp_sliding_joints"]]
    findings.append(f"At the reference friction ({REFERENCE_MU_JOINT}/{REFERENCE_MU_BASE}) the associative LP has sliding joints in "
                    f"{len(slid)} specimens{': ' + ', '.join(slid) if slid else ''}.")
    return {
        "summary": "Limit analysis: four-hinge mechanism on the continuous profile (global search), discrete "
                   "enumeration of the actual voussoirs, static LP with Coulomb friction, two-bar sliding model.",
        "tables": [{"name": "analytic", "title": "Limit analysis per specimen", "csv": "analytic/analytic.csv"}],
        "figures": figures, "findings": findings,
    }


# name -> (function, description); later steps are appended by the modules that provide them
STEPS: dict[str, tuple[StepFunc, str]] = {
    "catalogue": (step_catalogue, "specimen catalogue, drawings and meshes"),
    "analytic": (step_analytic, "limit analysis of every specimen"),
}


def all_steps() -> dict[str, tuple[StepFunc, str]]:
    """Every campaign step in order (the simulator steps are registered on first use)."""
    from dem import campaign_dem as cd

    STEPS["tilt"] = (cd.step_tilt, "virtual tilt test of every specimen vs limit analysis")
    STEPS["map"] = (cd.step_map, "friction threshold map (rocking / sliding)")
    STEPS["shake"] = (cd.step_shake, "shake-table thresholds, one-cycle sine pulses, vs four-bar")
    STEPS["record"] = (cd.step_record, "recorded accelerogram scaled until collapse")
    return STEPS


def run_campaign(ctx: CampaignContext, steps: list[str] | None = None) -> dict:
    """Run (or resume) the campaign; return the manifest."""
    all_steps()
    out = ctx.out
    out.mkdir(parents=True, exist_ok=True)
    manifest_path = out / "campaign.json"
    manifest = json.loads(manifest_path.read_text()) if manifest_path.exists() else {}
    params = {"specimens": [s.id for s in ctx.specimens], "config": ctx.config, "engine": ctx.engine, "quick": ctx.quick}
    if manifest and manifest.get("parameters") != params:
        raise ArchdemInputError(
            f"{out} holds a campaign with other parameters ({manifest.get('parameters')}); choose another --out"
        )
    from dem.provenance import provenance

    manifest.setdefault("parameters", params)
    manifest.setdefault("steps", {})
    manifest["provenance"] = provenance()
    for name in steps or list(STEPS):
        func, desc = STEPS[name]
        if name in manifest["steps"] and (out / name).is_dir():
            ctx.log(f"[{name}] already done ({desc}); kept")
            ctx.results[name] = manifest["steps"][name]["outputs"]
            continue
        ctx.log(f"[{name}] {desc} ...")
        tmp = out / f".{name}.part"
        if tmp.exists():
            shutil.rmtree(tmp)
        tmp.mkdir()
        t0 = time.perf_counter()
        outputs = func(ctx, tmp)
        wall = time.perf_counter() - t0
        final = out / name
        if final.exists():
            shutil.rmtree(final)
        tmp.rename(final)
        ctx.results[name] = outputs
        manifest["steps"][name] = {"outputs": outputs, "wall_s": wall}
        _write_json_atomic(manifest_path, manifest)
        ctx.log(f"[{name}] done in {wall:.1f} s")
    from dem.report import build_report

    rep = build_report(out, manifest, {k: v[1] for k, v in STEPS.items()})
    manifest["report"] = rep["report"]
    _write_json_atomic(manifest_path, manifest)
    return manifest


def _write_json_atomic(path: Path, obj: dict) -> None:
    from dem.atomic import atomic_path

    with atomic_path(path, overwrite=True) as tmp:
        tmp.write_text(json.dumps(obj, indent=2, default=str))
