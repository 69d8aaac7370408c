"""The fragility experiment as the program and the campaign see it (dem.experiments.contract)."""
from __future__ import annotations

from dem.experiments.contract import Experiment, Step

EXPERIMENT = Experiment(
    name="fragility", title="fragility curves from ensembles of perturbed realisations",
    commands=("dem.experiments.fragility.fragility_cmd",),
    steps=(Step("fragility", "dem.experiments.fragility.step_fragility:step_fragility",
                "fragility curves from ensembles of perturbed realisations under sine pulses", rank=110,
                optional=True),),
)
