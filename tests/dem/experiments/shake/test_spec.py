"""The options of ``archdem shake`` and ``archdem threshold`` as specs: a script that builds one meets
the command's refusals, and gets the motion, protocol and run specs the command runs."""
import math

import pytest

from analytic.motions.inputs import SinePulse
from dem.core.settings import dynamics_settings
from dem.experiments.shake.run import ShakeProtocol
from dem.experiments.shake.spec import ShakeOptions, ThresholdOptions
from foundation.errors import ArchdemInputError
from specimens.constants import G


@pytest.mark.parametrize("kw, msg", [
    ({}, "give exactly one input"),
    ({"sine": 4}, "--sine needs --amplitude A_G"),
    ({"sine": 1e9, "amplitude": 0.3}, "--sine must be a frequency in [0.01, 100] Hz, got 1e+09"),
    ({"sine": math.nan, "amplitude": 0.3}, "--sine must be a frequency in [0.01, 100] Hz, got nan"),
    ({"sine": 4, "amplitude": 1e-9}, "--amplitude 1e-09 g is below 1e-06 g"),
    ({"sine": 4, "amplitude": 0.3, "table_speed": 0.0}, "--table-speed must be a speed in (0, 100] m/s, got 0"),
    ({"sine": 4, "amplitude": 0.3, "tail": 1e9}, "zero tail must be between 0 and 600 s"),
    ({"sine": 4, "amplitude": 0.3, "duration": -1}, "--duration must be between 0 and 600 s"),
    ({"sine": 4, "amplitude": 0.3, "load": "other"}, "shake load must be one of inertial, driven-base"),
])
def test_shake_options_refuse_as_the_command_does(kw, msg):
    with pytest.raises(ArchdemInputError) as e:
        ShakeOptions(**kw)
    assert msg in str(e.value) and "\n" not in str(e.value)


def test_shake_options_build_the_motion_protocol_and_names():
    o = ShakeOptions(sine=4.0, amplitude=0.3)
    assert isinstance(o.motion, SinePulse) and o.motion.a == pytest.approx(0.3 * G) and o.motion.f == 4.0
    assert o.protocol == ShakeProtocol()
    assert o.stem("A", "glued") == "shake-A-glued-sine4Hz-0.3g"
    full = ShakeOptions(sine=4.0, amplitude=0.3, full=True, tail=0.5, load="driven-base")
    assert full.protocol == ShakeProtocol(tail=0.5, stop_on_collapse=False, load="driven-base", rest_after=None)
    # a table slower than the sine's peak speed (0.3 g at 4 Hz: 0.23 m/s) runs the servo's motion
    slow = ShakeOptions(sine=4.0, amplitude=0.3, table_speed=0.05).motion
    assert not isinstance(slow, SinePulse) and "v_max 0.05 m/s" in slow.source


def test_only_a_long_run_announces_itself():
    st = dynamics_settings()
    assert ShakeOptions(sine=4.0, amplitude=0.3).announcement(st) == ""
    long = ShakeOptions(sine=0.1, amplitude=0.3, full=True)  # 10 s of sine and 1 s of tail
    steps = math.ceil(11 / st.dt)
    assert long.announcement(st) == f"simulating up to 11 s of motion and tail ({steps} steps of {st.dt:g} s)"
    assert ShakeOptions(sine=0.1, amplitude=0.3).announcement(st).endswith("; stops at collapse, or once at rest "
                                                                          "after the motion")


@pytest.mark.parametrize("kw, msg", [
    ({}, "a threshold search needs --sine FREQ"),
    ({"sine": 0.0}, "--sine must be a frequency in [0.01, 100] Hz, got 0"),
    ({"sine": 4, "scan_ratio": 11}, "--scan-ratio must be in (1, 10], got 11"),
    ({"sine": 4, "tol": 0.6}, "--tol must be a relative tolerance in [0.001, 0.5], got 0.6"),
    ({"sine": 4, "a_min": 1e-9}, "--a-min 1e-09 g is below 1e-06 g"),
    ({"sine": 4, "a_max": 200}, "--a-max must be in (0, 100] g, got 200"),
    ({"sine": 4, "table_speed": -1}, "--table-speed must be a speed in (0, 100] m/s, got -1"),
    ({"sine": 4, "tail": -1}, "zero tail must be between 0 and 600 s"),
])
def test_threshold_options_refuse_as_the_command_does(kw, msg):
    with pytest.raises(ArchdemInputError) as e:
        ThresholdOptions(**kw)
    assert msg in str(e.value)


def test_threshold_options_make_the_search_spec():
    spec = ThresholdOptions(sine=5.0, a_min=0.2, a_max=0.9, scan_ratio=1.4, tol=0.05, tail=0.5, check=False,
                            table_speed=1.0).run_spec("M", dynamics_settings())
    assert (spec.target, spec.freq, spec.a_min_g, spec.a_max_g, spec.scan_ratio, spec.tol, spec.check) == (
        "M", 5.0, 0.2, 0.9, 1.4, 0.05, False)
    assert spec.protocol == ShakeProtocol(tail=0.5)
    assert spec.motion_fn.keywords == {"v_max": 1.0}  # the servo's sine
    assert ThresholdOptions(sine=5.0).run_spec("M", dynamics_settings()).check is True  # checked by default
