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
    import csv

    from dem.cli.specimens_cmd import JSON_KEYS, catalogue_rows
    from specimens.blocks import discretise
    from specimens.drawing import save_drawing
    from specimens.mesh import export_meshes

    ids = {s.id for s in ctx.specimens}
    rows = [r for r in catalogue_rows() if r["id"] in ids]
    with open(d / "catalogue.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
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


# name -> (function, description); later steps are appended by the modules that provide them
STEPS: dict[str, tuple[StepFunc, str]] = {
    "catalogue": (step_catalogue, "specimen catalogue, drawings and meshes"),
}


def run_campaign(ctx: CampaignContext, steps: list[str] | None = None) -> dict:
    """Run (or resume) the campaign; return the manifest."""
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
