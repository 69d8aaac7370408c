"""Fragility: ensembles of perturbed realisations under sine pulses (``run``), a study's parts from
what a user gives (``inputs``), the result file (``file``), the figure (``figure``), the command
``fragility`` and the campaign step ``fragility``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "fragility": "dem.experiments.fragility.run", "FragilityResult": "dem.experiments.fragility.run",
    "Perturbation": "dem.experiments.fragility.run", "arch_structure": "dem.experiments.fragility.run",
    "sine_spec": "dem.experiments.fragility.run", "record_spec": "dem.experiments.fragility.run",
    "FragilitySpec": "dem.experiments.fragility.run",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.fragility.run import (
        FragilityResult,
        FragilitySpec,
        Perturbation,
        arch_structure,
        fragility,
        record_spec,
        sine_spec,
    )

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
