"""The engines' shake study: bands and features from runs (hand-made outcomes), the classification
rules, one real case and study through the command line, and its input errors."""
import math

import numpy as np
import pytest

from dem.experiments.compare_engines.shake import (
    AGREE_RATIO,
    STUDY_SPECIMENS,
    bands,
    case_dt,
    class_counts,
    feature_values,
    features,
    study_cases,
)


def _res(first, runs):
    """A case result from (amplitude, collapsed, mode) runs."""
    a, c, m = zip(*runs)
    return {"amplitude_g": first, "run_amplitude_g": np.array(a), "run_collapsed": np.array(c), "run_mode": list(m)}


# survival to 0.7, collapse (rocking) to 0.8, survival to 1.2, collapse (sliding, then rocking) to the top
BANDED = _res(0.7, [(0.5, False, "-"), (0.69, False, "-"), (0.7, True, "rocking"), (0.8, True, "rocking"),
                    (0.9, False, "-"), (1.2, False, "-"), (1.3, True, "sliding"), (1.5, True, "sliding"),
                    (1.7, True, "rocking")])


def test_bands_edges_and_modes():
    bs = bands(BANDED)
    assert [b["collapse"] for b in bs] == [False, True, False, True]
    assert bs[1]["from_g"] == 0.7  # the bisected first collapse is its own edge
    assert bs[2]["from_g"] == pytest.approx(math.sqrt(0.8 * 0.9))  # other edges: geometric middle of the runs
    assert bs[3]["from_g"] == pytest.approx(math.sqrt(1.2 * 1.3)) and bs[3]["to_g"] == 1.7
    assert bs[1]["modes"] == ["rocking"] and bs[3]["modes"] == ["sliding", "rocking"] and bs[2]["modes"] == []
    assert [b["top"] for b in bs] == [False, False, False, True]


def test_feature_values():
    f = feature_values(BANDED)
    assert f["first"] == 0.7 and f["low_bands"] == [[0.7, pytest.approx(math.sqrt(0.72))]]
    assert f["survival_above"] == [[pytest.approx(math.sqrt(0.72)), pytest.approx(math.sqrt(1.56))]]
    assert f["upper_edge"] == pytest.approx(math.sqrt(1.56))
    # nothing collapses: no first threshold, no upper edge
    none = feature_values(_res(math.nan, [(0.5, False, "-"), (1.0, False, "-")]))
    assert math.isnan(none["first"]) and math.isnan(none["upper_edge"]) and none["low_bands"] == []


def test_classification_rules():
    plain = _res(0.7, [(0.69, False, "-"), (0.7, True, "rocking"), (1.7, True, "rocking")])
    # every engine and step has the low band, within one scan step: common
    close = _res(0.75, [(0.5, False, "-"), (0.74, False, "-"), (0.75, True, "rocking"), (0.8, True, "rocking"),
                        (0.9, False, "-"), (1.2, False, "-"), (1.3, True, "rocking"), (1.7, True, "rocking")])
    f = features({("a", 1.0): BANDED, ("b", 1.0): close})
    assert f["first threshold"]["class"] == "common" and f["low collapse band"]["class"] == "common"
    # one engine without the band at its default step but with it at the finer one: step-dependent
    f = features({("a", 1.0): BANDED, ("a", 0.5): BANDED, ("b", 1.0): plain, ("b", 0.5): close})
    assert f["low collapse band"]["class"] == "step-dependent"
    assert math.isnan(f["low collapse band"]["values"]["b@1"])  # absent
    # absent at both steps of one engine: engine-dependent; first thresholds 2x apart: engine-dependent
    far = _res(1.4, [(1.3, False, "-"), (1.4, True, "rocking"), (1.7, True, "rocking")])
    f = features({("a", 1.0): BANDED, ("a", 0.5): BANDED, ("b", 1.0): far, ("b", 0.5): far})
    assert f["low collapse band"]["class"] == "engine-dependent" and f["first threshold"]["class"] == "engine-dependent"
    assert f["upper edge"]["class"] == "common"  # 1.25 and 1.4 g: within one scan step
    assert 1.4 / math.sqrt(1.56) < AGREE_RATIO
    counts = class_counts([{"friction": "none", "features": f}, {"friction": "none", "features": f}])
    assert counts["none"]["first threshold"] == {"engine-dependent": 2}


def test_study_cases_grid():
    cases = study_cases(freqs=(2.0, 6.0), engines=("pybullet", "mujoco"))
    assert len(cases) == len(STUDY_SPECIMENS) * 2 * 2 * 2 * 2
    assert STUDY_SPECIMENS == ("Sh02-Sd015", "Sh02-Sd020", "Sh06-Sd015", "Sh06-Sd020", "Sh1-Sd015", "Sh1-Sd020")
    joints = next(c for c in cases if c["friction"] == "joints" and c["step"] == 0.5)
    assert (joints["mu_joint"], joints["mu_base"], joints["dt"]) == (0.577, 10.0, 2.5e-4)
    # half the step each engine integrates with: PyBullet's dt; MuJoCo's 0.25 ms internal step
    assert {c["engine"]: c["dt"] for c in cases if c["step"] == 0.5} == {"pybullet": 2.5e-4, "mujoco": 1.25e-4}
    assert {c["dt"] for c in cases if c["step"] == 1.0} == {5e-4}
    assert case_dt("lmgc90", 0.5) == 1.25e-4 and case_dt("pybullet", 2.0) == 1e-3


@pytest.mark.slow
def test_cli_one_case_each_engine_and_resume(tmp_path, capsys):
    # a real search: the no-sliding 2 Hz threshold of Sh06-Sd015 lies between its static onset and
    # the four-bar's; PyBullet and MuJoCo within one scan step of each other (measured 0.331 / 0.346 g)
    from dem.cli import main

    pytest.importorskip("mujoco", reason="the mujoco extra is not installed")
    out = tmp_path / "s.h5"
    argv = ["compare-shake", "--specimens", "Sh06-Sd015", "--engines", "pybullet,mujoco", "--freq", "2",
            "--steps", "1", "--friction", "none", "--workers", "2", "--out", str(out), "--json"]
    assert main(argv) == 0
    import json

    res = json.loads(capsys.readouterr().out)
    firsts = {c["engine"]: c["first_g"] for c in res["cases"]}
    lam = res["cases"][0]["lambda"]
    assert all(lam < a < 0.45 for a in firsts.values())
    (group,) = res["features"]
    assert group["features"]["first threshold"]["class"] == "common"
    assert res["pairwise"]["1"]["mujoco/pybullet"]["first threshold"] == [1, 1] and res["step_agreement"] == {}
    # the settled-or-range flag needs MuJoCo at its shakes' step (x0.5): not run here
    assert [(v["status"], v["why"]) for v in res["verdicts"]] == [("unchecked", "no mujoco x0.5 reading")]
    assert (tmp_path / "s.csv").read_text().count("\n") == 3
    # the study is never overwritten; a resume runs nothing new and reads the same
    assert main(argv) == 2
    assert main(["compare-shake", "--resume", str(out), "--json"]) == 0
    again = json.loads(capsys.readouterr().out)
    assert {c["engine"]: c["first_g"] for c in again["cases"]} == firsts


@pytest.mark.parametrize("argv", [["--engines", "pybullet,nope"], ["--engines", "pybullet,pybullet"],
                                  ["--friction", "some"], ["--steps", "0"], ["--freq", "-2"],
                                  ["--specimens", "XX"], ["--workers", "0"]])
def test_cli_bad_input_exits_2(argv, capsys, tmp_path):
    from dem.cli import main

    assert main(["compare-shake", *argv, "--out", str(tmp_path / "x.h5")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("stop, code, why", [(KeyboardInterrupt, 130, "interrupted;"),
                                              (None, 2, "study interrupted: a worker died;")])
def test_cli_stopped_study_names_its_resume(stop, code, why, tmp_path, monkeypatch, capsys):
    # a study that stops early (Ctrl-C, or a dead worker) says in one line how to continue it
    from dem.cli import main
    from dem.studies.sweep import StudyInterrupted

    def stopped(*_a, **_k):
        raise stop() if stop else StudyInterrupted("a worker died")

    monkeypatch.setattr("dem.studies.sweep.run_study", stopped)
    out = tmp_path / "s.h5"
    assert main(["compare-shake", "--specimens", "Sh06-Sd015", "--engines", "pybullet", "--out", str(out)]) == code
    (line,) = capsys.readouterr().err.splitlines()
    assert line == f"archdem: {why} finished cases are stored, continue with --resume {out}"


def test_pairwise_and_step_agreement():
    from dem.experiments.compare_engines.shake import pairwise, step_agreement
    from dem.studies.sweep import CaseRecord

    far = _res(1.4, [(1.3, False, "-"), (1.4, True, "rocking"), (1.7, True, "rocking")])

    def rec(engine, step, freq, res):
        p = {"id": "S", "friction": "none", "freq": freq, "engine": engine, "step": step}
        return CaseRecord(f"{engine}{step}{freq}", p, "ok", res)

    records = [rec("a", 1.0, 2.0, BANDED), rec("b", 1.0, 2.0, BANDED), rec("c", 1.0, 2.0, far),
               rec("a", 1.0, 4.0, BANDED), rec("b", 1.0, 4.0, far),
               rec("a", 0.5, 2.0, BANDED), rec("c", 0.5, 2.0, BANDED), rec("b", 0.5, 4.0, far)]
    pw = pairwise(records)
    assert pw["a/b"]["first threshold"] == [1, 2] and pw["a/c"]["first threshold"] == [0, 1]
    assert pw["a/b"]["upper edge"] == [2, 2]  # 1.25 and 1.4 g: one scan step apart
    sa = step_agreement(records)
    assert sa["a"]["first threshold"] == [1, 1] and sa["c"]["first threshold"] == [0, 1] and sa["b"]["upper edge"] == [1, 1]
    assert pairwise(records, 0.5)["a/c"]["low collapse band"] == [1, 1]


def test_step_agreement_of_two_steps_and_the_groups_that_move():
    from dem.experiments.compare_engines.shake import step_agreement, step_moves
    from dem.studies.sweep import CaseRecord

    far = _res(1.4, [(1.3, False, "-"), (1.4, True, "rocking"), (1.7, True, "rocking")])
    near = _res(0.72, [(0.6, False, "-"), (0.72, True, "rocking"), (1.7, True, "rocking")])

    def rec(engine, step, freq, res):
        p = {"id": "S", "friction": "joints", "freq": freq, "engine": engine, "step": step}
        return CaseRecord(f"{engine}{step}{freq}", p, "ok", res)

    # engine a: 0.7 g at x1 and x0.5, 1.4 g at x0.25 (moves on the finer pair only); b: one step each
    records = [rec("a", 1.0, 6.0, BANDED), rec("a", 0.5, 6.0, near), rec("a", 0.25, 6.0, far),
               rec("b", 1.0, 6.0, far), rec("b", 1.0, 2.0, far), rec("a", 1.0, 2.0, far), rec("a", 0.5, 2.0, far)]
    assert step_agreement(records, (1.0, 0.5))["a"]["first threshold"] == [2, 2]
    assert step_agreement(records, (0.5, 0.25))["a"]["first threshold"] == [0, 1]
    assert step_agreement(records)["a"]["first threshold"] == [1, 2]  # every step of the engine at once
    (m,) = step_moves(records)
    assert (m["freq"], m["moved"]) == (6.0, ["a"])
    assert m["values"][("a", 0.25)] == 1.4 and m["values"][("b", 1.0)] == 1.4 and len(m["values"]) == 4
    assert step_moves(records, engines=("b",)) == []


def test_the_settled_or_range_flag_of_a_small_synthetic_study():
    """The thresholds' check rule on a study's readings: the default (MuJoCo x0.5) against MuJoCo at half
    its step and, at 6 Hz with the joints free to slide, LMGC90 at its default step."""
    from dem.experiments.compare_engines.shake import default_step, group_verdict, verdict_counts, verdicts
    from dem.studies.sweep import CaseRecord

    assert default_step("mujoco") == 0.5  # 0.125 ms, the shakes' default step
    far = _res(1.4, [(1.3, False, "-"), (1.4, True, "rocking"), (1.7, True, "rocking")])
    near = _res(0.72, [(0.6, False, "-"), (0.72, True, "rocking"), (1.7, True, "rocking")])
    none = _res(math.nan, [(0.5, False, "-"), (1.7, False, "-")])

    def rec(sid, friction, freq, engine, step, res):
        p = {"id": sid, "friction": friction, "freq": freq, "engine": engine, "step": step}
        return CaseRecord(f"{sid}{friction}{engine}{step}{freq}", p, "ok", res)

    records = [
        # 6 Hz, joints: the half step agrees (0.70 / 0.72: 3 %), LMGC90 stands to the top -> a range open above
        rec("A", "joints", 6.0, "mujoco", 0.5, BANDED), rec("A", "joints", 6.0, "mujoco", 0.25, near),
        rec("A", "joints", 6.0, "lmgc90", 1.0, none),
        # 2 Hz, joints: the half step only (outside the band), alike -> settled, LMGC90 not needed
        rec("A", "joints", 2.0, "mujoco", 0.5, far), rec("A", "joints", 2.0, "mujoco", 0.25, far),
        # 6 Hz, no sliding: the half step only, which moves 2x -> range [0.7, 1.4]
        rec("A", "none", 6.0, "mujoco", 0.5, BANDED), rec("A", "none", 6.0, "mujoco", 0.25, far),
        rec("A", "none", 6.0, "lmgc90", 1.0, BANDED),
        # 8 Hz, joints, no LMGC90 reading: never settled
        rec("A", "joints", 8.0, "mujoco", 0.5, far), rec("A", "joints", 8.0, "mujoco", 0.25, far),
    ]
    v = {(r["friction"], r["freq"]): r for r in verdicts(records)}
    assert v[("joints", 6.0)]["status"] == "range" and v[("joints", 6.0)]["range_g"] == [0.7, None]
    assert v[("joints", 6.0)]["why"] == "lmgc90 reads otherwise"
    assert v[("joints", 2.0)]["status"] == "settled" and set(v[("joints", 2.0)]["readings"]) == {"mujoco@0.5",
                                                                                               "mujoco@0.25"}
    assert v[("none", 6.0)]["status"] == "range" and v[("none", 6.0)]["range_g"] == [0.7, 1.4]
    assert v[("joints", 8.0)]["status"] == "unchecked" and "lmgc90 x1" in v[("joints", 8.0)]["why"]
    assert verdict_counts(list(v.values())) == {"joints": {"range": 1, "settled": 1, "unchecked": 1},
                                                "none": {"range": 1}}
    # the margin: 5 % above the default reads alike, 8 % does not; none against none is alike
    assert group_verdict({("mujoco", 0.5): 1.0, ("mujoco", 0.25): 1.05}, 2.0, 0.577, 10.0)["status"] == "settled"
    assert group_verdict({("mujoco", 0.5): 1.0, ("mujoco", 0.25): 1.08}, 2.0, 0.577, 10.0)["status"] == "range"
    assert group_verdict({("mujoco", 0.5): math.nan, ("mujoco", 0.25): math.nan}, 2.0, 10.0, 10.0)["status"] == "settled"
    # the command's text and JSON of such a study (ShakeStudy): a line per verdict, its range, the failed cases
    from dem.experiments.compare_engines.shake import ShakeStudy, classify, step_agreement

    study = ShakeStudy("s.h5", "s.csv", 11, [], classify(records), {"1": {"a/b": {"first threshold": [1, 2]}}},
                       step_agreement(records), verdicts(records), ["A pybullet 2 Hz: boom"])
    assert study.lines() == [
        "0 of 11 cases -> s.h5 (table: s.csv)",
        "joints: first threshold 1 engine-dependent; low collapse band 1 step-dependent; survival band above 1 "
        "step-dependent; upper edge 1 engine-dependent",
        "none: first threshold 1 engine-dependent; low collapse band 1 engine-dependent; survival band above 1 "
        "engine-dependent; upper edge 1 common",
        "x1 a/b agree: first threshold 1/2",
        "mujoco at its steps agrees: first threshold 3/4, low collapse band 2/4, upper edge 3/4",
        "A           joints    6 Hz default threshold range 0.700-none g (lmgc90 reads otherwise)",
        "A           joints    2 Hz default threshold settled",
        "A           none      6 Hz default threshold range 0.700-1.400 g (half step reads otherwise)",
        "A           joints    8 Hz default threshold unchecked (no lmgc90 x1 reading)",
        "failed: A pybullet 2 Hz: boom"]
    d = study.describe()
    assert d["verdict_counts"] == {"joints": {"range": 1, "settled": 1, "unchecked": 1}, "none": {"range": 1}}
    assert list(d) == ["study", "csv", "cases", "features", "counts", "pairwise", "step_agreement", "verdicts",
                       "verdict_counts", "failed"]


@pytest.mark.parametrize("kw, msg", [
    ({"engines": "pybullet,nope"}, "--engines: unknown 'nope'; one of "),
    ({"friction": "none,none"}, "--friction: give distinct names separated by commas, got 'none,none'"),
    ({"steps": "5"}, "a time step factor must be in (0, 4], got 5.0"),
    ({"freq": "60"}, "--freq: one-cycle sines from above 0 to 50 Hz, got '60'"),
    ({"specimens": "XX"}, "unknown specimen 'XX'"),
])
def test_the_study_spec_refuses_as_the_command_does(kw, msg):
    from dem.experiments.compare_engines.shake import ShakeStudySpec
    from foundation.errors import ArchdemInputError

    with pytest.raises(ArchdemInputError) as e:
        ShakeStudySpec(**kw)
    assert msg in str(e.value)


def test_the_study_spec_cases():
    from dem.experiments.compare_engines.shake import ShakeStudySpec

    spec = ShakeStudySpec("Sh06-Sd015", "pybullet", "2,4", "1", "none", config="free")
    assert spec.cases == study_cases(["Sh06-Sd015"], [2.0, 4.0], ("pybullet",), [1.0], ("none",), "free")
    assert len(ShakeStudySpec().cases) == len(study_cases())  # its defaults are the study's
