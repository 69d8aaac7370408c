"""The modes experiment as the program and the campaign see it (dem.experiments.contract)."""
from __future__ import annotations

from dem.experiments.contract import Experiment, Step

EXPERIMENT = Experiment(
    name="modes", title="natural frequencies and free vibration on compliant joints",
    commands=("dem.experiments.modes.modes_cmd",),
    steps=(Step("modes", "dem.experiments.modes.step_modes:step_modes",
                "natural frequencies of every specimen on compliant joints", rank=30),),
)
