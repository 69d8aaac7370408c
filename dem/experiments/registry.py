"""Every experiment, one line each: the program's sub-commands, the campaign's steps and the report's
sections and summary come from this list (docs/architecture.md#the-experiment-contract).

An experiment declares itself in its folder's ``experiment.py`` (``EXPERIMENT``, a
:class:`dem.experiments.contract.Experiment`); adding one is its folder plus one line here. The
declarations are imported when first asked for, so that importing this module loads none of them.
"""
from __future__ import annotations

import functools

from dem.experiments.contract import Experiment, Step, Summary, resolve

#: The modules that declare the experiments, in the order of ``archdem --help``.
DECLARED = (
    "dem.experiments.tilt.experiment",
    "dem.experiments.shake.experiment",
    "dem.experiments.fragility.experiment",
    "dem.experiments.friction_map.experiment",
    "dem.experiments.modes.experiment",
    "dem.experiments.record.experiment",
    "dem.experiments.assessment.experiment",
    "dem.experiments.compare_engines.experiment",
    "dem.experiments.settle.experiment",
    "dem.experiments.mode_map.experiment",
)


@functools.cache
def experiments() -> tuple[Experiment, ...]:
    """Every experiment, in the order of :data:`DECLARED`."""
    return tuple(resolve(f"{m}:EXPERIMENT") for m in DECLARED)


def steps() -> list[Step]:
    """Every experiment's campaign steps, by rank (the campaign's order)."""
    return sorted((s for e in experiments() for s in e.steps), key=lambda s: s.rank)


def summaries() -> list[Summary]:
    """The experiments' parts of the report's summary, by rank (their columns' order, left to right)."""
    return sorted((e.summary for e in experiments() if e.summary is not None), key=lambda s: s.rank)


def commands() -> list[str]:
    """The sub-command modules of every experiment, in the registry's order."""
    return [m for e in experiments() for m in e.commands]
