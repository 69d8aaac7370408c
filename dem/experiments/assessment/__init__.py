"""The code-based assessment of a monument: the figure (``figure``), the command ``assess`` and the
campaign step ``assess``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "assess_with_records": "dem.experiments.assessment.run", "ArchAssessment": "dem.experiments.assessment.run",
    "AssessSpec": "dem.experiments.assessment.run", "MonumentSpec": "dem.experiments.assessment.run",
    "MonumentAssessment": "dem.experiments.assessment.run", "AssessOptions": "dem.experiments.assessment.spec",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.assessment.run import (
        ArchAssessment,
        AssessSpec,
        MonumentAssessment,
        MonumentSpec,
        assess_with_records,
    )
    from dem.experiments.assessment.spec import AssessOptions

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
