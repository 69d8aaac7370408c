"""The simulator: virtual tilt and shake-table tests of rigid-block arches (PyBullet, or MuJoCo),
collapse and per-joint failure modes, thresholds, friction maps, studies and the campaign.

    >>> from dem import ground_motion, shake, tilt
    >>> t = tilt("Sh06-Sd015")                 # a catalogue id, Specimen, PointedArch, Assembly or Model
    >>> s = shake("Sh02-Sd020", ground_motion(sine=4.0, amplitude=0.5))   # Hz and g, as the CLI
"""
from analytic.records import ground_motion
from dem.core.model import Model, as_model, from_assembly
from dem.core.settings import Settings
from dem.core.simulate import SimResult, simulate
from dem.experiments.domain import dem_failure_domain
from dem.experiments.friction_map import catalogue_map
from dem.experiments.shake import ShakeProtocol, ShakeResult, shake
from dem.experiments.thresholds import (
    ThresholdResult,
    failure_domain,
    static_onset,
    threshold,
)
from dem.experiments.tilt import TiltProtocol, TiltResult, tilt
from dem.formats.shake import load_shake, save_shake
from dem.formats.tilt import load_result, save_result

__all__ = [
    "ground_motion", "Model", "as_model", "from_assembly", "Settings", "SimResult", "simulate", "dem_failure_domain",
    "catalogue_map", "ShakeProtocol", "ShakeResult", "shake", "ThresholdResult", "failure_domain", "static_onset",
    "threshold", "TiltProtocol", "TiltResult", "tilt", "load_shake", "save_shake", "load_result", "save_result",
]
