"""The mode map's case function: the table's reach, the half cycle of a slip, and one real search."""
import math

import pytest

from analytic.motions.inputs import SinePulse
from dem.experiments.mode_map.case import mode_case, reach_g, servo_motion, slip_half
from dem.experiments.mode_map.run import ModeMapSpec
from specimens.constants import G


def test_the_reach_is_the_sine_whose_peak_speed_is_the_table_s():
    a = reach_g(8.0, 1.0)
    assert a == pytest.approx(2.562, abs=1e-3)  # pi f v / g
    assert a * G / (math.pi * 8.0) == pytest.approx(1.0)
    # within the reach the servo runs the sine itself; beyond it, not
    assert isinstance(servo_motion(0.9 * a * G, 8.0, v_max=1.0), SinePulse)
    assert not isinstance(servo_motion(1.2 * a * G, 8.0, v_max=1.0), SinePulse)
    assert isinstance(servo_motion(5 * a * G, 8.0), SinePulse)  # no speed limit: the ideal sine


def test_a_slip_falls_in_its_half_cycle():
    assert [slip_half(t, 10.0) for t in (None, 0.02, 0.05, 0.08, 0.12)] == ["", "first", "first", "second", "after"]


@pytest.mark.slow  # one threshold search: about 20 simulations
def test_one_cell_of_the_map_reads_as_the_study_did():
    """Sh06-Sd025 at 4 Hz (docs/validation.md#22): sliding after the first rebound at 0.741 g, within the
    table's reach, the crown joint R7 slipping first, in the first half cycle."""
    out = mode_case(ModeMapSpec(specimens=("Sh06-Sd025",)).case("Sh06-Sd025", 4.0))
    assert out["amplitude_g"] == pytest.approx(0.741, rel=0.03)
    assert (out["mode"], out["phase"], out["within_reach"]) == ("sliding", "after-first-rebound", True)
    assert (out["joint"], out["slip_half"]) == ("R7", "first")
    assert out["lambda"] < out["amplitude_g"] < out["scan_top_g"] and out["n_sims"] > 5
