"""The simulator: virtual tilt and shake-table tests of rigid-block arches (PyBullet, or MuJoCo),
collapse and per-joint failure modes, thresholds, friction maps, studies and the campaign.

    >>> from dem import ground_motion, shake, tilt
    >>> t = tilt("Sh06-Sd015")                 # a catalogue id, Specimen, PointedArch, Assembly or Model
    >>> s = shake("Sh02-Sd020", ground_motion(sine=4.0, amplitude=0.5))   # Hz and g, as the CLI
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use)
_EXPORTS = {
    "ground_motion": "analytic.motions.records", "example_record": "analytic.motions.records",
    "Model": "dem.core.model", "as_model": "dem.core.model", "from_assembly": "dem.core.model",
    "Settings": "dem.core.settings",
    "SimResult": "dem.core.simulate", "simulate": "dem.core.simulate",
    "dem_failure_domain": "dem.experiments.shake.domain",
    "assess_with_records": "dem.experiments.assessment.run",
    "catalogue_map": "dem.experiments.friction_map.run",
    "ShakeProtocol": "dem.experiments.shake.run", "ShakeResult": "dem.experiments.shake.run", "shake": "dem.experiments.shake.run",
    "ThresholdResult": "dem.experiments.shake.thresholds", "failure_domain": "dem.experiments.shake.thresholds", "static_onset": "dem.experiments.shake.thresholds", "threshold": "dem.experiments.shake.thresholds",
    "TiltProtocol": "dem.experiments.tilt.run", "TiltResult": "dem.experiments.tilt.run", "tilt": "dem.experiments.tilt.run",
    "load_shake": "dem.experiments.shake.file", "save_shake": "dem.experiments.shake.file",
    "load_result": "dem.experiments.tilt.file", "save_result": "dem.experiments.tilt.file",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from analytic.motions.records import example_record, ground_motion
    from dem.core.model import Model, as_model, from_assembly
    from dem.core.settings import Settings
    from dem.core.simulate import SimResult, simulate
    from dem.experiments.assessment.run import assess_with_records
    from dem.experiments.friction_map.run import catalogue_map
    from dem.experiments.shake.domain import dem_failure_domain
    from dem.experiments.shake.file import load_shake, save_shake
    from dem.experiments.shake.run import ShakeProtocol, ShakeResult, shake
    from dem.experiments.shake.thresholds import (
        ThresholdResult,
        failure_domain,
        static_onset,
        threshold,
    )
    from dem.experiments.tilt.file import load_result, save_result
    from dem.experiments.tilt.run import TiltProtocol, TiltResult, tilt


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
