"""Joint states from poses (docs/physics/dem.md#6-failure-mode) on imposed rigid motions of a single block: exact kinematics."""
import math

import numpy as np
import pytest

from dem.core.detect import PointTracker, classify, joint_kinematics
from dem.core.model import single_block
from dem.core.settings import Settings

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


def test_tracker_vectorised_displacements_match_per_body_ones():
    # the vectorised form used at every record equals the definition, body by body: each tracked
    # point carried by its body's rigid motion, pos_i + R_i (p - c_i) - p (random rigid poses
    # of the 15 bodies of a glued arch), and the largest one of a rotation about a corner is the
    # far corner's chord, 2 r sin(angle / 2) (closed form)
    from scipy.spatial.transform import Rotation

    from dem.core.model import from_assembly
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    m = from_assembly(discretise(get_specimen("Sh06-Sd015").arch, config="glued"))
    t = PointTracker(m)
    rng = np.random.default_rng(0)
    pos = t.c0 + 1e-3 * rng.standard_normal(t.c0.shape)
    R = Rotation.from_rotvec(0.01 * rng.standard_normal((m.n_bodies, 3))).as_matrix()
    per_body = [pos[i] + (p - t.c0[i]) @ R[i].T - p for i, p in enumerate(t.pts)]
    # 1e-15 m: only the summation order of the 3-term products differs (einsum against matmul),
    # a few ulp of the ~0.1 m point coordinates
    assert np.allclose(t.all_displacements(pos, R), np.concatenate(per_body), rtol=0, atol=1e-15)
    d = np.array([np.linalg.norm(u, axis=1).max() for u in per_body])
    dmax, i = t.max_displacement(pos, R)
    assert i == int(np.argmax(d)) and dmax == pytest.approx(d.max(), rel=1e-14)
    # time axis: (nt, n, 3) poses give (nt, m, 3)
    both = t.all_displacements(np.stack([pos, t.c0]), np.stack([R, np.repeat(np.eye(3)[None], m.n_bodies, 0)]))
    assert np.allclose(both[0], np.concatenate(per_body), atol=1e-15) and np.abs(both[1]).max() < 1e-15
    blk = single_block(B, H)
    pos1, R1 = _pose_rotated(blk, (B / 2, 0.0), -0.02)
    far = math.hypot(B, H)  # the upper left corner is the farthest from the pivot (right corner)
    assert PointTracker(blk).max_displacement(pos1, R1)[0] == pytest.approx(2 * far * math.sin(0.01), rel=1e-12)
