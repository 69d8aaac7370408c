"""``archdem tilt``: JSON keys, result file, exit 2 on bad input."""
import json

import numpy as np
import pytest

from dem.cli import main


def test_bad_input_exit_2(capsys):
    assert main(["tilt", "NOPE"]) == 2
    assert main(["tilt", "Sh02-Sd015", "--mu-joint", "-1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 2 and "archdem: error" in err


@pytest.mark.slow
def test_tilt_json(tmp_path, capsys):
    # a small arch (2 voussoirs per side, glued: 3 bodies) keeps this fast
    out = tmp_path / "runs"
    rc = main(["tilt", "--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2", "--json",
               "--out", str(out), "--plot", str(tmp_path / "f.png")])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    for k in ("lambda", "theta_deg", "mode", "joints", "bracket", "n_sims", "wall_s", "result_file"):
        assert k in d
    assert d["bracket"][0] <= d["lambda"] <= d["bracket"][1]
    assert {"joint", "state"} <= set(d["joints"][0])
    assert (tmp_path / "f.png").stat().st_size > 0
    from dem.experiments.tilt.file import load_result

    assert load_result(d["result_file"]).lam == pytest.approx(d["lambda"])


@pytest.mark.slow
def test_tilt_full_hold_is_stored(tmp_path, capsys):
    # --full-hold switches the hold's rest rule off; the result file says so (rest_after null)
    from dem.experiments.tilt.file import load_result

    args = ["tilt", "--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2", "--json", "--out", str(tmp_path)]
    assert main(args + ["--full-hold"]) == 0
    full = load_result(json.loads(capsys.readouterr().out)["result_file"])
    assert main(args) == 0
    rest = load_result(json.loads(capsys.readouterr().out)["result_file"])
    assert full.protocol.rest_after is None and rest.protocol.rest_after == 0.5
    assert np.isnan(full.stable.t_rest)


@pytest.mark.slow
def test_python_call_gives_the_cli_answer(tmp_path, capsys):
    # the CLI and dem.tilt on the same arch: the same search (LP-started), levels and lambda
    from dem import tilt
    from specimens import PointedArch, discretise

    assert main(["tilt", "--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2", "--json",
                 "--out", str(tmp_path)]) == 0
    cli = json.loads(capsys.readouterr().out)
    py = tilt(discretise(PointedArch.from_ratios(0.6, 0.25, 0.2), n_voussoirs=2))
    assert py.lam == cli["lambda"] and py.n_sims == cli["n_sims"] and list(py.bracket) == cli["bracket"]


SMALL = ["--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2"]


@pytest.mark.slow
def test_contact_is_reported_and_lowers_lambda(tmp_path, capsys):
    assert main(["tilt", *SMALL, "--json", "--out", str(tmp_path)]) == 0
    full = json.loads(capsys.readouterr().out)
    assert main(["tilt", *SMALL, "--contact", "0.7", "--json", "--out", str(tmp_path)]) == 0
    part = json.loads(capsys.readouterr().out)
    assert full["contact"] == 1.0 and part["contact"] == 0.7
    assert part["lambda"] < 0.85 * full["lambda"]


@pytest.mark.slow
def test_ensemble_of_zero_scatter_repeats_the_single_tilt_bit_for_bit(tmp_path, capsys):
    """Zero perturbation reproduces the deterministic run: every realisation gives the tilt test's lambda."""
    assert main(["tilt", *SMALL, "--contact", "0.8", "--json", "--out", str(tmp_path)]) == 0
    single = json.loads(capsys.readouterr().out)
    assert main(["tilt", *SMALL, "--contact", "0.8", "--ensemble", "2", "--seed", "4", "--scatter", "0",
                 "--workers", "1", "--json", "--out", str(tmp_path)]) == 0
    ens = json.loads(capsys.readouterr().out)
    assert ens["lambdas"] == [single["lambda"]] * 2 and ens["lambda_sd"] == 0.0
    assert ens["modes"] == {single["mode"]: 2} and ens["seeds"] == [[4, 0], [4, 1]] and ens["failed"] == []


@pytest.mark.slow
def test_ensemble_realisations_differ_and_are_reproducible(tmp_path, capsys):
    args = ["tilt", *SMALL, "--contact", "0.8", "--ensemble", "3", "--seed", "9", "--scatter", "2",
            "--workers", "2", "--json", "--out", str(tmp_path)]
    assert main(args) == 0
    a = json.loads(capsys.readouterr().out)
    assert main(args) == 0
    b = json.loads(capsys.readouterr().out)
    assert a["lambdas"] == b["lambdas"] and a["result_file"] != b["result_file"]
    assert len(set(a["lambdas"])) > 1 and a["lambda_sd"] > 0


@pytest.mark.parametrize("extra, msg", [
    (["--contact", "0"], "--contact"),
    (["--contact", "1.5"], "--contact"),
    (["--contact", "abc"], "--contact"),
    (["--ensemble", "3"], "--seed"),
    (["--seed", "3"], "--ensemble"),
    (["--ensemble", "3", "--seed", "1"], "--scatter"),
    (["--ensemble", "0", "--seed", "1", "--scatter", "1"], "1 to 10000"),
    (["--ensemble", "3", "--seed", "1", "--scatter", "-1"], "--scatter"),
])
def test_bad_contact_and_ensemble_input_exit_2_in_one_line(tmp_path, capsys, extra, msg):
    assert main(["tilt", *SMALL, "--out", str(tmp_path), *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and msg in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_tilt_shows_progress_on_a_terminal_only(tmp_path):
    # stderr on a pseudo-terminal: the progress line (levels, bracket), cleared before the answer; with
    # --json, or with stderr on a pipe, not a byte of it
    import subprocess
    import sys

    from tests.dem.core.test_progress import run_on_terminal

    # the small arch of test_tilt_json (3 bodies): about 1 s of simulation
    args = ["tilt", "--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2", "--out", str(tmp_path)]
    rc, out, err = run_on_terminal(args)
    assert rc == 0 and "lambda = " in out
    assert "tilt Sh0.6-Sd0.25-Rc0.2: " in err and "/3 sims" in err and "bracket [" in err and "level 0." in err
    assert err.rstrip("\r").rsplit("\r", 1)[-1].strip() == ""  # the line is cleared before the answer
    rc, out, err = run_on_terminal(args + ["--json"])
    assert rc == 0 and json.loads(out)["n_sims"] >= 3 and err == ""
    p = subprocess.run([sys.executable, "-m", "dem.cli", *args], capture_output=True, text=True, timeout=240)
    assert p.returncode == 0 and "sims" not in p.stderr and "\r" not in p.stderr
