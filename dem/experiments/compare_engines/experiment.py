"""The engine comparison as the program sees it (dem.experiments.contract): commands, no campaign step."""
from __future__ import annotations

from dem.experiments.contract import Experiment

EXPERIMENT = Experiment(
    name="compare_engines", title="the engines against limit analysis and against each other",
    commands=("dem.experiments.compare_engines.compare_engines_cmd", "dem.experiments.compare_engines.compare_shake_cmd"),
)
