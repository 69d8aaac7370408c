"""Engine cross-check: row arithmetic (identities), one real comparison row against the LP, and
the CLI's input errors."""
import math

import pytest

from dem.experiments.compare_engines.run import ComparisonRow, compare_specimen, summary
from dem.experiments.tilt.check import TiltCheck

pytest.importorskip("mujoco", reason="the mujoco extra is not installed (pip install -e '.[mujoco]')")


def _row(friction, lp, lams, hinges=(("L1", "intrados"),)):
    res = {e: TiltCheck("S", "glued", e, 10.0, 10.0, lam, "rocking", hinges, (), 5, 1.0, lp, hinges) for e, lam in lams.items()}
    return ComparisonRow("S", "glued", friction, 10.0, 10.0, lp, hinges, res, {e: "x" for e in lams})


def test_row_arithmetic_and_summary():
    # definitions: err = (lam - LP)/LP, diff = (second - first)/first, summary = max / mean of |.|
    a = _row("none", 0.5, {"pybullet": 0.49, "mujoco": 0.5025})
    b = _row("none", 0.4, {"pybullet": 0.38, "mujoco": 0.4})
    c = _row("reference", 0.3, {"pybullet": 0.3, "mujoco": 0.27})
    assert a.err_vs_lp("pybullet") == pytest.approx(-0.02)
    assert a.rel_diff == pytest.approx((0.5025 - 0.49) / 0.49)
    s = summary([a, b, c])
    assert s["no_sliding_err_vs_lp"]["pybullet"]["max_abs"] == pytest.approx(0.05)
    assert s["no_sliding_err_vs_lp"]["mujoco"]["mean_abs"] == pytest.approx(0.0025)
    assert s["max_abs_rel_diff"]["reference"] == pytest.approx(0.1)
    d = a.to_dict()
    assert d["engines"]["mujoco"]["hinges_match_lp"] and d["rel_diff"] == pytest.approx(a.rel_diff)
    assert math.isnan(_row("none", 0.5, {"mujoco": 0.5}).rel_diff)


@pytest.mark.slow
def test_compare_specimen_no_sliding_mujoco_against_lp():
    # a real row: MuJoCo at no sliding within 1 % of the exact LP (measured -0.3 %), same hinges
    (row,) = compare_specimen("Sh02-Sd020", "glued", engines=("mujoco",), frictions=("none",))
    assert abs(row.err_vs_lp("mujoco")) <= 0.01
    assert tuple(row.results["mujoco"].hinges) == row.lp_hinges


@pytest.mark.parametrize("argv", [["--engines", "pybullet,nope"], ["--engines", "mujoco"],
                                  ["--specimens", "XX"], ["--workers", "0"]])
def test_cli_bad_input_exits_2(argv, capsys):
    from dem.cli import main

    assert main(["compare-engines", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err


def test_compare_reports_each_specimen(monkeypatch):
    import dem.experiments.compare_engines.run as cr

    monkeypatch.setattr(cr, "_one", lambda job: [job[0]])
    calls = []
    rows = cr.compare(["A", "B"], engines=("pybullet",), progress=lambda *a: calls.append(a))
    assert rows == ["A", "B"]
    assert calls == [(0, 2, "2 tilts each"), (1, 2, "A done"), (2, 2, "B done")]


@pytest.mark.parametrize("kw, msg", [
    ({"engines": "pybullet,nope"}, "unknown engine 'nope'; available: "),
    ({"engines": "mujoco"}, "give two different engines to compare, got 'mujoco'"),
    ({"engines": "pybullet,pybullet"}, "give two different engines to compare, got 'pybullet,pybullet'"),
    ({"friction": "some"}, "friction must be one of both, none, reference, got 'some'"),
    ({"dt": -1.0}, "setting dt must be a positive number, got -1.0"),
])
def test_spec_refuses_as_the_command_does(kw, msg):
    from dem.experiments.compare_engines.run import CompareSpec
    from foundation.errors import ArchdemInputError

    with pytest.raises(ArchdemInputError) as e:
        CompareSpec(**kw)
    assert msg in str(e.value)


def test_spec_runs_compare_and_its_result_prints_the_table(monkeypatch):
    import dem.experiments.compare_engines.run as cr

    seen = {}

    def fake(ids, config, engines, frictions, base, workers, progress):
        seen.update(ids=ids, config=config, engines=engines, frictions=frictions, dt=base.dt, workers=workers)
        return [_row("none", 0.5, {"pybullet": 0.49, "mujoco": 0.5025})]

    monkeypatch.setattr(cr, "compare", fake)
    res = cr.CompareSpec("Sh02-Sd020", "pybullet,mujoco", "none", config="free", dt=2.5e-4).run(workers=2)
    assert seen == {"ids": ["Sh02-Sd020"], "config": "free", "engines": ("pybullet", "mujoco"),
                    "frictions": ("none",), "dt": 2.5e-4, "workers": 2}
    assert res.lines() == [
        "id           friction       LP  pybullet     err    mujoco     err    diff  modes",
        "S            none       0.5000    0.4900  -2.00%    0.5025  +0.50%  +2.55%  rocking/rocking",
        "err = (lambda - LP) / LP (an error at no sliding only); diff = (e2 - e1) / e1"]
    d = res.describe()
    assert list(d) == ["rows", "summary", "config", "dt"] and (d["config"], d["dt"]) == ("free", 2.5e-4)
    assert d["summary"]["no_sliding_err_vs_lp"]["pybullet"]["max_abs"] == pytest.approx(0.02)
    assert cr.CompareSpec().base.dt == cr.Settings().dt and cr.FRICTION_CHOICES[cr.CompareSpec().friction] == (
        "none", "reference")
