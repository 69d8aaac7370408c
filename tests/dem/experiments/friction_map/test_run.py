"""Friction map: threshold bracketing, bisection rounds, map-level resume, analytic curves, CLI."""
from __future__ import annotations

import functools
import json
import math
from pathlib import Path

import numpy as np
import pytest

from dem.experiments.friction_map import map_cmd
from dem.experiments.friction_map import run as fm
from dem.experiments.tilt import case as cases
from dem.studies.sweep import StudyInterrupted
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError

GRID = "0.3:1.5:0.1"


def _syn(mu_star=0.537, lam_rock=0.3, **hooks):
    return {"synthetic": {"mu_star": mu_star, "lam_rock": lam_rock, **hooks}}


def _map(tmp_path, name="m.h5", specimens=("Sh06-Sd015",), workers=1, **kw):
    extra = kw.pop("extra", _syn())
    kw.setdefault("non_associative", False)  # a mixed-integer program per friction: test_non_associative.py
    return fm.catalogue_map(list(specimens), "glued", kw.pop("mus", GRID), 1.0, tmp_path / name, workers=workers,
                            progress=False, func=cases.SYNTHETIC_CASE, extra=extra, **kw)


# ----------------------------------------------------------------------------- pure logic
def test_parse_grid():
    g = fm.parse_mu_grid("0.3:1.5:0.1")
    # 13 values, stop included; rounding to 1e-9 removes the float noise of start + k * step
    assert len(g) == 13 and g[0] == 0.3 and g[-1] == 1.5 and g[2] == 0.5
    assert fm.parse_mu_grid("0.8, 0.4,0.4") == [0.4, 0.8]
    for bad in ("abc", "1.5:0.3:0.1", "0.3:1.5:0", "0.3:1.5", "-0.1,0.5", "0:1:0.5", ""):
        with pytest.raises(ArchdemInputError):
            fm.parse_mu_grid(bad)


def test_threshold_bracket_rules():
    mus = [0.3, 0.4, 0.5, 0.6, 0.7]
    th = fm.threshold_bracket(mus, ["sliding", "mixed", "sliding", "rocking", "rocking"])
    # mixed counts as sliding: the last sliding point is 0.5, the next rocking one 0.6
    assert (th.lo, th.hi, th.status, th.monotonic) == (0.5, 0.6, "bracketed", True)
    assert th.mu_star == pytest.approx(0.55, abs=1e-15)
    # first switch as mu rises (the reference study's procedure): a sliding/mixed point above the
    # first rocking one does not move the bracket, it is flagged as non-monotonic
    th = fm.threshold_bracket(mus, ["sliding", "rocking", "mixed", "rocking", "rocking"])
    assert (th.lo, th.hi, th.status, th.monotonic) == (0.3, 0.4, "bracketed", False)
    # failed / none outcomes are ignored, order of input irrelevant
    th = fm.threshold_bracket(mus[::-1], ["rocking", "failed", "none", "sliding", "sliding"])
    assert (th.lo, th.hi) == (0.4, 0.7)
    th = fm.threshold_bracket(mus, ["rocking", "sliding", "rocking", "rocking", "rocking"])
    assert (th.status, th.hi, th.monotonic) == ("all_rocking", 0.3, False)
    assert fm.threshold_bracket(mus, ["rocking"] * 5).status == "all_rocking"
    assert fm.threshold_bracket(mus, ["rocking"] * 5).mu_star is None
    assert fm.threshold_bracket(mus, ["sliding"] * 5).status == "all_sliding"
    assert fm.threshold_bracket(mus, ["failed"] * 5).status == "no_data"
    assert fm.bisection_point(fm.Threshold(0.5, 0.6, "bracketed", True)) == 0.55
    assert fm.bisection_point(fm.Threshold(None, 0.3, "all_rocking", True)) is None


# ----------------------------------------------------------------------------- map machinery
@pytest.mark.slow
def test_map_bisection_brackets_known_threshold(tmp_path):
    true = 0.537
    r = _map(tmp_path, specimens=("Sh06-Sd015", "Sh1-Sd025"), workers=2, refine=3, extra=_syn(true))
    for s in r.specimens:
        th = s.threshold
        # grid step 0.1 halved 3 times: the bracket is 0.0125 wide and holds the true threshold
        assert th.status == "bracketed" and th.lo < true <= th.hi
        assert th.hi - th.lo == pytest.approx(0.1 / 8, abs=1e-9)
        assert sum(p.kind == "refine" for p in s.points) == 3
        assert sum(p.kind == "grid" for p in s.points) == 13
    assert r.rounds == 3 and r.n_failed == 0 and r.n_cases == 2 * 16


@pytest.mark.slow
def test_map_resume_after_crash_repeats_nothing(tmp_path):
    count = tmp_path / "count"
    count.mkdir()
    marker = tmp_path / "crash"
    marker.touch()
    # the worker dies at the first bisection midpoint (0.55), i.e. during refinement round 1
    extra = _syn(count_dir=str(count), crash_marker=str(marker), crash_mu=0.55)
    with pytest.raises(StudyInterrupted):
        _map(tmp_path, refine=3, extra=extra)
    n_first = len(list(count.iterdir()))
    assert n_first == 14  # 13 grid cases stored + the crashed one (whose count file was written)
    r = _map(tmp_path, refine=3, extra=extra, resume=True)
    files = list(count.iterdir())
    mus_run = sorted(float(f.name.split("-")[0]) for f in files)
    # every case ran exactly once, except the crashed one, which ran again on resume
    assert len(files) == len(r.specimens[0].points) + 1
    assert mus_run.count(0.55) == 2 and all(mus_run.count(m) == 1 for m in set(mus_run) - {0.55})
    # same answer as an uninterrupted map
    ref = _map(tmp_path, "ref.h5", refine=3)
    assert [(p.mu, p.mode, p.lam) for p in r.specimens[0].points] == \
        [(p.mu, p.mode, p.lam) for p in ref.specimens[0].points]
    # resuming a finished map runs nothing
    _map(tmp_path, refine=3, extra=extra, resume=True)
    assert len(list(count.iterdir())) == len(files)


@pytest.mark.slow
def test_failing_case_recorded_others_complete(tmp_path):
    r = _map(tmp_path, refine=2, extra=_syn(fail_mu=0.8))
    s = r.specimens[0]
    failed = [p for p in s.points if p.mode == "failed"]
    assert [p.mu for p in failed] == [0.8] and "fails on purpose" in failed[0].error and math.isnan(failed[0].lam)
    assert s.threshold.status == "bracketed" and s.threshold.lo < 0.537 <= s.threshold.hi
    assert r.n_failed == 1 and r.n_cases == 15
    rows = r.to_rows("points")
    assert len(rows) == 15 and {"id", "mu", "lambda", "mode"} <= set(rows[0])


@pytest.mark.slow
def test_dask_map_equals_local_map(tmp_path):
    distributed = pytest.importorskip("distributed", reason="the cluster extra is not installed (pip install -e '.[cluster]')")
    local = _map(tmp_path, "local.h5", refine=2, extra=_syn(fail_mu=0.9))
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                  dashboard_address=None) as cluster:
        remote = _map(tmp_path, "dask.h5", refine=2, extra=_syn(fail_mu=0.9), scheduler=cluster.scheduler_address)
    # same cases (keys), same bisection path, same outcomes
    assert [(p.key, p.mu, p.mode, p.kind) for p in remote.specimens[0].points] == \
        [(p.key, p.mu, p.mode, p.kind) for p in local.specimens[0].points]
    assert remote.specimens[0].threshold == local.specimens[0].threshold


@pytest.mark.slow
def test_figures_written(tmp_path):
    r = _map(tmp_path, specimens=("Sh06-Sd015", "Sh1-Sd025"), refine=1)
    paths = r.figures(tmp_path / "figs")
    assert {p.name for p in paths} == {"threshold_map.png", "mode_grid.png", "lambda_mu_Sh06-Sd015.png",
                                       "lambda_mu_Sh1-Sd025.png"}
    assert all(p.stat().st_size > 10_000 for p in paths)


# ----------------------------------------------------------------------------- analytic curves
@pytest.mark.parametrize("sid", ["Sh06-Sd015", "Sh02-Sd020"])
def test_analytic_curves_consistent(sid):
    from analytic.limit.limit_discrete import solve_lp
    from analytic.limit.two_bar import lambda_slide
    from specimens.blocks import discretise

    arch = get_specimen(sid).arch
    a = fm.analytic_curves(arch, "glued", 1.0, [0.3, 0.6, 1.2], non_associative=False)
    # uniqueness theorem: static LP without joint sliding = kinematic enumeration (HiGHS tolerance)
    assert a.lam_no_sliding == pytest.approx(a.lam_kinematic, rel=1e-6)
    # LP lambda(mu) non-decreasing and never above the no-sliding value (larger feasible set)
    assert np.all(np.diff(a.lam_lp) >= -1e-9) and np.all(a.lam_lp <= a.lam_no_sliding * (1 + 1e-9))
    # mu*_LP: below it lambda is short of the no-sliding value, above it reaches it
    asm = discretise(arch, config="glued")
    ms = a.mu_star_lp
    assert solve_lp(asm, ms + 2 * fm.LP_MU_TOL, 1.0).lam >= (1 - fm.LP_REL_TOL) * a.lam_no_sliding
    assert solve_lp(asm, ms - 2 * fm.LP_MU_TOL, 1.0).lam < (1 - fm.LP_REL_TOL) * a.lam_no_sliding
    # ... and the LP mechanism below it has a sliding joint, above it none
    assert any("sliding" in v for v in a.lp_states_below.values())
    assert not any("sliding" in v for v in a.lp_states_above.values())
    # two-bar mu*: its sliding multiplier equals the rocking one there (closed form vs linear solve)
    assert lambda_slide(arch, a.mu_star_two_bar) == pytest.approx(a.lam_kinematic, rel=1e-9)


def test_time_scale_similarity():
    from specimens.geometry import PointedArch

    small = PointedArch.from_ratios(0.6, 0.15, 0.2)
    big = PointedArch.from_ratios(0.6, 0.15, 2.5, width=1.25)
    c_small = cases.make_case("s", small, "glued", 0.5, 1.0)
    c_big = cases.make_case("b", big, "glued", 0.5, 1.0)
    s = math.sqrt(2.5 / 0.2)  # lengths x 12.5 -> times x sqrt(12.5) under gravity
    assert c_small["time_scale"] == 1.0 and c_big["time_scale"] == pytest.approx(s, rel=1e-12)
    p0, p1 = cases.scaled_protocol(c_small["protocol"], 1.0), cases.scaled_protocol(c_big["protocol"], s)
    assert p1.hold_time == pytest.approx(s * p0.hold_time) and p1.scan_rate == pytest.approx(p0.scan_rate / s)
    # the rest rule: its times scale like the hold, its growth is relative to the ring thickness
    assert p1.rest_after == pytest.approx(s * p0.rest_after) and p1.rest_window == pytest.approx(s * p0.rest_window)
    assert p1.rest_growth == p0.rest_growth
    st0, st1 = cases.scaled_settings(c_small), cases.scaled_settings(c_big)
    # same number of steps per protocol phase at both scales
    assert p1.hold_time / st1.dt == pytest.approx(p0.hold_time / st0.dt, rel=1e-9)


def test_case_key_holds_the_protocol_timing():
    # a study made with other ramp/hold defaults must not be resumed into: both times are part of
    # the case dict (the study's key), and a case with another ramp is another case
    from dem.experiments.tilt.run import TiltProtocol
    from dem.studies.sweep import case_key
    from specimens.geometry import PointedArch

    arch = PointedArch.from_ratios(0.6, 0.15, 0.2)
    c = cases.make_case("s", arch, "glued", 0.5, 1.0)
    d = TiltProtocol()
    assert c["protocol"]["ramp_time"] == d.ramp_time and c["protocol"]["hold_time"] == d.hold_time
    assert c["protocol"]["rest_after"] == d.rest_after and c["protocol"]["rest_growth"] == d.rest_growth
    other = cases.make_case("s", arch, "glued", 0.5, 1.0, protocol={**fm.MAP_PROTOCOL, "ramp_time": 2 * d.ramp_time})
    assert case_key(other) != case_key(c)


def test_map_cases_keep_their_own_first_bracket():
    # the map bisects from MAP_GUESS_BRACKET (see there why), a case with another protocol from the
    # tilt test's default; both, and when the bracket's ends are simulated, are written in the case
    # (and so in its key) and reach the protocol
    from dem.experiments.tilt.run import GUESS_BRACKET, TiltProtocol
    from dem.studies.sweep import case_key
    from specimens.geometry import PointedArch

    arch = PointedArch.from_ratios(0.6, 0.15, 0.2)
    c = cases.make_case("s", arch, "glued", 0.5, 1.0)
    assert tuple(c["protocol"]["guess_bracket"]) == cases.MAP_GUESS_BRACKET != GUESS_BRACKET
    assert cases.scaled_protocol(c["protocol"], 1.0).guess_bracket == cases.MAP_GUESS_BRACKET
    full = cases.make_case("s", arch, "glued", 0.5, 1.0, protocol={"kind": "hold", "tol": 0.005, "start": "lp"})
    assert cases.scaled_protocol(full["protocol"], 1.0).guess_bracket == TiltProtocol().guess_bracket == GUESS_BRACKET
    assert case_key(full) != case_key({**full, "protocol": {**full["protocol"], "guess_bracket": [0.95, 1.01]}})
    assert c["protocol"]["probe_ends"] == full["protocol"]["probe_ends"] == TiltProtocol().probe_ends == "last"
    assert cases.scaled_protocol(c["protocol"], 1.0).probe_ends == "last"
    assert case_key(full) != case_key({**full, "protocol": {**full["protocol"], "probe_ends": "first"}})


# ----------------------------------------------------------------------------- CLI
def _cli(argv, capsys):
    from dem.cli import main

    code = main(argv)
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.slow
def test_cli_json_schema(tmp_path, capsys, monkeypatch):
    # the CLI with the synthetic case function (the DEM path is covered by the real map test)
    real = fm.catalogue_map

    @functools.wraps(real)  # the CLI reads its defaults from the signature
    def fake(*a, **kw):
        return real(*a, **{**kw, "func": cases.SYNTHETIC_CASE, "extra": _syn(), "non_associative": False})

    monkeypatch.setattr(fm, "catalogue_map", fake)
    monkeypatch.setattr(map_cmd, "catalogue_map", fake)  # the command imported it by name
    code, out, err = _cli(["map", "--specimens", "Sh06-Sd015,Sh1-Sd010", "--mu", "0.3:0.9:0.2", "--workers", "1",
                           "--refine", "2", "--out", str(tmp_path / "s.h5"), "--json", "--plot", str(tmp_path / "p")],
                          capsys)
    assert code == 0, err
    data = json.loads(out)
    assert [d["id"] for d in data] == ["Sh06-Sd015", "Sh1-Sd010"]
    for d in data:
        assert {"id", "mu_star_dem", "mu_star_two_bar", "mu_star_lp", "mu_star_na", "points"} <= set(d)
        assert all(set(p) >= {"mu", "lambda", "mode"} for p in d["points"])
        assert len(d["points"]) == 4 + 2 and 0.5 < d["mu_star_dem"] <= 0.6
    assert (tmp_path / "p" / "threshold_map.png").exists()
    # the same study resumed: nothing new, same answer; an existing --out is refused
    code, out2, _ = _cli(["map", "--specimens", "Sh06-Sd015,Sh1-Sd010", "--mu", "0.3:0.9:0.2", "--workers", "1",
                          "--refine", "2", "--resume", str(tmp_path / "s.h5"), "--json"], capsys)
    assert code == 0 and json.loads(out2) == data
    code, _, err = _cli(["map", "--specimens", "Sh06-Sd015", "--out", str(tmp_path / "s.h5")], capsys)
    assert code == 2 and err.count("\n") == 1 and "exists" in err


@pytest.mark.parametrize("argv, words", [
    (["--mu", "abc"], "friction grid"),
    (["--mu", "1.5:0.3:0.1"], "start <= stop"),
    (["--specimens", "Sh9-Sd9"], "unknown specimen"),
    (["--mu-base", "-1"], "--mu-base"),
    (["--workers", "0"], "--workers"),
    (["--out", "a.h5", "--resume", "b.h5"], "not both"),
    (["--full-scale", "--specimens", "L7-Sh1-Sd0.1"], "full-scale"),
    (["--resume", "missing-dir/none.h5", "--specimens", "Sh06-Sd015", "--mu", "0.5"], None),
])
def test_cli_bad_input_exit_2(argv, words, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    if words is None:  # resume of a file that is not there starts a new study: check it is refused as non-HDF5
        Path("missing-dir").mkdir()
        Path("missing-dir/none.h5").write_text("not hdf5")
        words = "HDF5"
    code, out, err = _cli(["map", *argv], capsys)
    assert code == 2 and words in err and err.count("\n") == 1 and out == ""


# ----------------------------------------------------------------------------- the real DEM
@pytest.mark.slow  # two real DEM tilts (7 simulations each): 30 s on 2 idle cores, ~60 s on a loaded machine
def test_real_dem_map_two_frictions(tmp_path):
    """One specimen, two frictions far either side of its threshold."""
    from analytic.limit.limit_discrete import enumerate_mechanisms
    from specimens.blocks import discretise

    sp = get_specimen("Sh06-Sd015")
    r = fm.catalogue_map([sp], "glued", [0.3, 1.2], 1.0, tmp_path / "dem.h5", workers=2, progress=False, refine=0)
    s = r.specimens[0]
    assert r.n_failed == 0
    lo, hi = s.points
    lam_k = enumerate_mechanisms(discretise(sp.arch, config="glued")).lam
    # high friction: pure rocking at the four-hinge multiplier (DEM vs kinematic enumeration; 6 %
    # = the 2 % map tilt tolerance + the few-% DEM/limit-analysis gap measured in validation)
    assert hi.mode == "rocking" and hi.lam == pytest.approx(lam_k, rel=0.06)
    # low friction: the LP's mechanism slides (mu*_LP ~ 0.36) and so does the DEM, at a lower lambda
    assert lo.mode in fm.SLIDING_MODES and lo.lam < hi.lam
    # the DEM's mode switch lies in (0.3, 1.2]; so does the LP's, checked on the LP itself: short of
    # its no-sliding multiplier at 0.3, reaching it at 1.2 (and mu*_LP, bisected, in between)
    from analytic.limit.limit_discrete import solve_lp

    th, asm = s.threshold, discretise(sp.arch, config="glued")
    assert (th.status, th.lo, th.hi) == ("bracketed", 0.3, 1.2)
    lam_ns = solve_lp(asm, math.inf, 1.0).lam
    assert solve_lp(asm, th.lo, 1.0).lam < (1 - fm.LP_REL_TOL) * lam_ns <= solve_lp(asm, th.hi, 1.0).lam
    assert th.lo < s.analytic.mu_star_lp <= th.hi
    # without dilatancy too (its multiplier is at most the LP's: its mu* is not below the LP's)
    assert s.analytic.mu_star_lp - fm.LP_MU_TOL <= s.analytic.mu_star_na <= th.hi


@pytest.mark.slow
def test_replay_tilt_reproduces_the_collapse():
    # the report's collapse figure re-runs the collapsing level of a stored case: the engine is
    # deterministic for identical command sequences, so mode and joint states must be the case's
    sp = get_specimen("Sh06-Sd015")
    case = cases.make_case(sp.id, sp.arch, "glued", 1.2, 1.0, protocol={"kind": "hold", "tol": 0.05})
    res = cases.tilt_case(case)
    rep = cases.replay_tilt(case, res)
    assert rep.collapse is not None and rep.collapse.collapsed
    assert rep.mode == res["mode"]
    assert [j.state for j in rep.joints] == list(res["joint_states"])
    assert (rep.lam, rep.bracket) == (res["lambda"], tuple(res["bracket"]))
    assert [lv for lv, _ in rep.levels] == pytest.approx(np.asarray(res["levels"])[:, 0])


@pytest.mark.slow
def test_map_of_an_arch_on_piers(tmp_path, capsys, monkeypatch):
    """The map on piers: every case carries the piers, the references are those of the arch on
    piers (LP, enumeration, hinges anywhere), the two-bar ones (a ring on a rigid base) are absent."""
    import h5py

    from analytic.limit.limit_discrete import solve_lp
    from specimens import Piers, discretise

    real = fm.catalogue_map

    @functools.wraps(real)
    def fake(*a, **kw):
        return real(*a, **{**kw, "func": cases.SYNTHETIC_CASE, "extra": _syn(), "non_associative": False})

    monkeypatch.setattr(fm, "catalogue_map", fake)
    monkeypatch.setattr(map_cmd, "catalogue_map", fake)  # the command imported it by name
    piers = ["--pier-height", "0.4", "--pier-width", "0.144", "--pier-courses", "2"]
    code, out, err = _cli(["map", "--specimens", "Sh06-Sd015", "--mu", "0.3:0.9:0.2", "--workers", "1", "--refine", "0",
                           "--out", str(tmp_path / "s.h5"), "--json", *piers], capsys)
    assert code == 0, err
    d = json.loads(out)[0]
    asm = discretise(get_specimen("Sh06-Sd015").arch, piers=Piers(0.4, 0.144, courses=2))
    assert d["lambda_no_sliding"] == pytest.approx(solve_lp(asm, math.inf, 1.0).lam, rel=1e-9)
    assert d["mu_star_two_bar"] is None and d["mu_star_lp"] is not None
    with h5py.File(tmp_path / "s.h5", "r") as f:
        assert all(json.loads(g.attrs["params"])["piers"]["height"] == 0.4 for g in f["cases"].values())
    code, _, err = _cli(["map", "--specimens", "Sh06-Sd015", "--out", str(tmp_path / "t.h5"), "--pier-height", "0.4",
                         "--pier-width", "0.04"], capsys)
    assert code == 2 and "narrower than the ring's springing" in err and not (tmp_path / "t.h5").exists()


def test_the_map_declares_its_tables_once_and_prints_itself(tmp_path):
    # a specimen's map built by hand: its summary row and its tilts' rows in their schemas' columns, read back
    # typed from CSV; the printed table
    from dem.common.tables import read_csv

    nan = math.nan
    a = fm.AnalyticCurves(np.array([0.3, 0.6]), np.array([0.2, 0.3]), np.array([0.2, 0.3]), 0.35, 0.35, 0.34, 0.17,
                          0.415, 0.453, 0.442)
    pts = [fm.MapPoint(0.3, 0.22, "sliding", "grid", 2, 1.5, "k1", {"L4": "slide"}),
           fm.MapPoint(0.6, nan, "failed", "grid", 0, 0.1, "k2", {}, "boom")]
    s = fm.SpecimenMap("Sh02-Sd020", get_specimen("Sh02-Sd020").arch, "glued", 1.0, pts,
                       fm.Threshold(0.375, 0.4125, "bracketed", True), a)
    r = fm.MapResult(tmp_path / "m.h5", "glued", 1.0, [0.3, 0.6], [s], 2, 1, 12.0, [1.5], 3)
    summary, points = r.to_rows("summary"), r.to_rows("points")
    assert list(summary[0]) == s.SCHEMA.names and list(points[0]) == s.POINTS_SCHEMA.names
    assert summary[0]["mu_star_dem"] == pytest.approx(0.39375) and summary[0]["n_failed"] == 1
    s.write_csv(tmp_path / "map.csv")
    _, back = read_csv(tmp_path / "map.csv")
    assert back[0]["dem_monotonic"] is True and back[0]["n_tilts"] == 2 and back[0]["span_m"] == summary[0]["span_m"]
    assert points[1]["lambda"] is None and points[0]["joints"] == "L4:slide"
    assert r.lines("m.h5") == [
        "friction map (glued, mu_base 1, 2 friction values, 3 bisection rounds): 2 tilts, 1 failed, 12 s -> m.h5",
        "id                        Sh    Sd  mu*DEM  bracket         mu*LP   mu*NA  mu*2bar  lambda_ns  status",
        "Sh02-Sd020              0.20  0.20   0.394  [ 0.375, 0.412]  0.415     -     0.453    0.350  bracketed"]


def test_run_of_a_spec_passes_every_field_to_the_map(monkeypatch):
    import dataclasses
    import inspect

    names = list(inspect.signature(fm.catalogue_map).parameters)
    got = {}
    monkeypatch.setattr(fm, "catalogue_map", lambda *a, **kw: got.update(zip(names, a), **kw))
    spec = fm.MapSpec(("Sh06-Sd015",), "free", "0.3,0.6", 0.9, refine=1, protocol={"tol": 0.05}, settings={"dt": 1e-4},
                      n_voussoirs=6, time_scale=1.0, contact=0.8, law={"Sh06-Sd015": {}}, non_associative=False)
    fm.run(spec, "x.h5", workers=1, resume=True)
    assert set(got) <= set(names) and got["out_path"] == "x.h5" and got["workers"] == 1 and got["resume"] is True
    assert all(got[f.name] == getattr(spec, f.name) for f in dataclasses.fields(spec))
