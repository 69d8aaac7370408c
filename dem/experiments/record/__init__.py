"""Recorded accelerograms: the DEM runs of records for an assessment, what a record file holds and the
record step's row (``run``), the command ``record`` and the campaign step ``record``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "run_records": "dem.experiments.record.run", "RecordRun": "dem.experiments.record.run",
    "dem_verdict": "dem.experiments.record.run", "RecordSpec": "dem.experiments.record.run",
    "RecordSummary": "dem.experiments.record.run", "RecordThreshold": "dem.experiments.record.run",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.record.run import (
        RecordRun,
        RecordSpec,
        RecordSummary,
        RecordThreshold,
        dem_verdict,
        run_records,
    )

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
