"""The shake table: one run (``run``), thresholds (``thresholds``), DEM failure domains (``domain``),
the result file (``file``), figures and animations (``figure``, ``animation``), the options of ``shake``
and ``threshold`` as specs (``spec``), the commands ``shake``, ``threshold``, ``animate``, ``domain`` and
``rock`` and the campaign step ``shake``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "shake": "dem.experiments.shake.run", "ShakeProtocol": "dem.experiments.shake.run",
    "ShakeResult": "dem.experiments.shake.run", "ShakeSpec": "dem.experiments.shake.run",
    "ThresholdSpec": "dem.experiments.shake.thresholds", "DomainThreshold": "dem.experiments.shake.domain",
    "threshold": "dem.experiments.shake.thresholds", "static_onset": "dem.experiments.shake.thresholds",
    "ThresholdResult": "dem.experiments.shake.thresholds", "Verdict": "dem.experiments.shake.thresholds",
    "check_threshold": "dem.experiments.shake.thresholds", "reference_needed": "dem.experiments.shake.thresholds",
    "CHECK_MARGIN": "dem.experiments.shake.thresholds",
    "dem_failure_domain": "dem.experiments.shake.domain",
    "load_shake": "dem.experiments.shake.file", "save_shake": "dem.experiments.shake.file",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.shake.run import ShakeProtocol, ShakeResult, ShakeSpec, shake
    from dem.experiments.shake.thresholds import (
        CHECK_MARGIN,
        ThresholdResult,
        ThresholdSpec,
        Verdict,
        check_threshold,
        reference_needed,
        static_onset,
        threshold,
    )
    from dem.experiments.shake.domain import DomainThreshold, dem_failure_domain
    from dem.experiments.shake.file import load_shake, save_shake

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
