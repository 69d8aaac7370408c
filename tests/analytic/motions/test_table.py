"""The shake table as a speed-limited actuator (analytic/motions/table.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from analytic.motions.inputs import SampledMotion, SinePulse
from analytic.motions.table import LAB_TABLE_SPEED, servo_sine, servo_table
from specimens.constants import G
from foundation.errors import ArchdemInputError

DT = 1e-4


def sine(a_g: float, f: float) -> np.ndarray:
    t = DT * np.arange(int(round(1 / (f * DT))) + 1)
    return a_g * G * np.sin(2 * math.pi * f * t)


@pytest.mark.parametrize("tau", [None, 0.02])
def test_below_the_speed_limit_the_table_runs_the_sine(tau):
    a = sine(1.0, 4.0)  # peak speed 9.81 / (4 pi) = 0.78 m/s < 1 m/s
    h = servo_table(a, DT, LAB_TABLE_SPEED, tau)
    assert len(h.accel) == len(a)  # at rest when the command ends: nothing appended
    assert np.max(np.abs(h.accel - a)) < 1e-4 * G
    # the closed form of the velocity, A / (2 pi f) (1 - cos 2 pi f t), peaking at A / (pi f)
    assert np.max(h.velocity) == pytest.approx(G / (4 * math.pi), rel=1e-6)


@pytest.mark.parametrize("tau", [None, 0.01, 0.05])
def test_the_speed_never_exceeds_the_limit(tau):
    a = sine(3.0, 8.0)  # peak speed of the command 1.17 m/s
    h = servo_table(a, DT, LAB_TABLE_SPEED, tau)
    assert np.max(np.abs(h.velocity)) <= LAB_TABLE_SPEED + 1e-12
    assert np.max(np.abs(h.velocity)) == pytest.approx(LAB_TABLE_SPEED)


def test_a_velocity_command_holds_the_speed_with_no_acceleration_then_resumes_the_sine():
    f, a_g = 8.0, 3.0
    a = sine(a_g, f)
    h = servo_table(a, DT, LAB_TABLE_SPEED)
    w, A = 2 * math.pi * f, a_g * G
    t_sat = math.acos(1 - LAB_TABLE_SPEED * w / A) / w  # where the commanded speed reaches v_max
    t = DT * np.arange(len(h.accel))
    held = (t > t_sat + 2 * DT) & (t < 1 / f - t_sat - 2 * DT)
    assert held.sum() > 100 and np.all(np.abs(h.accel[held]) < 1e-9)
    before, after = t < t_sat - 2 * DT, (t > 1 / f - t_sat + 2 * DT) & (t < 1 / f - 2 * DT)
    assert np.max(np.abs(h.accel[before] - a[before])) < 1e-3 * A
    assert np.max(np.abs(h.accel[after] - a[after])) < 1e-3 * A
    # the jump at saturation: from A sin(w t_sat) to zero within two samples
    k = int(t_sat / DT)
    assert h.accel[k - 1] > 0.5 * A and abs(h.accel[k + 2]) < 1e-9
    assert abs(h.velocity[-1]) < 1e-9 and h.position[-1] < np.sum(np.cumsum(a) * DT) * DT  # the stroke lost


def test_a_position_loop_recovers_the_stroke_and_brakes_harder_than_the_sine():
    a = sine(3.0, 8.0)
    h = servo_table(a, DT, LAB_TABLE_SPEED, tau=0.02)
    v_c = np.concatenate([[0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * DT)])
    x_end = float(np.sum(0.5 * (v_c[1:] + v_c[:-1]) * DT))
    assert len(h.accel) > len(a)  # it settles after the command
    assert h.position[-1] == pytest.approx(x_end, abs=2e-6)
    assert np.min(h.accel) < -1.1 * 3.0 * G  # catching up: deceleration beyond the sine's amplitude


def test_the_acceleration_cap():
    a = sine(3.0, 8.0)
    cap = 3.5 * G
    h = servo_table(a, DT, LAB_TABLE_SPEED, tau=0.02, a_max=cap)
    assert np.max(np.abs(h.accel)) <= cap * (1 + 1e-9)
    assert np.max(np.abs(h.velocity)) <= LAB_TABLE_SPEED + 1e-12


def test_servo_sine_is_the_sine_within_reach_and_sampled_beyond():
    reach = math.pi * 8.0 * LAB_TABLE_SPEED  # [m/s^2], 2.56 g
    assert servo_sine(0.99 * reach, 8.0) == SinePulse(0.99 * reach, 8.0)
    m = servo_sine(1.2 * reach, 8.0)
    assert isinstance(m, SampledMotion)
    assert m.pga <= 1.2 * reach * (1 + 1e-6)
    v = np.concatenate([[0.0], np.cumsum(0.5 * (m.values[1:] + m.values[:-1]) * m.dt)])
    assert np.max(v) == pytest.approx(LAB_TABLE_SPEED, rel=1e-3)
    assert servo_sine(2.0 * reach, 8.0, a_max=10 * G).pga <= 10 * G * (1 + 1e-9)


@pytest.mark.parametrize("kw", [{"dt": 0.0}, {"v_max": -1.0}, {"tau": 0.0}, {"a_max": math.nan}])
def test_bad_input_is_refused(kw):
    args = {"accel": np.ones(10), "dt": 1e-3, "v_max": 1.0, **kw}
    with pytest.raises(ArchdemInputError):
        servo_table(**args)
    with pytest.raises(ArchdemInputError):
        servo_table(np.array([1.0, math.inf]), 1e-3, 1.0)
