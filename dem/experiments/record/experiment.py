"""The record experiment as the program and the campaign see it (dem.experiments.contract)."""
from __future__ import annotations

from dem.experiments.contract import Experiment, Step

EXPERIMENT = Experiment(
    name="record", title="recorded accelerograms",
    commands=("dem.experiments.record.record_cmd",),
    steps=(Step("record", "dem.experiments.record.step_record:step_record",
                "recorded accelerogram scaled until collapse", rank=80),),
)
