"""Shake-table runs: a single rectangular block against the rocking-block model (docs/validation.md#3-single-block),
the first-rebound definition, and the run file."""
import math

import numpy as np
import pytest

from analytic.motions.inputs import PulseA, SinePulse
from dem.core.model import single_block
from dem.core.settings import Settings
from dem.experiments.shake.file import load_shake, save_shake
from dem.experiments.shake.run import ShakeProtocol, first_rebound, shake
from specimens.constants import NO_SLIDING_MU, G
from foundation.errors import ArchdemInputError

# full base 0.1 m x height 0.4 m (b/h = 0.25); planar, because the analytic model is 2-D and the
# 3-D block (0.1 m wide) otherwise rocks out of plane too (measured: 45 mm drift along z, then an
# energy jump, at 0.33 g / 3 Hz); friction high enough that the block never slides
B, H = 0.1, 0.4
SETTINGS = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, planar=True)


@pytest.fixture(scope="module")
def block():
    return single_block(B, H)


def _max_rotation(res) -> float:
    from dem.core.detect import in_plane_angle

    return float(np.abs(in_plane_angle(res.sim.history.rotations()[:, 0])).max())


def _rotation_at_end(res) -> float:
    from dem.core.detect import in_plane_angle

    return float(abs(in_plane_angle(res.sim.history.rotations()[-1:, 0])[0]))


def test_rocking_onset_is_g_b_over_h(block):
    # a constant acceleration (pulse A, 0.3 s) 2 % below g b/h does not rock the block; 2 % above it
    # does (linearised growth phi ~ C (cosh p t - 1), p = 5.97 rad/s: ~0.01 rad after 0.3 s)
    onset = G * B / H
    proto = ShakeProtocol(tail=0.0, duration=0.3)
    below = shake(block, PulseA(0.98 * onset, 0.3), SETTINGS, proto)
    above = shake(block, PulseA(1.02 * onset, 0.3), SETTINGS, proto)
    # below onset the step only compresses the contact (a transient 4e-4 rad, back to 5e-5 rad at the
    # end, measured); above it the block rocks and the rotation keeps growing to 1.3e-2 rad at 0.3 s
    end_below, end_above = _rotation_at_end(below), _rotation_at_end(above)
    assert end_below < 2e-4
    assert end_above > 5e-3 and end_above == pytest.approx(_max_rotation(above))
    assert not below.collapsed and not above.collapsed


# (below, above): relative distances from the analytic threshold at which the DEM must survive and
# collapse. Measured (scan ratio 1.01, bisection 0.5 %): the DEM collapses from +0.9 % (2 Hz), +0.5 %
# (3 Hz, 5 Hz) on, so 2 % above everywhere; below it survives down to -10 % at 2 Hz (one lone collapse
# at -0.1 %), but collapses in islands at -8.7 % to -7.1 % (3 Hz) and -14 % to -3.4 % (5 Hz): impact
# scatter. At 5 Hz the -10 % run survives between islands: there the 10 % holds only as this point check
BAND = {2.0: (0.02, 0.02), 3.0: (0.10, 0.02), 5.0: (0.10, 0.02)}


@pytest.mark.parametrize("freq", sorted(BAND))
@pytest.mark.slow
def test_overturning_amplitude_matches_rocking_block_model(block, freq):
    """The DEM overturning amplitude of a plain one-cycle sine against the analytic rocking-block
    threshold (docs/physics/dynamics.md#2-the-rocking-block, Housner restitution from the momentum
    balance), by two runs per frequency: BAND below it survives, BAND above it collapses. The
    validation's 10 % (docs/validation.md#3-single-block) is the scatter of impact modelling: the
    DEM impact keeps 0.77-0.80 of the energy against Housner's 0.83 (4 contact points and ERP)."""
    from analytic.rocking.domain import failure_domain
    from analytic.rocking.rocking_block import RockingBlock

    dom = failure_domain(RockingBlock(B / 2, H / 2), "sine0", [freq], a_max_ratio=8.0, n_scan=16, workers=1)
    a_an = dom.columns[0].thresholds[0][0]
    below, above = BAND[freq]
    assert max(below, above) <= 0.10  # never wider than the validation rule
    proto = ShakeProtocol(tail=2.0)
    lo = shake(block, SinePulse((1 - below) * a_an, freq), SETTINGS, proto)
    hi = shake(block, SinePulse((1 + above) * a_an, freq), SETTINGS, proto)
    assert not lo.collapsed, f"{freq} Hz: DEM collapsed {below:.0%} below the analytic threshold {a_an / G:.4f} g"
    assert hi.collapsed, f"{freq} Hz: DEM survived {above:.0%} above the analytic threshold {a_an / G:.4f} g"
    # collapse is overturning: the block ends up rotated past its slenderness angle
    assert _max_rotation(hi) > math.atan(B / H)


def test_first_rebound_definition():
    # u = sin(2 pi t) from t = 0: motion starts at the first |u| > onset, first velocity reversal at t = 1/4
    t = np.linspace(0, 1, 1001)
    u = 1e-3 * np.sin(2 * np.pi * t)
    t0, tr = first_rebound(t, u, 1e-5)
    assert t0 == pytest.approx(0.002, abs=1e-3)  # 1e-3 sin(2 pi t) = 1e-5 at t = 1.6e-3
    assert tr == pytest.approx(0.25, abs=1e-3)  # linear interpolation of du/dt = 0 between records
    # a monotonic excursion has no rebound; a still crown has no onset
    assert first_rebound(t, 1e-3 * t, 1e-5)[1] is None
    assert first_rebound(t, np.zeros_like(t), 1e-5) == (None, None)


def test_run_file_roundtrip(block, tmp_path):
    res = shake(block, SinePulse(0.5 * G, 4.0), SETTINGS, ShakeProtocol(tail=0.25))
    p = save_shake(res, tmp_path / "run.h5")
    d = load_shake(p)
    s = d["summary"]
    assert s["collapsed"] == res.collapsed and s["peak_crown_mm"] == pytest.approx(res.peak_crown_mm)
    np.testing.assert_allclose(d["crown_u"], res.crown_u)
    # the stored input is the motion sampled at the simulator step: its peak is the amplitude
    assert np.abs(d["input_a"]).max() == pytest.approx(0.5 * G, rel=1e-4)
    assert d["sim"].history.pos.shape == res.sim.history.pos.shape
    with pytest.raises(ArchdemInputError, match="exists; an existing result is never overwritten"):
        save_shake(res, p)
    assert load_shake(p)["summary"] == s  # the file is untouched


def test_skipping_the_friction_readout_leaves_the_run_unchanged(block):
    """Threshold scans skip the contact-force readout of the friction work: it only reads the
    engine, so the run itself (poses, outcome) must be the same step for step."""
    proto = ShakeProtocol(tail=0.25)
    a = shake(block, SinePulse(0.5 * G, 4.0), SETTINGS, proto)
    b = shake(block, SinePulse(0.5 * G, 4.0), SETTINGS, proto, friction_work=False)
    assert math.isfinite(a.sim.history.friction_work) and math.isnan(b.sim.history.friction_work)
    assert (a.collapsed, a.mode) == (b.collapsed, b.mode)
    np.testing.assert_array_equal(a.sim.history.pos, b.sim.history.pos)


@pytest.mark.parametrize("amp_g, freq", [
    pytest.param(0.2, 4.0, id="below-onset"),  # below the rocking onset g b/h = 0.25 g: it survives
    # regression pin: that 0.32 g at 3 Hz survives is this code's own earlier output, not physics
    # (the analytic threshold is 0.3602 g, but the DEM collapses in an island from 0.3287 g, BAND)
    pytest.param(0.32, 3.0, id="regression-pin-rocks-and-survives"),
])
@pytest.mark.slow
def test_a_run_ends_once_at_rest_after_the_motion(block, amp_g, freq):
    """The end-at-rest rule (ShakeProtocol.rest_after) only cuts a survived run short: the run is
    the same step for step up to the end, with the same outcome and residual displacement as the
    whole duration simulated. At 0.32 g, 3 Hz the block rocks until about 2.7 s (swings of 31 mm
    at the top corner, each apex at rest for an instant: the rule looks at 0.1 s), then stands."""
    proto = ShakeProtocol(tail=4.0)
    cut = shake(block, SinePulse(amp_g * G, freq), SETTINGS, proto)
    whole = shake(block, SinePulse(amp_g * G, freq), SETTINGS, ShakeProtocol(tail=4.0, rest_after=None))
    assert not whole.collapsed and not cut.collapsed and math.isnan(whole.sim.t_rest)
    t_end = 1.0 / freq + proto.rest_after
    assert t_end <= cut.sim.t_rest < whole.sim.history.t[-1]
    n = len(cut.sim.history.t)
    np.testing.assert_array_equal(cut.sim.history.pos, whole.sim.history.pos[:n])
    # at rest: what is left of the run moves the crown by less than the rule's span (3e-4 x size)
    span = proto.rest_span * block.size
    assert abs(cut.residual_crown_mm - whole.residual_crown_mm) < 1e3 * span
    assert cut.summary()["t_end_at_rest"] == cut.sim.t_rest


def test_bad_rest_rule_is_an_input_error():
    for kw in ({"rest_after": -0.1}, {"rest_window": 0.0}, {"rest_span": float("nan")}):
        with pytest.raises(ArchdemInputError, match="rest"):
            ShakeProtocol(**kw)


def test_bad_confirmation_is_an_input_error():
    for bad in (1.0, 0.5, float("nan")):
        with pytest.raises(ArchdemInputError, match="confirm_fraction"):
            ShakeProtocol(confirm_fraction=bad)
    assert ShakeProtocol(confirm_fraction=None).confirm_fraction is None  # the criterion's firing is the collapse


# a square block (b/h = 1): the collapse criterion (its far top corner moved by its height) fires at a
# rotation of 2 asin(1 / (2 sqrt 2)) = 41.4 deg, inside its slenderness angle of 45 deg
SQUARE = 0.2


@pytest.mark.slow
def test_a_block_the_pulse_pushes_back_from_past_its_slenderness_survives():
    """A one-cycle 2 Hz sine 5 % below the analytic overturning amplitude throws the square block to
    61.7 deg (analytic and DEM alike), past the criterion and past its slenderness angle, and the second
    half of the pulse brings it back: survival, with the firing, peak and residual displacement kept. The
    rule of a firing as the collapse called it one at 0.265 s; 5 % above the threshold it falls and the
    collapse is confirmed at two block heights (docs/decisions/012-collapse-confirmed.md)."""
    from analytic.rocking.domain import failure_domain
    from analytic.rocking.dynamics import simulate as rock
    from analytic.rocking.rocking_block import RockingBlock
    from dem.core.settings import dynamics_settings

    rb = RockingBlock(SQUARE / 2, SQUARE / 2)
    a_an = failure_domain(rb, "sine0", [2.0], a_max_ratio=8.0, n_scan=16, workers=1).columns[0].thresholds[0][0]
    blk = single_block(SQUARE, SQUARE)
    st = dynamics_settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, planar=True)
    below = shake(blk, SinePulse(0.95 * a_an, 2.0), st, ShakeProtocol(tail=2.0))
    assert not below.collapsed and below.recovered and below.t_exceed is not None
    phi = math.degrees(rock(rb, SinePulse(0.95 * a_an, 2.0)).max_ratio * rb.alpha)
    assert phi > 55.0 and math.degrees(_max_rotation(below)) == pytest.approx(phi, abs=1.0)
    s = below.summary()
    assert s["max_displacement_mm"] > 1.4e3 * SQUARE and s["residual_displacement_mm"] < 0.1e3 * SQUARE
    assert s["t_end_at_rest"] is not None and s["recovered"] and s["t_collapse_confirmed"] is None
    old = shake(blk, SinePulse(0.95 * a_an, 2.0), st, ShakeProtocol(tail=2.0, confirm_fraction=None))
    assert old.collapsed and old.t_collapse == below.t_exceed
    above = shake(blk, SinePulse(1.05 * a_an, 2.0), st, ShakeProtocol(tail=2.0))
    assert above.collapsed and above.t_collapse == above.t_exceed
    assert above.sim.t_confirm > above.t_collapse and above.sim.history.dmax[-1] > 2.0 * SQUARE
    assert math.degrees(_max_rotation(above)) > 85.0  # on its side


@pytest.mark.slow
def test_the_quick_campaigns_6hz_top_amplitude_is_an_excursion_the_arch_recovers_from():
    """Sh02-Sd020 (glued, reference friction, MuJoCo) under the 6 Hz one-cycle sine at 4 x its static
    lambda, the top of the quick campaign's scan: a point passes the ring thickness (48 mm) at 0.12 s
    and the arch comes back to rest 3.6 mm from where it started. Until decision 012 this was a collapse."""
    from dem.core.model import as_model
    from dem.core.settings import dynamics_settings
    from dem.experiments.shake.thresholds import static_onset

    model = as_model("Sh02-Sd020")
    st = dynamics_settings()
    a = 4.0 * static_onset(model, st)
    r = shake(model, SinePulse(a * G, 6.0), st)
    s = r.summary()
    assert not r.collapsed and r.recovered and r.t_exceed == pytest.approx(0.12, abs=0.011)
    assert s["max_displacement_mm"] > 1.05e3 * model.size and s["residual_displacement_mm"] < 0.15e3 * model.size
    assert s["t_end_at_rest"] is not None
    assert shake(model, SinePulse(a * G, 6.0), st, ShakeProtocol(confirm_fraction=None)).collapsed


@pytest.mark.slow
def test_the_issue_case_on_lmgc90_recovers_and_stands():
    """Issue 53: Sh06-Sd015, free, friction 0.577 everywhere, 6 Hz at 1.3 g on LMGC90 passed the ring
    thickness (49.9 mm at 0.185 s; the criterion fired at 0.14 s) and stood again 15 mm from where it
    started: a survival, the firing kept."""
    pytest.importorskip("compas_lmgc90", reason="the lmgc90 extra is not installed (pip install -e '.[lmgc90]')")
    from dem.core.model import as_model
    from dem.core.settings import dynamics_settings

    model = as_model("Sh06-Sd015", config="free")
    r = shake(model, SinePulse(1.3 * G, 6.0), dynamics_settings(mu_joint=0.577, mu_base=0.577, engine="lmgc90"))
    s = r.summary()
    assert not r.collapsed and r.recovered and r.t_exceed == pytest.approx(0.14, abs=0.011)
    assert s["max_displacement_mm"] == pytest.approx(49.9, abs=1.0) and s["max_displacement_mm"] > 1e3 * model.size
    assert s["residual_displacement_mm"] == pytest.approx(15.0, abs=1.0) and s["t_end_at_rest"] is not None


def test_progress_reports_simulated_seconds_and_the_end():
    # a block toppled by a strong pulse: the simulated time of the run (rounded to 0.01 s) out of its
    # duration, then where it ended and why; the run is the one without progress
    calls = []
    block, pulse = single_block(0.1, 0.4), SinePulse(30.0, 2.0)
    r = shake(block, pulse, progress=lambda *a: calls.append(a))
    t_end = round(r.sim.steps * r.settings.dt, 2)
    assert calls[0] == (0.0, 1.5, "input") and calls[-1] == (t_end, t_end, "collapsed")
    assert [c[0] for c in calls] == sorted(c[0] for c in calls)
    plain = shake(block, pulse)
    assert (plain.collapsed, plain.t_collapse, plain.sim.steps) == (r.collapsed, r.t_collapse, r.sim.steps)


def test_the_spec_runs_as_shake_and_its_summary_is_its_schema_row(block, tmp_path):
    """``run(ShakeSpec)`` is ``shake`` with the spec's fields; the summary (the JSON of ``archdem shake``) is
    the result's one row, in its schema's columns, and the CSV of that row reads back to it."""
    from dem.common.tables import read_csv
    from dem.experiments.shake.run import ShakeResult, ShakeSpec, run

    proto = ShakeProtocol(tail=0.0, duration=0.1)
    a = run(ShakeSpec(block, SinePulse(0.5 * G, 4.0), SETTINGS, proto, label="b"))
    b = shake(block, SinePulse(0.5 * G, 4.0), SETTINGS, proto, label="b")
    sa, sb = a.summary(), b.summary()
    assert list(sa) == ShakeResult.SCHEMA.names
    assert {k: v for k, v in sa.items() if k != "wall_s"} == {k: v for k, v in sb.items() if k != "wall_s"}
    assert sa["id"] == "b" and sa["steps"] == b.sim.steps and isinstance(sa["steps"], int)
    a.write_csv(tmp_path / "run.csv")
    _, (row,) = read_csv(tmp_path / "run.csv")
    assert row["peak_crown_mm"] == sa["peak_crown_mm"] and row["joints"] == sa["joints"]
    assert row["collapsed"] is sa["collapsed"]


def test_the_text_of_a_run_says_survival_or_collapse_and_where_the_file_is(block):
    from dem.experiments.shake.run import ShakeSpec, run

    res = run(ShakeSpec(block, SinePulse(0.2 * G, 4.0), SETTINGS, ShakeProtocol(tail=0.0, duration=0.1), label="b"))
    res.result_file = "runs/x.h5"
    text = res.text()
    assert text.startswith("b (") and f"mu {NO_SLIDING_MU:g}/{NO_SLIDING_MU:g}), PGA 0.200 g: survival, none; crown " \
        f"peak {res.peak_crown_mm:.2f} mm, residual {res.residual_crown_mm:.2f} mm; " in text
    assert text.endswith(" -> runs/x.h5")
