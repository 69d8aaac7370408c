"""The shake table as the program, the campaign and the report see it (dem.experiments.contract)."""
from __future__ import annotations

import math

from dem.experiments.contract import Experiment, Step, Summary, Tables, fmt


def summary_cells(tables: Tables, sid: str) -> tuple[str]:
    """The least DEM shake threshold of specimen ``sid`` [g] and its frequency [Hz] ("" if none was found)."""
    found = [r for r in tables.get("shake", []) if r.get("id") == sid
             and isinstance(r.get("a_dem_g"), float) and not math.isnan(r["a_dem_g"])]
    low = min(found, key=lambda r: r["a_dem_g"]) if found else None
    return ("" if low is None else f"{fmt(low['a_dem_g'])} g at {fmt(low['freq_Hz'])} Hz",)


EXPERIMENT = Experiment(
    name="shake", title="the shake table, its thresholds and DEM failure domains",
    commands=("dem.experiments.shake.domain_cmd", "dem.experiments.shake.shake_cmd",
              "dem.experiments.shake.threshold_cmd", "dem.experiments.shake.animate_cmd"),
    steps=(Step("shake", "dem.experiments.shake.step_shake:step_shake",
                "shake-table thresholds, one-cycle sine pulses, vs four-bar", rank=70),),
    summary=Summary(columns=("least shake threshold (DEM)",), cells=summary_cells, ids=("shake",), rank=20),
)
