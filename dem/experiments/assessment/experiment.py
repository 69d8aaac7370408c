"""The code assessment as the program, the campaign and the report see it (dem.experiments.contract)."""
from __future__ import annotations

from dem.experiments.contract import Experiment, Step, Summary, Tables, fmt


def summary_table(tables: Tables) -> tuple[str, tuple[str, ...], list[tuple[str, ...]]] | None:
    """The monument's verdicts, with and without FRP strips (None when the assess step did not run)."""
    rows = tables.get("assess")
    if not rows:
        return None
    return ("Noh Gumbad: code checks (SLV) and the published convention",
            ("configuration", "FRP", "lambda", "a0*/PGA", "SI linear", "SI displacement", "verdict"),
            [(fmt(r["configuration"]), "yes" if r["frp"] else "no", fmt(r["lambda"]),
              fmt(r.get("a0_over_pga_published_convention")), fmt(r["safety_index_linear"]),
              fmt(r["safety_index_displacement"]), "verified" if r["verified"] else "NOT verified") for r in rows])


EXPERIMENT = Experiment(
    name="assessment", title="the code assessment, the shipped drawing end to end",
    commands=("dem.experiments.assessment.assess_cmd",),
    steps=(
        Step("assess", "dem.experiments.assessment.step_assess:step_assess",
             "code-based assessment of the Noh Gumbad vaults, with and without FRP strips", rank=100),
        Step("drawing", "dem.experiments.assessment.step_drawing:step_drawing",
             "the shipped drawing of an arch on piers: limit analysis, DEM tilt, code checks", rank=120, optional=True),
    ),
    summary=Summary(table=summary_table),
)
