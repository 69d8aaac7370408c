"""``archdem shake``, ``threshold``, ``animate`` and ``domain --engine dem``: JSON keys, files,
exit 2 on bad input. A small arch (2 voussoirs per side, glued: 3 bodies) keeps these fast."""
import json
from pathlib import Path

import pytest

from dem.cli import main

SMALL = ["--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2"]
DATA = Path(__file__).resolve().parents[2] / "data" / "ground_motions"


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


def test_shake_json_and_files(tmp_path, capsys):
    out = tmp_path / "runs"
    rc = main(["shake", *SMALL, "--sine", "4", "--amplitude", "0.3", "--json", "--out", str(out),
               "--plot", str(tmp_path / "h.png"), "--tail", "0.3"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    for k in ("collapsed", "t_collapse", "mode", "peak_crown_mm", "residual_crown_mm", "result_file",
              "collapse_phase", "joints"):
        assert k in d
    assert d["pga_g"] == pytest.approx(0.3)
    assert (d["t_collapse"] is None) == (not d["collapsed"])
    assert abs(d["residual_crown_mm"]) <= d["peak_crown_mm"] + 1e-12
    from dem.formats.shake import load_shake

    assert load_shake(d["result_file"])["summary"]["peak_crown_mm"] == pytest.approx(d["peak_crown_mm"])
    assert (tmp_path / "h.png").stat().st_size > 0
    # the run file animates
    assert main(["animate", d["result_file"], "--out", str(tmp_path / "a.gif"), "--frames", "5"]) == 0


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


def test_shake_record(tmp_path, capsys):
    rec = DATA / "RSN77_SFERN_PUL164.AT2"
    rc = main(["shake", *SMALL, "--record", str(rec), "--pga", "0.2", "--duration", "0.5", "--json",
               "--out", str(tmp_path)])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert d["pga_g"] == pytest.approx(0.2) and d["duration"] == pytest.approx(0.5)
    assert d["input"]["kind"] == "record"


def test_threshold_json(tmp_path, capsys):
    rc = main(["threshold", *SMALL, "--sine", "5", "--json", "--a-max", "1.2", "--scan-ratio", "1.4",
               "--tol", "0.05", "--workers", "1", "--tail", "0.5"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert "amplitude_g" in d and "bands" in d
    if d["amplitude_g"] is not None:
        lo, hi = d["bracket_g"]
        assert hi == d["amplitude_g"] and hi / lo - 1 <= 0.05
        # physically required: no collapse below the static onset
        assert d["amplitude_g"] >= d["lambda"] * 0.99


def test_domain_engine_dem(tmp_path, capsys):
    rc = main(["domain", *SMALL, "--engine", "dem", "--freq", "5", "--json", "--workers", "1",
               "--plot", str(tmp_path / "d.png"), "--amax", "3"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert "points" in d and "bands" in d
    assert all(p["amplitude_g"] >= d["lambda"] * 0.99 for p in d["points"])
    assert (tmp_path / "d.png").stat().st_size > 0
