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


# ------------------------------------------------------- thresholds of the joint states and the mode
# The window increment ``w`` passed to classify is chosen so that the imposed opening or slip is
# 0.9 x or 1.1 x the settings' fraction of it; the defaults, and unequal fractions so that a rule
# reading the other fraction is caught.
@pytest.fixture(params=[Settings(), Settings(hinge_fraction=0.03, slide_fraction=0.08)], ids=["default", "unequal"])
def S(request):
    return request.param


def _rest(m):
    c0 = np.array([b.centroid for b in m.bodies])
    return c0, np.repeat(np.eye(3)[None], m.n_bodies, 0)


def _rocked(m, angle, slip=0.0, pivot=(B / 2, 0.0)):
    """The single block slid by ``slip`` along x, then rotated by ``angle`` about its slid base corner."""
    R = _rot_about(pivot, angle)
    p = np.array([pivot[0] + slip, pivot[1], 0.0])
    return (p + R @ (m.bodies[0].centroid + np.array([slip, 0.0, 0.0]) - p))[None], R[None]


@pytest.mark.parametrize("f, state, mode", [(0.9, "closed", "none"), (1.1, "hinge", "rocking")])
def test_hinge_needs_an_opening_above_hinge_fraction_of_the_window(f, state, mode, S):
    m = single_block(B, H)
    pos1, R1 = _rocked(m, -0.02)
    opening = B * math.sin(0.02)
    states, md = classify(m, S, *_rest(m), pos1, R1, opening / (f * S.hinge_fraction))
    assert (states[0].state, md) == (state, mode)
    assert states[0].opening == pytest.approx(opening, rel=1e-9)


@pytest.mark.parametrize("f, state, mode", [(0.9, "closed", "none"), (1.1, "slide", "sliding")])
def test_slide_needs_a_slip_above_slide_fraction_of_the_window(f, state, mode, S):
    m = single_block(B, H)
    pos0, R0 = _rest(m)
    states, md = classify(m, S, pos0, R0, pos0 + [0.003, 0.0, 0.0], R0, 0.003 / (f * S.slide_fraction))
    assert (states[0].state, md) == (state, mode)


@pytest.mark.parametrize("f, state", [(0.9, "closed"), (1.1, "open")])
def test_lift_off_parts_the_joint_above_the_hinge_fraction(f, state, S):
    # both ends open by the lift; the slip of a parted joint is not a slide
    from dem.experiments.friction_map.run import SLIDING_MODES

    m = single_block(B, H)
    pos0, R0 = _rest(m)
    lift = 0.002
    states, _ = classify(m, S, pos0, R0, pos0 + [0.0, lift, 0.0], R0, lift / (f * S.hinge_fraction))
    assert states[0].state == state and states[0].face == ""
    states, md = classify(m, S, pos0, R0, pos0 + [10 * lift, lift, 0.0], R0, lift / (f * S.hinge_fraction))
    assert states[0].state == ("slide" if f < 1 else "open")
    assert (md in SLIDING_MODES) is (f < 1)


@pytest.mark.parametrize("f_open, f_slip, state", [(1.1, 1.1, "hinge+slide"), (0.9, 1.1, "slide"),
                                                     (1.1, 0.9, "hinge"), (0.9, 0.9, "closed")])
def test_a_joint_that_rotates_and_slips_is_hinge_plus_slide(f_open, f_slip, state, S):
    m = single_block(B, H)
    w = 0.002
    angle = -math.asin(f_open * S.hinge_fraction * w / B)  # opens the intrados end by f_open x the fraction
    pos1, R1 = _rocked(m, angle, slip=f_slip * S.slide_fraction * w)
    states, _ = classify(m, S, *_rest(m), pos1, R1, w)
    assert states[0].state == state and states[0].face == ("extrados" if f_open > 1 else "")
    # slip read at the pivot end: the imposed slip, not the pivot's plus the lifted corner's B (1 - cos)
    assert abs(states[0].slip) == pytest.approx(f_slip * S.slide_fraction * w, rel=1e-9)


@pytest.mark.parametrize("angle, face", [(-0.02, "extrados"), (0.02, "intrados")])
def test_hinge_face_is_the_pivot_end_and_slip_is_read_there(angle, face, S):
    m = single_block(B, H)
    pivot = (B / 2, 0.0) if face == "extrados" else (-B / 2, 0.0)
    pos1, R1 = _rocked(m, angle, slip=0.001, pivot=pivot)
    states, _ = classify(m, S, *_rest(m), pos1, R1, 0.001)
    assert (states[0].state, states[0].face) == ("hinge+slide", face)
    assert abs(states[0].slip) == pytest.approx(0.001, rel=1e-9)
    assert states[0].rotation == pytest.approx(angle, rel=1e-9)


@pytest.mark.parametrize("ratio, mode", [(0.9, "mixed"), (1.1, "sliding")])
def test_sliding_needs_slip_at_least_the_opening(ratio, mode, S):
    # sliding: summed slip >= half of summed slip + opening, i.e. slip >= opening; else mixed
    m = single_block(B, H)
    opening = B * math.sin(0.02)
    pos1, R1 = _rocked(m, -0.02, slip=ratio * opening)
    states, md = classify(m, S, *_rest(m), pos1, R1, opening)
    assert states[0].state == "hinge+slide" and md == mode


def _stack(b=B, h=H):
    """Two blocks b x h stacked on the base: joint B0 (base - block 0), J1 (block 0 - block 1)."""
    from dem.core.model import BaseSpec, BodySpec, JointSpec, Model

    def block(k):
        poly = np.array([[-b / 2, k * h], [b / 2, k * h], [b / 2, (k + 1) * h], [-b / 2, (k + 1) * h]])
        return BodySpec(f"K{k}", (poly,), 0.1, 1.0, np.array([0.0, (k + 0.5) * h, 0.0]), np.eye(3), poly)

    def joint(name, a, y):
        return JointSpec(name, a, a + 1, np.array([-b / 2, y]), np.array([b / 2, y]), np.array([0.0, 1.0]))

    return Model("stack", (block(0), block(1)), (joint("B0", -1, 0.0), joint("J1", 0, h)),
                 BaseSpec((np.array([[-1.0, -0.1], [1.0, -0.1], [1.0, 0.0], [-1.0, 0.0]]),), 0.4), 2 * h, 1)


def _stack_pose(m, angle, slip):
    """Both blocks rotated by ``angle`` about the base's right corner; block 1 then slid by ``slip``
    along the rotated joint J1."""
    R = _rot_about((B / 2, 0.0), angle)
    p = np.array([B / 2, 0.0, 0.0])
    c = np.array([b.centroid for b in m.bodies])
    pos = p + (c - p) @ R.T
    pos[1] += slip * (R @ [1.0, 0.0, 0.0])
    return pos, np.array([R, R])


@pytest.mark.parametrize("f, j1, mode", [(0.9, "closed", "rocking"), (1.1, "slide", "mixed")])
def test_hinges_with_a_little_slip_are_mixed_which_the_friction_map_counts_as_sliding(f, j1, mode, S):
    # a hinge at the base and a slip at J1 just below / above slide_fraction of the window: the
    # rocking/sliding boundary of the friction map's mu* (mixed counts as sliding there)
    from dem.experiments.friction_map.run import ROCKING_MODES, SLIDING_MODES

    m = _stack()
    w = B * math.sin(0.02)  # the window: the base hinge's opening
    pos1, R1 = _stack_pose(m, -0.02, f * S.slide_fraction * w)
    states, md = classify(m, S, *_rest(m), pos1, R1, w)
    assert [(s.joint, s.state) for s in states] == [("B0", "hinge"), ("J1", j1)]
    assert md == mode and md in (SLIDING_MODES if f > 1 else ROCKING_MODES)


@pytest.mark.parametrize("ratio, mode", [(0.9, "mixed"), (1.1, "sliding")])
def test_assembly_slides_when_its_summed_slip_reaches_its_summed_opening(ratio, mode, S):
    m = _stack()
    opening = B * math.sin(0.02)
    pos1, R1 = _stack_pose(m, -0.02, ratio * opening)
    states, md = classify(m, S, *_rest(m), pos1, R1, opening)
    assert [s.state for s in states] == ["hinge", "slide"] and md == mode
    assert abs(states[1].slip) == pytest.approx(ratio * opening, rel=1e-9) and abs(states[1].opening) < 1e-12
