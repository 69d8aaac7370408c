"""The tilt test: the run (``run``), its check against limit analysis (``check``), the study case
(``case``), ensembles of imperfect joints (``ensemble``), the result file (``file``), the figure
(``figure``), the command's options (``spec``), the commands ``tilt`` and ``calibrate`` and the campaign steps ``tilt``, ``lab`` and ``piers``.

The names below are its contract: the other experiments import them from this package, never from
its modules (docs/architecture.md).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use, so that importing this package stays light)
_EXPORTS = {
    "tilt": "dem.experiments.tilt.run", "TiltProtocol": "dem.experiments.tilt.run", "TiltSpec": "dem.experiments.tilt.run",
    "TiltResult": "dem.experiments.tilt.run", "RC_REF": "dem.experiments.tilt.run",
    "TiltCheck": "dem.experiments.tilt.check", "check_result": "dem.experiments.tilt.check",
    "reference_lp": "dem.experiments.tilt.check",
    "DEM_CASE": "dem.experiments.tilt.case", "MAP_PROTOCOL": "dem.experiments.tilt.case",
    "MAP_TILT_TOL": "dem.experiments.tilt.case", "make_case": "dem.experiments.tilt.case",
    "scaled_protocol": "dem.experiments.tilt.case",
    "load_result": "dem.experiments.tilt.file", "save_result": "dem.experiments.tilt.file",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from dem.experiments.tilt.run import RC_REF, TiltProtocol, TiltResult, TiltSpec, tilt
    from dem.experiments.tilt.check import TiltCheck, check_result, reference_lp
    from dem.experiments.tilt.case import DEM_CASE, MAP_PROTOCOL, MAP_TILT_TOL, make_case, scaled_protocol
    from dem.experiments.tilt.file import load_result, save_result

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
