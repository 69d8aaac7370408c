"""The catalogue step: the specimens' table, drawings and meshes."""
from __future__ import annotations

import json
from pathlib import Path

from dem.common.campaign import CampaignContext, write_csv
from specimens.blocks import discretise
from specimens.catalogue import JSON_KEYS, catalogue_rows
from specimens.drawing import save_drawing
from specimens.mesh import export_meshes


def step_catalogue(ctx: CampaignContext, d: Path) -> dict:
    """Catalogue table (CSV, JSON), a drawing and the meshes of every specimen."""
    ids = {s.id for s in ctx.specimens}
    rows = [r for r in catalogue_rows() if r["id"] in ids]
    write_csv(d / "catalogue.csv", rows)
    (d / "catalogue.json").write_text(json.dumps([{k: r[k] for k in JSON_KEYS} for r in rows], indent=2))
    figures = []
    for s in ctx.specimens:
        asm = discretise(s.arch, config=ctx.config, contact=ctx.contact_of(s))
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
