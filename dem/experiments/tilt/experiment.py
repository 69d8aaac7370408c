"""The tilt test as the program, the campaign and the report see it (dem.experiments.contract)."""
from __future__ import annotations

from dem.experiments.contract import Experiment, Step, Summary, Tables, fmt


def _first(tables: Tables, name: str, sid: str, col: str) -> str:
    """The text of ``col`` in the first row of table ``name`` about specimen ``sid`` ("" if none)."""
    r = next((r for r in tables.get(name, []) if r.get("id") == sid), None)
    return "" if r is None else fmt(r.get(col))


def summary_cells(tables: Tables, sid: str) -> tuple[str, str, str]:
    """lambda of the laboratory, of the limit analysis (the analytic step's, else the lab step's LP) and of
    the DEM (the lab step's calibrated stand-in)."""
    lam_la = next((v for c in ("lambda_discrete_free", "lambda_discrete_glued")
                   if (v := _first(tables, "analytic", sid, c))), "") or _first(tables, "lab", sid, "lambda_lp_effective")
    return (_first(tables, "lab", sid, "lambda_lab_mean"), lam_la, _first(tables, "lab", sid, "lambda_dem_effective_mean"))


EXPERIMENT = Experiment(
    name="tilt", title="tilt test, tilt ensembles of imperfect joints, arches on piers",
    commands=("dem.experiments.tilt.calibrate_cmd", "dem.experiments.tilt.tilt_cmd"),
    steps=(
        Step("tilt", "dem.experiments.tilt.step_tilt:step_tilt",
             "virtual tilt test of every specimen vs limit analysis", rank=40),
        Step("lab", "dem.experiments.tilt.step_lab:step_lab",
             "virtual vs physical: calibrated imperfect joints against the laboratory tilt tests", rank=50),
        Step("piers", "dem.experiments.tilt.step_piers:step_piers",
             "one arch on piers of growing height: limit analysis and DEM tilt", rank=90, optional=True),
    ),
    # the limit analysis's column sits between the laboratory's and the DEM's: the lambdas side by side
    summary=Summary(columns=("lambda laboratory", "lambda limit analysis", "lambda DEM"), cells=summary_cells,
                    ids=("lab", "analytic"), rank=10),
)
