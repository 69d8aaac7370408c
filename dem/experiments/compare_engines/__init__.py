"""Both engines against limit analysis (``run``: ``CompareSpec`` -> ``EngineComparison``), the figure
(``figure``), the command ``compare-engines``; the engines against each other on the shake table
(``shake``: ``ShakeStudySpec`` -> ``ShakeStudy``), the command ``compare-shake``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "compare": "dem.experiments.compare_engines.run", "ComparisonRow": "dem.experiments.compare_engines.run",
    "summary": "dem.experiments.compare_engines.run",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.compare_engines.run import ComparisonRow, compare, summary

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
