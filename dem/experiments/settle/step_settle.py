"""The settle step (optional): the rest state of every specimen of the campaign."""
from __future__ import annotations

from pathlib import Path

from dem.common.campaign import CampaignContext, write_csv
from dem.core.settings import Settings
from dem.experiments.settle.run import SettleResult, SettleSpec, run
from dem.experiments.tilt import TiltProtocol
from specimens.blocks import discretise


def step_settle(ctx: CampaignContext, d: Path) -> dict:
    """Each specimen's blocks (the campaign's configuration, contact fraction and joints) left 1 s under
    gravity on the tilt test's engine."""
    results = []
    for s in ctx.specimens:
        c = ctx.contact_of(s)
        asm = discretise(s.arch, config=ctx.config, **({"contact": c} if c != 1.0 else {}))
        results.append(run(SettleSpec(asm, ctx.config, Settings(engine=ctx.engine, **ctx.law_of(s)), label=s.id)))
    write_csv(d / "settle.csv", [r for res in results for r in res.rows()], SettleResult.SCHEMA)
    still = [r.id for r in results if not r.at_rest]
    worst = max(results, key=lambda r: r.max_displacement_mm)
    return {
        "summary": f"{ctx.joints_text()} The {ctx.config} blocks of every specimen built in place and left "
                   f"{results[0].duration_s:g} s under gravity on their base ({ctx.engine}); at rest by the tilt "
                   f"test's rest rule over the last {TiltProtocol().rest_window:g} s.",
        "tables": [{"name": "settle", "title": "Rest state under gravity", "csv": "settle/settle.csv"}],
        "findings": [f"{len(results) - len(still)} of {len(results)} specimens at rest after {results[0].duration_s:g} s"
                     + (f" ({', '.join(still)} not)" if still else "")
                     + f"; the largest block displacement {worst.max_displacement_mm:.3g} mm ({worst.id})."],
    }
