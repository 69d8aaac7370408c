"""The settle experiment as the program, the campaign and the report see it (dem.experiments.contract)."""
from __future__ import annotations

from dem.experiments.contract import Experiment, Step

EXPERIMENT = Experiment(
    name="settle", title="the rest state of an arch",
    commands=("dem.experiments.settle.settle_cmd",),
    steps=(Step("settle", "dem.experiments.settle.step_settle:step_settle",
                "the rest state of every specimen: its blocks left under gravity on their base", rank=130,
                optional=True),),
)
