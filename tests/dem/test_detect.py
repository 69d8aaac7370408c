"""Joint states from poses (spec §4.4) on imposed rigid motions of a single block: exact kinematics."""
import math

import numpy as np
import pytest

from dem.detect import PointTracker, classify, joint_kinematics
from dem.model import single_block
from dem.settings import Settings

B, H = 0.1, 0.2


def _rot_about(point, angle):
    c, s = math.cos(angle), math.sin(angle)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return R


def _pose_rotated(m, pivot, angle):
    b = m.bodies[0]
    R = _rot_about(pivot, angle)
    p = np.array([pivot[0], pivot[1], 0.0])
    pos = p + R @ (b.centroid - p)
    return pos[None], R[None]


def test_rocking_about_right_corner_is_a_hinge_at_extrados():
    m = single_block(B, H)
    pos0, R0 = m.bodies[0].centroid[None], np.eye(3)[None]
    pos1, R1 = _pose_rotated(m, (B / 2, 0.0), -0.02)  # tips over to +x about the right corner
    k = joint_kinematics(m, pos1, R1)
    # closed form: the left corner lifts by b sin(theta), the pivot stays
    assert k["open_i"][0] == pytest.approx(B * math.sin(0.02), rel=1e-9)
    assert k["open_e"][0] == pytest.approx(0.0, abs=1e-15)
    window = PointTracker(m).max_displacement(pos1, R1)[0]
    states, mode = classify(m, Settings(), pos0, R0, pos1, R1, window)
    assert (states[0].state, states[0].face, mode) == ("hinge", "extrados", "rocking")


def test_translation_along_base_is_a_slide():
    m = single_block(B, H)
    pos0, R0 = m.bodies[0].centroid[None], np.eye(3)[None]
    pos1 = pos0 + np.array([0.003, 0.0, 0.0])
    k = joint_kinematics(m, pos1, R0)
    assert abs(k["slip_i"][0]) == pytest.approx(0.003, rel=1e-12) and abs(k["open_i"][0]) < 1e-15
    states, mode = classify(m, Settings(), pos0, R0, pos1, R0, 0.003)
    assert (states[0].state, mode) == ("slide", "sliding")


def test_lift_off_is_open():
    m = single_block(B, H)
    pos0, R0 = m.bodies[0].centroid[None], np.eye(3)[None]
    pos1 = pos0 + np.array([0.0, 0.002, 0.0])
    states, _ = classify(m, Settings(), pos0, R0, pos1, R0, 0.002)
    assert states[0].state == "open"
