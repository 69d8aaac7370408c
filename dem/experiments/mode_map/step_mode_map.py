"""The mode-map step (optional): the shake table's mode map of the campaign's specimens."""
from __future__ import annotations

from pathlib import Path

from dem.common.campaign import CampaignContext, studies_dir
from dem.common.figures import save_figure
from dem.experiments.mode_map.figure import mode_map_figure
from dem.experiments.mode_map.run import ModeMapSpec, run


def step_mode_map(ctx: CampaignContext, d: Path) -> dict:
    """Every specimen of the campaign at every frequency of the map, the fitted table of the defaults
    (:class:`ModeMapSpec`) with the campaign's contact fraction; the searches run as one resumable study
    on the campaign's workers (``studies/mode-map.h5``: an interrupted step resumes its cases)."""
    spec = ModeMapSpec(specimens=tuple(s.id for s in ctx.specimens), contact=ctx.contact)
    res = run(spec, studies_dir(ctx) / "mode-map.h5", workers=ctx.workers, scheduler=ctx.scheduler, resume=True)
    res.write_csv(d / "mode_map.csv")
    save_figure(mode_map_figure(res.rows(), spec.title()), d / "mode_map.png", dpi=130)
    speed = "the ideal sine" if spec.table_speed is None else f"a servo of {spec.table_speed:g} m/s, " + (
        "velocity command" if spec.tau is None else f"position loop {spec.tau * 1e3:g} ms")
    return {
        "summary": f"Per specimen and one-cycle sine of {', '.join(f'{f:g}' for f in spec.freqs)} Hz, the least "
                   f"commanded amplitude that brings the glued arch down on the dynamics engine's defaults (whatever "
                   f"the campaign's configuration, engine and joint law), the table {speed}: the "
                   f"scan from the static onset reaches {spec.scan_over:g} x the table's reach pi f v, bisected "
                   "to 1 %; the collapsing run read again for the joint that slips first (both its ends more than "
                   f"{spec.slip_mm:g} mm along it) and the half cycle it slips in.",
        "tables": [{"name": "mode_map", "title": "The mode map, a row per search", "csv": "mode-map/mode_map.csv"}],
        "figures": [{"path": "mode-map/mode_map.png",
                     "caption": "The mode map: specimens by frequency, coloured by the mode of the first collapse"}],
        "findings": res.findings(),
    }
