"""Natural frequencies on compliant joints: DEM free vibration (``run``) beside the analytic modes,
the figure (``figure``), the command's spec and result (``spec``), the command ``modes`` and the campaign step ``modes``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "free_vibration": "dem.experiments.modes.run", "Vibration": "dem.experiments.modes.run",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.modes.run import Vibration, free_vibration

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
