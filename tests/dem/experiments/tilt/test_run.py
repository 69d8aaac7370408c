"""The staircase and continuous-ramp tilt protocols against the closed form of a single block
(docs/validation.md#3-single-block): the same two cases the hold-and-bisect protocol passes in test_engines_shared;
the hold protocol's LP start (its first bracket around the static LP of the same blocks)."""
import functools
from dataclasses import replace

import numpy as np
import pytest

from dem.core.model import single_block
from dem.core.settings import Settings
from dem.experiments.tilt.run import TiltProtocol, tilt

B, H = 0.1, 0.2  # b/h = 0.5
MU_SLIDE = 0.3  # < b/h: Coulomb sliding at lambda = mu
TRUTH = {"slide": MU_SLIDE, "rock": B / H}
MU_BASE = {"slide": MU_SLIDE, "rock": 1.0}

# staircase: 0.01 steps held 0.3 s; ramp: 0.005 per second (its onset lag for the sliding
# block, ~ r^(2/3) (6 d / g)^(1/3), is then ~1 % of mu; see dem.experiments.tilt.run). Both read lambda at
# the onset of the collapsing motion, not when the collapse criterion fires (which lagged by
# +2 % to +9 % at the former defaults: a sliding block needs time to travel 6 % of its height).
STAIRS = TiltProtocol(kind="staircase", step=0.01, stair_hold=0.3, lam_max=0.7)


@functools.lru_cache(maxsize=None)
def _run(case: str, kind: str, rate: float = 0.005):
    proto = STAIRS if kind == "staircase" else TiltProtocol(kind="ramp", rate=rate, lam_max=0.7)
    return tilt(single_block(B, H), Settings(mu_joint=1.0, mu_base=MU_BASE[case]), proto)


@pytest.mark.parametrize("kind", ["staircase", "ramp"])
@pytest.mark.parametrize("case", ["slide", "rock"])
@pytest.mark.slow
def test_block_threshold(case, kind):
    r = _run(case, kind)
    truth = TRUTH[case]
    if case == "slide":
        assert r.mode == "sliding" and r.joints[0].state == "slide"
    else:  # overturns about its downhill (+x, "extrados") corner
        assert r.mode == "rocking" and (r.joints[0].state, r.joints[0].face) == ("hinge", "extrados")
    assert r.n_sims == 1
    if kind == "staircase":
        # the staircase answers to one step (0.01 = 2-3 % here): its bracket, one step wide,
        # must hold the closed-form threshold (1e-9: rounding of k * step)
        assert r.bracket[1] - r.bracket[0] == pytest.approx(STAIRS.step)
        assert r.bracket[0] - 1e-9 <= truth <= r.bracket[1] + 1e-9
        assert r.lam == r.bracket[1]
    else:
        assert r.lam == pytest.approx(truth, rel=0.02)  # the 2 % for the block


@pytest.mark.slow
def test_ramp_rate_insensitivity():
    # docs/validation.md#8-insensitivity-to-time-step-and-rate: halving the ramp rate changes lambda by < 2 %
    fast, slow = _run("rock", "ramp", 0.01), _run("rock", "ramp", 0.005)
    assert abs(fast.lam - slow.lam) / slow.lam < 0.02


def test_hold_lp_start_brackets_the_lp_of_the_assembly(monkeypatch):
    # the LP start resolves the estimate from the assembly tilt() is given, stores it as the
    # result's protocol.guess and bisects GUESS_BRACKET x LP; the held levels are faked
    # (collapse above a known threshold) so that only the bracketing logic runs
    from types import SimpleNamespace

    import dem.experiments.tilt.run as pr
    from dem.core.model import from_assembly
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen
    from foundation.errors import ArchdemInputError

    asm = discretise(get_specimen("Sh06-Sd015").arch, config="glued")
    model, settings = from_assembly(asm), Settings()
    lp = pr.lp_guess(asm, settings)
    truth = 0.97 * lp
    levels = []

    def fake_hold(model, settings, proto, lam):
        levels.append(lam)
        return SimpleNamespace(collapsed=lam > truth, mode="rocking", joints=[])

    monkeypatch.setattr(pr, "hold_level", fake_hold)
    proto = TiltProtocol(start="lp", tol=0.005)
    bare = replace(model, assembly=None)  # a model that does not know its blocks (e.g. read from a file)
    with pytest.raises(ValueError, match="assembly"):
        tilt(bare, settings, proto)
    r = tilt(model, settings, proto, assembly=asm)
    assert r.protocol.guess == lp and r.protocol.start == "lp"
    lo, hi = (x * lp for x in pr.GUESS_BRACKET)
    # probe_ends "last": the midpoint first; the truth lies below the bracket, so the lower end is
    # simulated once the bisection ends on it, collapses and moves the bracket down
    assert levels[0] == pytest.approx(0.5 * (lo + hi)) and lo in levels and hi not in levels
    assert r.bracket[0] <= truth < r.bracket[1] and r.bracket[1] - r.bracket[0] <= 0.005 * r.bracket[1]
    # the default start: the LP when the assembly is given, otherwise the ramp scan (faked here:
    # collapse detected 10 % above the truth); the result stores which one ran
    auto = tilt(model, settings, TiltProtocol(tol=0.005), assembly=asm)
    assert auto.protocol.start == "lp" and auto.protocol.guess == lp and auto.lam == r.lam
    # a model built from its blocks knows them: the same start and answer without passing them
    own = tilt(model, settings, TiltProtocol(tol=0.005))
    assert own.protocol.start == "lp" and own.levels == auto.levels and own.lam == auto.lam
    monkeypatch.setattr(pr, "simulate", lambda model, settings, load, duration, **kw:
                        SimpleNamespace(collapsed=True, t_collapse=1.1 * truth / load.rate))
    scan = tilt(bare, settings, TiltProtocol(tol=0.005))
    assert scan.protocol.start == "scan" and scan.protocol.guess is None
    assert scan.bracket[0] <= truth < scan.bracket[1]
    with pytest.raises(ArchdemInputError, match="start"):
        TiltProtocol(start="guess")
    with pytest.raises(ArchdemInputError, match="guess"):  # the former sentinel: a clear error, not a TypeError
        TiltProtocol(guess="lp")


@pytest.mark.parametrize("truth, n_last, n_first", [(0.99, 3, 5), (0.973, 4, 5), (0.96, 8, 7), (1.02, 8, 6)])
def test_hold_first_bracket_costs(monkeypatch, truth, n_last, n_first):
    # inside GUESS_BRACKET the bisection reaches 0.5 % in 3 bisections. probe_ends "first": 2 ends + 3
    # = 5 simulations; "last" (the default): 3, plus an end the bisection ends on (0.973: every
    # midpoint collapsed, 0.972 is simulated). An end that is wrong costs one step outward and a 5 %
    # bracket (4 bisections): "first" 7 or 6, "last" 8 (the 3 first midpoints, the end, 4 more).
    # Faked levels, bracketing only
    from types import SimpleNamespace

    import dem.experiments.tilt.run as pr
    from dem.core.model import from_assembly
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    asm = discretise(get_specimen("Sh06-Sd015").arch, config="glued")
    levels = []

    def fake_hold(model, settings, proto, lam):
        levels.append(lam)
        return SimpleNamespace(collapsed=lam > truth, mode="rocking", joints=[])

    monkeypatch.setattr(pr, "hold_level", fake_hold)
    for probe, n_sims in (("last", n_last), ("first", n_first)):
        levels.clear()
        r = tilt(from_assembly(asm), Settings(), TiltProtocol(guess=1.0, tol=0.005, probe_ends=probe))
        assert r.n_sims == n_sims == len(levels) and r.bracket[0] <= truth < r.bracket[1]
        assert r.bracket[1] - r.bracket[0] <= 0.005 * r.bracket[1]
        # both ends of the final bracket were simulated: the last stable and the first collapsing level
        assert r.bracket[0] in levels and r.bracket[1] in levels
        assert max(x for x in levels if x <= truth) == r.bracket[0]
        assert min(x for x in levels if x > truth) == r.bracket[1]
    levels.clear()
    wide = tilt(from_assembly(asm), Settings(), TiltProtocol(guess=1.0, tol=0.005, guess_bracket=[0.95, 1.01],
                                                             probe_ends="first"))
    assert levels[:2] == [1.01, 0.95 if truth < 1.01 else 1.01 * pr.GUESS_STEPS[0]]
    assert wide.protocol.guess_bracket == (0.95, 1.01)
    assert wide.bracket[0] <= truth < wide.bracket[1]


@pytest.mark.parametrize("bad", [(1.01, 0.95), (0.0, 1.0), (0.9,), "lp", (0.9, float("inf"))])
def test_bad_guess_bracket_is_an_input_error(bad):
    from foundation.errors import ArchdemInputError

    with pytest.raises(ArchdemInputError, match="guess_bracket"):
        TiltProtocol(guess_bracket=bad)
    with pytest.raises(ArchdemInputError, match="probe_ends"):
        TiltProtocol(probe_ends="never")


def test_slowed_protocol_scales_every_duration_and_rate():
    p = TiltProtocol()
    s = p.slowed(2.0)
    for k in ("ramp_time", "hold_time", "stair_hold", "rest_after", "rest_window"):
        assert getattr(s, k) == 2 * getattr(p, k), k
    assert (s.scan_rate, s.rate) == (p.scan_rate / 2, p.rate / 2)
    # levels, tolerances and the rest rule's relative growth are not times
    assert (s.tol, s.step, s.guess_bracket, s.rest_growth) == (p.tol, p.step, p.guess_bracket, p.rest_growth)
    assert TiltProtocol(rest_after=None).slowed(3.0).rest_after is None


# ------------------------------------------------------------------------ the hold's rest rule
def _level(model, settings, lam, **proto):
    from dem.experiments.tilt.run import hold_level

    return hold_level(model, settings, TiltProtocol(**proto), lam)


def test_rest_rule_ends_a_level_at_rest():
    # a block at half its sliding threshold is at rest: the level ends rest_after into the hold,
    # not collapsed, having simulated less than the full hold
    p = TiltProtocol()
    s = Settings(mu_joint=1.0, mu_base=MU_SLIDE)
    r = _level(single_block(B, H), s, 0.5 * MU_SLIDE)
    assert not r.collapsed
    assert r.t_rest == pytest.approx(p.ramp_time + p.rest_after, abs=s.record_every / 2)
    assert r.steps < round((p.ramp_time + p.hold_time) / s.dt)
    full = _level(single_block(B, H), s, 0.5 * MU_SLIDE, rest_after=None)
    assert not full.collapsed and np.isnan(full.t_rest)  # held the full hold_time
    assert full.steps == round((p.ramp_time + p.hold_time) / s.dt)


@pytest.mark.parametrize("excess", [0.01, 0.003])
def test_rest_rule_does_not_end_a_block_sliding_just_above_mu(excess):
    # 1 % and 0.3 % above mu (the hold's bisection stops at 0.5 %) the block accelerates at only
    # ~ g (lambda - mu): it must not be taken for at rest, so the level runs as held the full hold
    # (bit-identical): at +1 % it collapses, at +0.3 % it slides ~3 % of its height in the hold,
    # short of the collapse displacement (6 %), with or without the rule
    s = Settings(mu_joint=1.0, mu_base=MU_SLIDE)
    lam = (1 + excess) * MU_SLIDE
    r, full = _level(single_block(B, H), s, lam), _level(single_block(B, H), s, lam, rest_after=None)
    assert np.isnan(r.t_rest)  # not ended at rest
    assert r.steps == full.steps and r.collapsed == full.collapsed and r.history.dmax[-1] == full.history.dmax[-1]
    assert full.history.dmax[-1] > 0.02 * H  # it did slide
    if excess == 0.01:
        assert r.collapsed


@pytest.mark.slow
def test_rest_rule_on_an_arch_below_and_above_the_lp():
    # with no sliding the LP is the exact threshold: 0.9 x LP is at rest (ends early), 1.01 x LP
    # collapses as when held the full hold
    from dem.core.model import from_assembly
    from dem.experiments.tilt.run import lp_guess
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen
    from specimens.constants import NO_SLIDING_MU

    asm = discretise(get_specimen("Sh06-Sd015").arch, config="glued")
    m, s = from_assembly(asm), Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU)
    lp = lp_guess(asm, s)
    below = _level(m, s, 0.9 * lp)
    assert not below.collapsed and not np.isnan(below.t_rest)
    above, above_full = _level(m, s, 1.01 * lp), _level(m, s, 1.01 * lp, rest_after=None)
    assert above_full.collapsed and above.collapsed and above.t_collapse == above_full.t_collapse


def test_rest_rule_inputs():
    from foundation.errors import ArchdemInputError

    with pytest.raises(ArchdemInputError, match="rest_after"):
        TiltProtocol(rest_after=-0.1)
    with pytest.raises(ArchdemInputError, match="rest_growth"):
        TiltProtocol(rest_growth=0.0)
    assert TiltProtocol(rest_after=None).rest_after is None


def test_kinetic_energy_closed_form():
    # translation 1/2 m v^2 plus rotation 1/2 w . (R I R^T) w, for a body turned by R
    from scipy.spatial.transform import Rotation

    from dem.core.simulate import _kinetic_energy

    m = np.array([2.0, 3.0])
    inertia = np.array([np.diag([1.0, 2.0, 3.0]), np.diag([0.5, 0.5, 4.0])])
    R = Rotation.from_rotvec([[0.3, -0.2, 0.1], [0.0, 0.0, 0.0]]).as_matrix()
    v = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0]])
    w = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]])
    truth = 0.5 * 2.0 * 1.0 + 0.5 * 3.0 * 4.0 + 0.5 * w[0] @ R[0] @ inertia[0] @ R[0].T @ w[0] + 0.5 * 0.5
    assert _kinetic_energy(m, inertia, v, w, R) == pytest.approx(truth, rel=1e-14)


def test_hold_search_out_of_simulations_is_an_error_not_a_lambda(monkeypatch):
    # the truth far below the first estimate (0.3 x it): stepping down 5 % a simulation cannot reach it
    # in max_sims; the tilt test must say so, not return a bracket whose lower end was never simulated
    from types import SimpleNamespace

    import dem.experiments.tilt.run as pr
    from dem.core.model import single_block
    from foundation.errors import ArchdemInputError

    guess, held = 0.5, []

    def fake_hold(model, settings, proto, lam):
        held.append(lam)
        return SimpleNamespace(collapsed=lam > 0.3 * guess, mode="rocking", joints=[])

    monkeypatch.setattr(pr, "hold_level", fake_hold)
    with pytest.raises(ArchdemInputError, match="max_sims"):
        tilt(single_block(0.1, 0.4), Settings(), TiltProtocol(guess=guess))
    assert len(held) == TiltProtocol().max_sims


def test_on_level_hook_sees_every_held_level(monkeypatch):
    from types import SimpleNamespace

    import dem.experiments.tilt.run as pr
    from dem.core.model import single_block

    monkeypatch.setattr(pr, "hold_level", lambda model, settings, proto, lam:
                        SimpleNamespace(collapsed=lam > 0.25, mode="rocking", joints=[]))
    seen = []
    r = tilt(single_block(0.1, 0.4), Settings(), TiltProtocol(guess=0.25), on_level=lambda lam, sim: seen.append((lam, sim.collapsed)))
    assert seen == r.levels and r.bracket[0] <= 0.25 < r.bracket[1]


def test_time_scale_of_larger_arches_only():
    # similar arches run the same dimensionless test: times x sqrt(L / L_ref), never below 1
    import math

    from dem.core.model import single_block
    from dem.experiments.tilt.run import LENGTH_REF, RC_REF, scaled, time_scale_of
    from foundation.errors import ArchdemInputError
    from specimens.catalogue import SPECIMEN_IDS, get_specimen
    from specimens.geometry import PointedArch

    assert all(time_scale_of(get_specimen(s).arch) == 1.0 for s in SPECIMEN_IDS)
    big = PointedArch.from_radii(5.0, 5.8, 0.0)
    assert time_scale_of(big) == pytest.approx(math.sqrt(big.Rc / RC_REF))
    assert time_scale_of(single_block(0.2, 0.8)) == 1.0
    assert time_scale_of(big, 2.0) == 2.0
    with pytest.raises(ArchdemInputError):
        time_scale_of(big, -1)
    p, s = scaled(TiltProtocol(), Settings(), 3.0)
    assert p.time_scale == 3.0 and p.hold_time == pytest.approx(3.0) and p.ramp_time == pytest.approx(1.5)
    # the step stays (PyBullet's contacts are not similar under a larger one); records follow the protocol
    assert s.dt == Settings().dt and s.record_every == pytest.approx(3 * Settings().record_every)
    assert LENGTH_REF == pytest.approx(max(get_specimen(i).arch.Rp for i in SPECIMEN_IDS))


def test_time_scale_of_a_drawing_from_its_length_scale(tmp_path):
    import math

    from dem.experiments.tilt.run import LENGTH_REF, time_scale_of
    from specimens.arch_set import set_arch
    from specimens.catalogue import get_specimen
    from specimens.exchange import read_assembly, write_assembly

    asm = set_arch("drawn-ring-csv").assembly(tmp_path)
    assert time_scale_of(asm) == pytest.approx(math.sqrt(asm.length_scale / LENGTH_REF)) and time_scale_of(asm) > 1
    # a catalogue arch drawn and read back keeps its scale (the drawing carries its length scale)
    from specimens.blocks import discretise

    sh1 = discretise(get_specimen("Sh1-Sd025").arch, config="free")
    back = read_assembly(write_assembly(sh1, tmp_path / "sh1.csv"))
    assert time_scale_of(back) == time_scale_of(sh1) == 1.0


@pytest.mark.parametrize("truth", [0.99, 0.973, 0.96, 1.02])
@pytest.mark.parametrize("probe", ["last", "first"])
def test_progress_follows_the_search(monkeypatch, truth, probe):
    # the progress of a hold search: one report as each level starts and ends, the simulations counted,
    # the bracket the search holds (a wrong end moved outward), the total never below what was run;
    # the last report is the answer. Faked levels, as above
    from types import SimpleNamespace

    import dem.experiments.tilt.run as pr
    from dem.core.model import single_block

    def fake_hold(model, settings, proto, lam, engine=None):
        return SimpleNamespace(collapsed=lam > truth, mode="rocking", joints=[])

    monkeypatch.setattr(pr, "hold_level", fake_hold)
    calls = []
    r = tilt(single_block(0.1, 0.4), Settings(), TiltProtocol(guess=1.0, probe_ends=probe),
             progress=lambda done, total, note: calls.append((done, total, note)))
    ends = [c for c in calls if " held;" in c[2] or " collapsed;" in c[2]]
    assert [c[0] for c in ends] == list(range(1, r.n_sims + 1))
    assert all(total >= done for done, total, _ in calls)
    assert ends[-1][1] == r.n_sims  # nothing left once the search ended
    assert f"bracket [{r.bracket[0]:.4f}, {r.bracket[1]:.4f}]" in ends[-1][2]
    assert calls[-1] == (r.n_sims, r.n_sims, f"lambda = {r.lam:.4f}")
    for (lam, collapsed), (_, _, note) in zip(r.levels, ends):
        assert note.startswith(f"level {lam:.4f} {'collapsed' if collapsed else 'held'}")


@pytest.mark.slow
def test_progress_of_a_real_tilt_reports_simulated_time():
    calls = []
    r = tilt("Sh06-Sd010", progress=lambda done, total, note: calls.append((done, total, note)))
    assert calls[0] == (0, None, "static LP of the blocks (first estimate)")
    assert any(" s; bracket" in note for _, _, note in calls)  # within a level: its simulated time
    assert [d for d, _, _ in calls] == sorted(d for d, _, _ in calls) and calls[-1][0] == r.n_sims


# ------------------------------------------------------------------------ spec, run and the result's table
def _faked_result(monkeypatch, **spec):
    """A tilt of Sh06-Sd015 through run(TiltSpec) with faked held levels (collapse above 0.29): the
    bracketing only, and the result as the command sees it."""
    from types import SimpleNamespace

    import dem.experiments.tilt.run as pr
    from dem.core.model import from_assembly
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    monkeypatch.setattr(pr, "hold_level", lambda model, settings, proto, lam:
                        SimpleNamespace(collapsed=lam > 0.29, mode="rocking", joints=[], out_of_plane={},
                                        history=SimpleNamespace(friction_work=1e-3)))
    asm = discretise(get_specimen("Sh06-Sd015").arch, config="glued")
    return pr, asm, pr.run(pr.TiltSpec(from_assembly(asm, name="Sh06-Sd015"), assembly=asm, label="Sh06-Sd015", **spec))


def test_run_of_a_spec_is_the_tilt_call(monkeypatch):
    pr, asm, res = _faked_result(monkeypatch, protocol=TiltProtocol(tol=0.005))
    old = tilt(asm, Settings(), TiltProtocol(tol=0.005), label="Sh06-Sd015")
    assert (res.lam, res.bracket, res.levels, res.protocol) == (old.lam, old.bracket, old.levels, old.protocol)
    with pytest.raises(Exception):  # a spec is frozen
        pr.TiltSpec("Sh06-Sd015").label = "x"


def test_the_result_declares_its_row_once(monkeypatch, tmp_path):
    # the JSON answer is the schema's one row, in its order; the CSV reads back typed; the printed lines
    from dem.common.tables import read_csv

    _, _, res = _faked_result(monkeypatch)
    s = res.summary()
    assert list(s) == res.SCHEMA.names and s["lambda"] == res.lam and s["n_sims"] == res.n_sims
    assert s["lp_check"]["agrees"] in (True, False) and s["joints"] == []
    res.write_csv(tmp_path / "tilt.csv")
    _, rows = read_csv(tmp_path / "tilt.csv")
    assert rows[0]["lambda"] == res.lam and rows[0]["bracket"] == list(res.bracket) and rows[0]["planar"] is False
    lines = res.lines()
    assert lines[0].startswith(f"Sh06-Sd015 (glued, mu 0.577/1, hold): lambda = {res.lam:.4f} (theta = ")
    assert f"{res.n_sims} simulations" in lines[0] and lines[-1].startswith("  limit analysis of the same blocks: lambda = ")
    assert len(lines) == 2  # the catalogue's scale: no line on a slowed protocol
