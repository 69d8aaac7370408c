"""The collapse rule of ``simulate``, the mode window of ``read_mode`` and ``onset_time`` on imposed
rigid motions (docs/physics/dem.md#5-collapse-criterion, #6-failure-mode): a scripted engine
reports chosen poses and velocities at every record, histories are built from arrays. Every
threshold is probed at 0.9 x and 1.1 x its value in the settings."""
import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from dem.core.engines.base import Engine
from dem.core.loads import Rest
from dem.core.model import side_by_side, single_block
from dem.core.settings import Settings
from dem.core.simulate import History, SimResult, onset_time, read_mode, simulate

B, H, W = 0.1, 0.2, 0.1  # single_block's size is its height H
S = Settings()
D_C = S.collapse_fraction * H  # collapse displacement
V_C = S.collapse_speed
LO, HI = (f * H for f in S.mode_window)


class ScriptedEngine(Engine):
    """Reports ``frames[k] = (pos, R, v, w)`` (arrays over the bodies) at record ``k``: the poses
    and velocities an engine would give, chosen by the test."""

    name = "scripted"

    def __init__(self, frames, record_steps: int) -> None:
        self.frames, self.rec, self.steps, self.closed = frames, record_steps, 0, False

    def build(self, model, settings, driven_base: bool = False) -> None:
        assert len(self.frames[0][0]) == model.n_bodies

    def set_gravity(self, vec) -> None:
        pass

    def step(self, n: int = 1) -> None:
        self.steps += n

    def _frame(self):
        assert self.steps % self.rec == 0, "poses read between records"
        return self.frames[self.steps // self.rec]

    def poses(self):
        pos, R, _, _ = self._frame()
        return np.array(pos, float), np.array(R, float)

    def velocities(self):
        _, _, v, w = self._frame()
        return np.array(v, float), np.array(w, float)

    def close(self) -> None:
        self.closed = True


def _run(model, frames, stop_on_collapse=True, settings=S) -> SimResult:
    eng = ScriptedEngine(frames, settings.record_steps)
    sim = simulate(model, settings, Rest(), (len(frames) - 1) * settings.record_every, engine=eng,
                   stop_on_collapse=stop_on_collapse)
    assert eng.closed
    return sim


def _slid(model, d: float, speed: float, body: int = 0):
    """All bodies at rest in place but ``body``, translated by ``d`` along x at ``speed``."""
    c0 = np.array([b.centroid for b in model.bodies])
    pos, v = c0.copy(), np.zeros_like(c0)
    pos[body, 0] += d
    v[body, 0] = speed
    return pos, np.repeat(np.eye(3)[None], model.n_bodies, 0), v, np.zeros_like(c0)


def _rz(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _rocked(model, angle: float, slip: float = 0.0, pivot=(B / 2, 0.0), w: float = 0.0):
    """The single block translated by ``slip`` along x, then rotated by ``angle`` about its
    (translated) base corner ``pivot``; angular speed ``w`` about z."""
    R = _rz(angle)
    p = np.array([pivot[0] + slip, pivot[1], 0.0])
    c = model.bodies[0].centroid + np.array([slip, 0.0, 0.0])
    return (p + R @ (c - p))[None], R[None], np.zeros((1, 3)), np.array([[0.0, 0.0, w]])


@pytest.fixture(scope="module")
def block():
    return single_block(B, H, width=W)


# ------------------------------------------------------------------------------ collapse rule
@pytest.mark.parametrize("dist, speed, collapsed", [(1.1, 1.1, True), (1.1, 0.9, False), (0.9, 1.1, False),
                                                     (0.9, 100.0, False)])
def test_collapse_needs_the_distance_and_the_speed(block, dist, speed, collapsed):
    # the block slides (all points move by the same distance) and then keeps the pose for two records
    frame = _slid(block, dist * D_C, speed * V_C)
    sim = _run(block, [_slid(block, 0.0, 0.0), frame, frame, frame])
    assert sim.collapsed is collapsed
    assert sim.history.dmax[1] == pytest.approx(dist * D_C, rel=1e-9)
    if collapsed:  # at the first record, and the run stopped there
        assert sim.t_collapse == 1 * S.record_steps * S.dt == sim.history.t[-1]
        assert len(sim.history.t) == 2 and sim.steps == S.record_steps
    else:
        assert math.isnan(sim.t_collapse) and len(sim.history.t) == 4


def test_collapse_is_declared_at_the_first_record_where_both_conditions_hold(block):
    # far but slow, then fast but near, then both: collapse at record 3, not before
    frames = [_slid(block, 0.0, 0.0), _slid(block, 1.1 * D_C, 0.9 * V_C), _slid(block, 0.9 * D_C, 1.1 * V_C),
              _slid(block, 1.1 * D_C, 1.1 * V_C), _slid(block, 2.0 * D_C, 2.0 * V_C), _slid(block, 3.0 * D_C, 0.0)]
    sim = _run(block, frames)
    assert sim.collapsed and sim.t_collapse == 3 * S.record_steps * S.dt
    assert np.array_equal(sim.history.t, np.arange(4) * S.record_steps * S.dt)
    # without stopping, the run goes on to its end and keeps the first collapse time
    full = _run(block, frames, stop_on_collapse=False)
    assert full.collapsed and full.t_collapse == sim.t_collapse and len(full.history.t) == len(frames)
    assert full.steps == (len(frames) - 1) * S.record_steps


@pytest.mark.parametrize("f_dist, f_speed, collapsed", [(0.9, 0.9, True), (1.1, 0.9, False), (0.9, 1.1, False)])
def test_collapse_thresholds_are_read_from_the_settings(block, f_dist, f_speed, collapsed):
    # one imposed motion (the default collapse distance at the default speed), settings' thresholds
    # moved below or above it (the mode window kept under the collapse fraction)
    frames = [_slid(block, 0.0, 0.0), _slid(block, D_C, V_C)]
    st = S.with_(collapse_fraction=f_dist * S.collapse_fraction, collapse_speed=f_speed * V_C, mode_window=(0.01, 0.05))
    assert _run(block, frames, settings=st).collapsed is collapsed


@pytest.mark.parametrize("dist, spin, collapsed", [(1.1, 1.1, True), (1.1, 0.9, False), (0.9, 1.1, False)])
def test_collapse_watches_the_farthest_point_and_the_spin_of_the_body(block, dist, spin, collapsed):
    # rocking about the right base corner: the far (upper left) corner moves the chord 2 r sin(angle / 2),
    # the centroid only half of it; the spin alone is imposed (v = 0): the body's speed bound is
    # |w| r_max, r_max from the centroid to a corner of the 3-D box
    r = math.hypot(B, H)
    angle = -2 * math.asin(dist * D_C / (2 * r))
    r_max = math.sqrt((B / 2) ** 2 + (H / 2) ** 2 + (W / 2) ** 2)
    frame = _rocked(block, angle, w=-spin * V_C / r_max)
    sim = _run(block, [_rocked(block, 0.0), frame, frame])
    assert np.linalg.norm(frame[0][0] - block.bodies[0].centroid) < 0.6 * D_C
    assert sim.history.dmax[1] == pytest.approx(dist * D_C, rel=1e-9)
    assert sim.collapsed is collapsed


@pytest.mark.parametrize("moving_body_speed, collapsed", [(0.9, False), (1.1, True)])
def test_collapse_speed_is_that_of_the_body_that_moved_farthest(moving_body_speed, collapsed):
    # two independent blocks: block 0 moved past the collapse distance, block 1 moved less but
    # fast; only block 0's speed counts
    two = side_by_side(single_block(B, H, width=W), 2)
    pos, R, v, w = _slid(two, 1.1 * D_C, moving_body_speed * V_C, body=0)
    pos[1, 0] += 0.5 * D_C
    v[1, 0] = 100 * V_C
    sim = _run(two, [_slid(two, 0.0, 0.0), (pos, R, v, w), (pos, R, v, w)])
    assert sim.collapsed is collapsed


def test_simulate_reads_the_mode_of_the_recorded_motion(block):
    # a block tipping about its right corner at a steady rate: rocking, hinge at the extrados
    # (the pivot), collapse once the far corner passed the collapse distance
    angles = np.linspace(0.0, -0.1, 11)
    frames = [_rocked(block, a, w=-0.5) for a in angles]
    sim = _run(block, frames)
    assert sim.collapsed and sim.mode == "rocking"
    assert (sim.joints[0].joint, sim.joints[0].state, sim.joints[0].face) == ("B0", "hinge", "extrados")
    k = len(sim.history.t) - 1
    assert sim.history.dmax[k] > D_C >= sim.history.dmax[k - 1]
    # the recorded orientation is the imposed one
    assert np.allclose(sim.history.rotations()[:, 0], [f[1][0] for f in frames[: k + 1]], atol=1e-12)


# ------------------------------------------------------------------------------- mode window
def _history(model, frames, dmax) -> History:
    """A history of the poses of ``frames`` (one record every 10 ms) with the largest displacements
    ``dmax``, set directly: ``read_mode`` finds the window from ``dmax`` alone."""
    n = len(frames)
    pos = np.array([f[0] for f in frames])
    quat = Rotation.from_matrix(np.array([f[1] for f in frames]).reshape(-1, 3, 3)).as_quat().reshape(n, -1, 4)
    z = np.zeros(n)
    return History(0.01 * np.arange(n), pos, quat, np.tile([0.0, -S.g, 0.0], (n, 1)), np.asarray(dmax, float), z, z)


TH1, TH3 = -0.01, -0.06  # rotation before and at the end of the window [rad]
SLIP = 3e-3  # [m] slip between the record before the window and its start


@pytest.mark.parametrize("f_lo, f_hi", [(1.0, 1.0), (1.1, 1.1)])  # reaching an end: equal counts
def test_mode_is_read_between_the_records_that_first_reach_the_window_ends(block, f_lo, f_hi):
    # record 1: rocked, below the window; record 2: slipped, window starts (dmax reaches lo);
    # record 3: rocked further, window ends (dmax reaches hi); record 4: a large slip after it.
    # Between records 2 and 3 the motion is a pure rotation about the corner: rocking. Starting one
    # record early adds the slip (mixed), ending one late adds the last slip (sliding)
    frames = [_rocked(block, 0.0), _rocked(block, TH1), _rocked(block, TH1, SLIP), _rocked(block, TH3, SLIP),
              _rocked(block, TH3, 10 * SLIP)]
    dmax = [0.0, 0.9 * LO, f_lo * LO, f_hi * HI, 3 * HI]
    states, mode = read_mode(block, S, _history(block, frames, dmax))
    assert mode == "rocking"
    st = states[0]
    assert (st.state, st.face) == ("hinge", "extrados")
    assert st.opening == pytest.approx(B * (math.sin(-TH3) - math.sin(-TH1)), rel=1e-9)
    assert abs(st.slip) < 1e-12 and st.rotation == pytest.approx(TH3 - TH1, rel=1e-9)
    # the same records with the window one record earlier or later read the slips
    early = _history(block, frames, [0.0, f_lo * LO, f_lo * LO, f_hi * HI, 3 * HI])
    late = _history(block, frames, [0.0, 0.9 * LO, f_lo * LO, 0.9 * HI, 3 * HI])
    assert read_mode(block, S, early)[1] == "mixed"
    assert read_mode(block, S, late)[1] == "sliding"


def test_window_without_upper_end_runs_to_the_last_record(block):
    # the largest displacement reaches lo (record 2) but never hi: the window ends at the last
    # record and leaves out the slip before it
    th4 = -0.08
    frames = [_rocked(block, 0.0), _rocked(block, 0.0, SLIP), _rocked(block, TH1, SLIP), _rocked(block, TH3, SLIP),
              _rocked(block, th4, SLIP)]
    states, mode = read_mode(block, S, _history(block, frames, [0.0, 0.9 * LO, 1.1 * LO, 0.9 * HI, 0.95 * HI]))
    assert mode == "rocking" and states[0].state == "hinge"
    assert states[0].rotation == pytest.approx(th4 - TH1, rel=1e-9) and abs(states[0].slip) < 1e-12


def test_motion_below_the_window_reads_mode_none_with_the_creep_of_the_whole_history(block):
    frames = [_rocked(block, 0.0), _rocked(block, 0.0, SLIP / 3), _rocked(block, 0.0, SLIP)]
    states, mode = read_mode(block, S, _history(block, frames, [0.0, 0.3 * LO, 0.9 * LO]))
    assert mode == "none"
    assert states[0].state == "slide" and abs(states[0].slip) == pytest.approx(SLIP, rel=1e-9)


def test_window_crossed_in_one_record_reads_the_whole_history(block):
    # lo and hi first reached at the same record: the states are read from record 0 to the last one
    frames = [_rocked(block, 0.0), _rocked(block, 0.0, SLIP), _rocked(block, TH3, SLIP)]
    states, mode = read_mode(block, S, _history(block, frames, [0.0, 0.9 * LO, 1.1 * HI]))
    assert states[0].state == "hinge+slide" and abs(states[0].slip) == pytest.approx(SLIP, rel=1e-9)
    assert states[0].rotation == pytest.approx(TH3, rel=1e-9) and mode == "mixed"


# -------------------------------------------------------------------------------- onset time
@pytest.mark.parametrize("factors, k_onset", [
    ([0.0, 0.5, 1.1, 0.9, 1.0, 1.1, 2.0, 3.0], 4),  # last excursion starts where dmax reaches lo
    ([0.0, 0.5, 1.1, 0.9, 1.1, 2.0, 3.0], 4),
    ([0.0, 0.2, 0.5, 0.9, 0.99], 4),  # never above: the last record
    ([1.1, 2.0, 3.0], 0),  # never below: the first record
])
def test_onset_is_the_first_record_of_the_last_excursion_above_the_window_start(block, factors, k_onset):
    n = len(factors)
    frames = [_rocked(block, 0.0)] * n
    h = _history(block, frames, np.array(factors) * LO)
    sim = SimResult({}, 1.0, h, True, float(h.t[-1]), [], "rocking", {}, 0.0, 0)
    assert onset_time(block, S, sim) == h.t[k_onset]


# --------------------------------------------------------------------- confirmed collapse (shakes)
SC = S.with_(collapse_confirm=2 * S.collapse_fraction)  # confirmed at twice the collapse distance


def _still(model):
    return _slid(model, 0.0, 0.0)


def _record_t(k: int) -> float:
    return k * S.record_steps * S.dt


def test_without_confirmation_the_criterion_firing_is_the_collapse(block):
    # the tilt's rule (collapse_confirm None): collapse, exceedance and confirmation at the first firing
    assert S.collapse_confirm is None
    sim = _run(block, [_still(block), _slid(block, 1.1 * D_C, 1.1 * V_C), _slid(block, 0.5 * D_C, 0.0)])
    assert sim.collapsed and sim.t_collapse == sim.t_exceed == sim.t_confirm == _record_t(1)


def test_an_excursion_the_model_comes_back_from_is_no_collapse(block):
    # past the criterion (and fast) at records 1-2, back below it from record 3: survived, the firing kept
    frames = [_still(block), _slid(block, 1.1 * D_C, 1.1 * V_C), _slid(block, 1.9 * D_C, 1.1 * V_C),
              _slid(block, 0.5 * D_C, 1.1 * V_C), _slid(block, 0.5 * D_C, 0.0)]
    sim = _run(block, frames, settings=SC)
    assert not sim.collapsed and math.isnan(sim.t_collapse) and math.isnan(sim.t_confirm)
    assert sim.t_exceed == _record_t(1) and len(sim.history.t) == len(frames)  # simulated to its end


@pytest.mark.parametrize("f_confirm, collapsed", [(1.1, True), (0.9, False)])
def test_a_collapse_is_confirmed_at_the_confirm_distance(block, f_confirm, collapsed):
    # the criterion fires at record 1; record 2 is at f_confirm x the confirmation distance; then back
    d_ok = SC.collapse_confirm * H
    frames = [_still(block), _slid(block, 1.1 * D_C, 1.1 * V_C), _slid(block, f_confirm * d_ok, 0.0),
              _slid(block, 0.5 * D_C, 0.0), _slid(block, 0.5 * D_C, 0.0)]
    sim = _run(block, frames, settings=SC)
    assert sim.collapsed is collapsed and sim.t_exceed == _record_t(1)
    if collapsed:  # no speed asked there; stopped at the confirmation; the collapse dated at the firing
        assert (sim.t_collapse, sim.t_confirm) == (_record_t(1), _record_t(2)) and len(sim.history.t) == 3


def test_the_collapse_is_dated_at_the_excursion_that_did_not_come_back(block):
    # a first excursion (records 1-2) comes back (record 3); the second (from record 4) is confirmed at record 5
    d_ok = SC.collapse_confirm * H
    frames = [_still(block), _slid(block, 1.1 * D_C, V_C * 2), _slid(block, 1.5 * D_C, V_C * 2),
              _slid(block, 0.5 * D_C, V_C * 2), _slid(block, 1.1 * D_C, V_C * 2), _slid(block, 1.1 * d_ok, V_C * 2)]
    sim = _run(block, frames, settings=SC)
    assert sim.collapsed and sim.t_exceed == _record_t(1)
    assert (sim.t_collapse, sim.t_confirm) == (_record_t(4), _record_t(5))
    # a slow record past the distance does not start an excursion: the criterion needs the speed
    frames[4] = _slid(block, 1.1 * D_C, 0.9 * V_C)
    assert _run(block, frames, settings=SC).t_collapse == _record_t(5)


@pytest.mark.parametrize("rest", [False, True])
def test_ending_past_the_criterion_is_a_collapse(block, rest):
    # fired at record 1, then still (1.5 x the collapse distance, below the confirmation) to the end or
    # until the rest rule ends the run: it did not come back, confirmed when the run ends
    frames = [_still(block), _slid(block, 1.5 * D_C, 1.1 * V_C)] + [_slid(block, 1.5 * D_C, 0.0)] * 6
    eng = ScriptedEngine(frames, SC.record_steps)
    rule = (_record_t(2), 2 * SC.record_every, 1e-6) if rest else None
    sim = simulate(block, SC, Rest(), (len(frames) - 1) * SC.record_every, engine=eng, rest=rule, rest_span=True)
    assert sim.collapsed and sim.t_collapse == sim.t_exceed == _record_t(1)
    t_end = _record_t(3) if rest else _record_t(len(frames) - 1)  # at rest: no variation over records 1-3
    assert sim.t_confirm == t_end == sim.history.t[-1]
    assert (sim.t_rest == t_end) if rest else math.isnan(sim.t_rest)
    # the same end below the criterion's distance is a survival after an excursion
    frames = [_still(block), _slid(block, 1.5 * D_C, 1.1 * V_C)] + [_slid(block, 0.9 * D_C, 0.0)] * 6
    eng = ScriptedEngine(frames, SC.record_steps)
    sim = simulate(block, SC, Rest(), (len(frames) - 1) * SC.record_every, engine=eng, rest=rule, rest_span=True)
    assert not sim.collapsed and sim.t_exceed == _record_t(1)


def test_an_engine_running_other_options_than_the_settings_is_refused(block):
    from dem.core.engines.options import PyBulletOptions
    from foundation.errors import ArchdemInputError

    frames = [_slid(block, 0.0, 0.0)] * 3
    eng = ScriptedEngine(frames, S.record_steps)
    eng.options = PyBulletOptions(solver_iterations=50)
    with pytest.raises(ArchdemInputError, match="other options than settings.engine_options"):
        simulate(block, S, Rest(), 2 * S.record_every, engine=eng)
    eng.options = S.engine_options  # the settings' own: runs
    assert simulate(block, S, Rest(), 2 * S.record_every, engine=eng).steps == 2 * S.record_steps
