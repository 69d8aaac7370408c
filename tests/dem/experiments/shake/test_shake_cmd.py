"""``archdem shake``, ``threshold``, ``animate`` and ``domain --engine dem``: JSON keys, files,
exit 2 on bad input. A small arch (2 voussoirs per side, glued: 3 bodies) keeps these fast."""
import json
from pathlib import Path

import pytest

from dem.cli import main

SMALL = ["--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2"]
DATA = Path(__file__).resolve().parents[3] / "data" / "ground_motions"


def _lp_lambda() -> float:
    """The LP multiplier of SMALL (glued) at the default friction of joints and base."""
    from analytic.limit.limit_discrete import solve_lp
    from dem.core.settings import Settings
    from specimens import PointedArch, discretise

    arch = PointedArch.from_ratios(*(float(SMALL[k + 1]) for k in (0, 2, 4)))
    return solve_lp(discretise(arch, n_voussoirs=2, config="glued"), Settings().mu_joint, Settings().mu_base).lam


def test_bad_input_exit_2(capsys, tmp_path):
    cases = [
        ["shake", "Sh02-Sd020"],  # no input
        ["shake", "Sh02-Sd020", "--sine", "4"],  # no amplitude
        ["shake", "Sh02-Sd020", "--sine", "-4", "--amplitude", "0.5"],
        ["shake", "Sh02-Sd020", "--sine", "4", "--amplitude", "0.5", "--record", "x.AT2"],
        ["shake", "Sh02-Sd020", "--record", str(tmp_path / "missing.AT2")],
        ["shake", "Sh02-Sd020", "--sine", "4", "--amplitude", "0.5", "--mu-joint", "-1"],
        ["threshold", "Sh02-Sd020", "--sine", "0"],
        ["animate", str(tmp_path / "none.h5"), "--out", str(tmp_path / "a.gif")],
    ]
    for c in cases:
        assert main(c) == 2, c
    err = capsys.readouterr().err
    assert err.count("archdem: error") == len(cases)


@pytest.mark.slow
def test_shake_json_and_files(tmp_path, capsys):
    out = tmp_path / "runs"
    rc = main(["shake", *SMALL, "--sine", "4", "--amplitude", "0.3", "--json", "--out", str(out),
               "--plot", str(tmp_path / "h.png"), "--tail", "0.3"])
    assert rc == 0
    cap = capsys.readouterr()
    assert "simulating up to" not in cap.err  # a short run starts without announcing itself
    d = json.loads(cap.out)
    for k in ("collapsed", "t_collapse", "mode", "peak_crown_mm", "residual_crown_mm", "result_file",
              "collapse_phase", "joints"):
        assert k in d
    assert d["pga_g"] == pytest.approx(0.3)
    assert (d["t_collapse"] is None) == (not d["collapsed"])
    assert abs(d["residual_crown_mm"]) <= d["peak_crown_mm"] + 1e-12
    from dem.experiments.shake.file import load_shake

    assert load_shake(d["result_file"])["summary"]["peak_crown_mm"] == pytest.approx(d["peak_crown_mm"])
    assert (tmp_path / "h.png").stat().st_size > 0
    # the run file animates
    assert main(["animate", d["result_file"], "--out", str(tmp_path / "a.gif"), "--frames", "5"]) == 0
    # ... and an output that cannot be made is refused in one line (no library warning), leaving nothing
    capsys.readouterr()
    for bad in (tmp_path / "h.png" / "b.gif", Path("/proc/archdem-none/b.gif")):
        assert main(["animate", d["result_file"], "--out", str(bad), "--frames", "5"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "cannot create directory" in err, err


def test_python_call_gives_the_cli_answer(tmp_path, capsys):
    # dem.shake with ground_motion(sine=F, amplitude=A) takes the CLI's units (Hz, g) and answers the same
    from dem import ShakeProtocol, ground_motion, shake
    from specimens import PointedArch, discretise

    assert main(["shake", *SMALL, "--sine", "4", "--amplitude", "0.3", "--json", "--out", str(tmp_path)]) == 0
    cli = json.loads(capsys.readouterr().out)
    arch = PointedArch.from_ratios(*(float(SMALL[k + 1]) for k in (0, 2, 4)))
    py = shake(discretise(arch, n_voussoirs=2), ground_motion(sine=4, amplitude=0.3), protocol=ShakeProtocol()).summary()
    for k in ("collapsed", "t_collapse", "mode", "peak_crown_mm", "residual_crown_mm", "pga_g"):
        assert py[k] == cli[k], k


def test_shake_record(tmp_path, capsys, monkeypatch):
    """A record run; one longer than ANNOUNCE_SIMULATED_S (lowered here) states its length first."""
    import dem.experiments.shake.spec as spec

    monkeypatch.setattr(spec, "ANNOUNCE_SIMULATED_S", 0.4)
    rec = DATA / "RSN77_SFERN_PUL164.AT2"
    rc = main(["shake", *SMALL, "--record", str(rec), "--pga", "0.2", "--duration", "0.5", "--json",
               "--out", str(tmp_path)])
    assert rc == 0
    cap = capsys.readouterr()
    assert "archdem: simulating up to 0.5 s of motion and tail (4000 steps of 0.000125 s)" in cap.err
    d = json.loads(cap.out)
    assert d["pga_g"] == pytest.approx(0.2) and d["duration"] == pytest.approx(0.5)
    assert d["input"]["kind"] == "record"


@pytest.mark.slow  # one threshold search: 2-4 s
def test_threshold_json(tmp_path, capsys):
    rc = main(["threshold", *SMALL, "--sine", "5", "--json", "--a-max", "3", "--scan-ratio", "1.4",
               "--tol", "0.05", "--workers", "1", "--tail", "0.5", "--no-check"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert d["verdict"]["text"] == "unchecked (not checked)"  # --no-check: the search alone
    assert d["lambda"] == pytest.approx(_lp_lambda(), rel=1e-12)  # the static onset: the LP of the same blocks
    assert d["amplitude_g"] is not None, "no collapse found up to 3 g"
    lo, hi = d["bracket_g"]
    assert hi == d["amplitude_g"] and hi / lo - 1 <= 0.05
    # both ends of the bracket were simulated, with the outcomes that make it a threshold
    outcome = {r["amplitude_g"]: r["collapsed"] for r in d["runs"]}
    assert outcome[hi] and not outcome[lo]
    # physically required: no collapse below the static onset
    assert d["amplitude_g"] >= d["lambda"] * 0.99


@pytest.mark.slow
def test_shake_and_threshold_take_the_effective_contact(tmp_path, capsys):
    from analytic.limit.limit_discrete import solve_lp
    from dem.core.settings import Settings
    from specimens import PointedArch, discretise

    assert main(["shake", *SMALL, "--contact", "0.8", "--sine", "4", "--amplitude", "0.1", "--tail", "0.2",
                 "--json", "--out", str(tmp_path)]) == 0
    assert json.loads(capsys.readouterr().out)["contact"] == 0.8
    assert main(["threshold", *SMALL, "--contact", "0.8", "--sine", "5", "--json", "--a-max", "3",
                 "--scan-ratio", "1.4", "--tol", "0.05", "--workers", "1", "--tail", "0.5"]) == 0
    d = json.loads(capsys.readouterr().out)
    relieved = discretise(PointedArch.from_ratios(0.6, 0.25, 0.2), n_voussoirs=2, config="glued", contact=0.8)
    # the static onset is the LP of the relieved blocks, below the full blocks'
    assert d["contact"] == 0.8 and d["lambda"] == pytest.approx(
        solve_lp(relieved, Settings().mu_joint, Settings().mu_base).lam, rel=1e-12)
    assert d["lambda"] < 0.95 * _lp_lambda()
    assert d["amplitude_g"] is not None and d["amplitude_g"] >= 0.99 * d["lambda"]


@pytest.mark.slow
def test_domain_engine_dem(tmp_path, capsys):
    rc = main(["domain", *SMALL, "--engine", "dem", "--freq", "5", "--json", "--workers", "1",
               "--plot", str(tmp_path / "d.png"), "--amax", "3"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert d["lambda"] == pytest.approx(_lp_lambda(), rel=1e-12)
    assert [p["x"] for p in d["points"]] == [5.0]  # a collapse was found at the one frequency
    assert d["points"][0]["amplitude_g"] >= d["lambda"] * 0.99  # not below the static onset
    assert (tmp_path / "d.png").stat().st_size > 0


@pytest.mark.slow
def test_shake_shows_progress_on_a_terminal_only(tmp_path):
    # the simulated time of the run on a terminal's line; nothing with --json
    from tests.dem.core.test_progress import run_on_terminal

    args = ["shake", "--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2", "--sine", "2", "--amplitude", "0.5",
            "--full", "--tail", "1", "--out", str(tmp_path)]
    rc, out, err = run_on_terminal(args)
    assert rc == 0 and "PGA 0.500 g" in out
    assert "shake Sh0.6-Sd0.25-Rc0.2: " in err and "/1.5 s simulated" in err
    rc, out, err = run_on_terminal(args + ["--json"])
    assert rc == 0 and json.loads(out)["pga_g"] == pytest.approx(0.5) and err == ""
