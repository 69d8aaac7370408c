"""The friction map as the program and the campaign see it (dem.experiments.contract)."""
from __future__ import annotations

from dem.experiments.contract import Experiment, Step

EXPERIMENT = Experiment(
    name="friction_map", title="the rocking/sliding threshold friction mu*",
    commands=("dem.experiments.friction_map.map_cmd",),
    steps=(Step("map", "dem.experiments.friction_map.step_map:step_map",
                "friction threshold map (rocking / sliding)", rank=60),),
)
