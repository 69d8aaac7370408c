"""Gravity fields: tilt at constant magnitude with lambda = tan theta; ground motion as inertia."""
import math

import numpy as np
import pytest

from analytic.motions.inputs import SinePulse
from dem.core.loads import GroundShake, TiltHold, TiltRamp, TiltStairs, tilt_gravity
from specimens.constants import G


@pytest.mark.parametrize("lam", [0.0, 0.2, 0.577, 2.0])
def test_tilt_gravity(lam):
    g = tilt_gravity(lam)
    assert np.linalg.norm(g) == pytest.approx(G, rel=1e-14)  # rotated, not scaled
    assert g[0] / -g[1] == pytest.approx(lam, rel=1e-14, abs=1e-15)  # lambda = tan theta


def test_ramps_reach_their_levels():
    h = TiltHold(0.3, ramp_time=1.0)
    assert h.level(0.0) == 0.0 and h.level(0.5) == pytest.approx(0.15) and h.level(2.0) == 0.3
    assert TiltRamp(0.1).level(2.0) == pytest.approx(0.2)
    s = TiltStairs(step=0.01, hold=0.5, rise=0.2)
    assert s.level(0.7 * 3 - 1e-9) == pytest.approx(0.03)  # after three full periods


def test_ground_motion_is_inertial_field():
    m = SinePulse(2.0, 4.0)
    load = GroundShake(m)
    t = 0.05
    assert np.allclose(load.gravity(t), [-float(m.acceleration(t)), -G, 0.0])
    assert load.duration == pytest.approx(0.25)
    assert math.isclose(load.gravity(1.0)[0], 0.0, abs_tol=0.0)
