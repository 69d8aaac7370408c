"""The friction map: the rocking/sliding threshold friction mu* (``run``), the figure (``figure``),
the command's options (``spec``), the command ``map`` and the campaign step ``map``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "catalogue_map": "dem.experiments.friction_map.run", "MapResult": "dem.experiments.friction_map.run",
    "MapSpec": "dem.experiments.friction_map.run",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.friction_map.run import MapResult, MapSpec, catalogue_map

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
