"""The shake table's mode map: per specimen and frequency of a one-cycle sine, the first collapse within a
speed-limited table's reach, its failure mode and the joint that slips first (``run``: ``ModeMapSpec`` ->
``run.run`` -> ``ModeMapResult``, ``run.read`` without running), the sweep's case function (``case``), the
figure (``figure``) and the optional campaign step ``mode-map`` (``step_mode_map``); declared in ``experiment``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "ModeMapSpec": "dem.experiments.mode_map.run", "ModeMapResult": "dem.experiments.mode_map.run",
    "mode_case": "dem.experiments.mode_map.case", "first_slip": "dem.experiments.mode_map.case",
    "reach_g": "dem.experiments.mode_map.case", "servo_motion": "dem.experiments.mode_map.case",
    "SLIP_MM": "dem.experiments.mode_map.case", "mode_map_figure": "dem.experiments.mode_map.figure",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.mode_map.case import SLIP_MM, first_slip, mode_case, reach_g, servo_motion
    from dem.experiments.mode_map.figure import mode_map_figure
    from dem.experiments.mode_map.run import ModeMapResult, ModeMapSpec

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
