"""Every output and option is checked before the first simulation: a refusal comes in one line,
under a second, with nothing written; an option that does nothing where it is given is refused."""
import os
import time

import pytest

from dem.cli import main

SINE = ["--sine", "4", "--amplitude", "0.3"]
FRAGILITY = ["fragility", "--block", "0.05", "0.2", "--sine", "4", "--amplitudes", "0.3", "--realizations", "1"]
TILT = ["tilt", "Sh02-Sd020"]


def _refused_at_once(tmp_path, monkeypatch, capsys, argv, msg):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "old.h5").write_bytes(b"old")
    (tmp_path / "old.png").write_bytes(b"old")
    (tmp_path / "dir").mkdir()
    (tmp_path / "zeros.csv").write_text("t [s],a [g]\n" + "\n".join(f"{k * 0.01:.2f},0" for k in range(10000)))
    (tmp_path / "tiny.csv").write_text("t [s],a [g]\n" + "\n".join(f"{k * 0.01:.2f},{3e-10 * (-1) ** k:g}" for k in range(1000)))
    before = sorted((p, p.stat().st_mtime_ns) for p in tmp_path.rglob("*"))
    t0 = time.process_time()  # CPU seconds: on shared cores the wall time measures the neighbours
    assert main(argv) == 2
    cpu = time.process_time() - t0
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and msg in err, err
    assert cpu < 1.0, f"refused after {cpu:.2f} s of computing"
    assert sorted((p, p.stat().st_mtime_ns) for p in tmp_path.rglob("*")) == before


@pytest.mark.parametrize("argv, msg", [
    ([*FRAGILITY, "--out", "old.h5"], "old.h5 exists; a study is never overwritten"),
    ([*FRAGILITY, "--out", "dir"], "not a folder"),
    ([*FRAGILITY, "--out", "/proc/x/s.h5"], "cannot create directory /proc/x"),
    (["map", "--specimens", "Sh02-Sd020", "--out", "old.h5"], "old.h5 exists"),
    (["map", "--specimens", "Sh02-Sd020", "--out", "a" * 250 + ".h5"], "is too long"),
    (["shake", "Sh02-Sd020", *SINE, "--plot", "a" * 300 + ".png"], "is too long"),
    ([*TILT, "--out", "/proc/x"], "cannot create directory /proc/x"),
    ([*TILT, "--out", ""], "--out is empty"),
    (["mesh", "Sh02-Sd020", "--out", ""], "--out is empty"),
    # an empty name would mean no figure at all: the run went on without it
    (["shake", "Sh02-Sd020", *SINE, "--plot", ""], "--plot is empty"),
    (["domain", "Sh02-Sd020", "--engine", "dem", "--freq", "4", "--plot", " "], "--plot is empty"),
    ([*FRAGILITY, "--plot", ""], "--plot is empty"),
    pytest.param(["shake", "Sh02-Sd020", *SINE, "--out", "/sys/x"], "cannot create directory /sys/x",
                 marks=pytest.mark.skipif(not os.path.ismount("/sys"), reason="no sysfs at /sys here: a plain, writable folder")),
    (["shake", "Sh02-Sd020", *SINE, "--plot", "old.png"], "exists"),
    (["rock", "Sh02-Sd020", "--freq", "4", "--amplitude", "0.5", "--plot", "x.txt"], "--plot must end in"),
    (["domain", "Sh02-Sd020", "--plot", "x.txt"], "--plot must end in"),
    (["compare-engines", "--specimens", "Sh02-Sd020", "--plot", "old.png"], "exists"),
    (["calibrate", "--out", "dir"], "dir is a folder; give a file name"),
    (["tilt", "--Sh", "0.6", "--Sd", "0.15", "--Rc", "0.2", "--joints", "table-5.1"], "not an arch by its parameters"),
    # runs that cannot mean anything: an arch that cannot stand, records that move nothing
    (["tilt", "--Sh", "0", "--Sd", "0.03", "--Rc", "0.2"], "cannot stand under its own weight"),
    (["threshold", "--Sh", "0", "--Sd", "0.03", "--Rc", "0.2", "--sine", "4"], "cannot stand under its own weight"),
    (["assess", "--Sh", "0", "--Sd", "0.03", "--Rc", "0.2", "--spectrum", "ec8", "--ag", "0.2"], "cannot stand"),
    (["shake", "Sh02-Sd020", "--record", "zeros.csv", "--pga", "0.4"], "is all zeros"),
    (["shake", "Sh02-Sd020", "--record", "zeros.csv", "--scale", "1"], "is all zeros"),
    (["shake", "Sh02-Sd020", "--record", "tiny.csv", "--scale", "1"], "peaks at 3e-10 g"),
    (["rock", "Sh02-Sd020", "--record", "zeros.csv", "--scale", "1"], "is all zeros"),
])
def test_outputs_and_inputs_checked_before_any_run(tmp_path, monkeypatch, capsys, argv, msg):
    _refused_at_once(tmp_path, monkeypatch, capsys, argv, msg)


@pytest.mark.parametrize("argv, msg", [
    ([*TILT, "--protocol", "ramp", "--start", "lp"], "--start does nothing here"),
    ([*TILT, "--protocol", "ramp", "--full-hold"], "--full-hold does nothing here"),
    # a default given by hand is given: it still does nothing
    ([*TILT, "--protocol", "staircase", "--start", "auto"], "--start does nothing here"),
    (["shake", "Sh02-Sd020", *SINE, "--baseline"], "--baseline goes with --record"),
    (["shake", "Sh02-Sd020", *SINE, "--units", "g"], "--units does nothing here: it is a drawing's length unit (--geometry) or a record's"),
    (["compare-engines", "--engines", "pybullet,pybullet"], "give two different engines"),
    (["rock", "Sh02-Sd020", "--freq", "4", "--amplitude", "0.5", "--duration", "0.3"], "--duration does nothing"),
    (["rock", "Sh02-Sd020", "--input", "A", "--duration", "0.3", "--amplitude", "0.5", "--freq", "4"],
     "--freq does nothing"),
    (["rock", "Sh02-Sd020", "--freq", "4", "--amplitude", "0.5", "--scale", "2"], "--scale does nothing"),
    (["map", "--specimens", "Sh02-Sd020", "--workers", "2", "--scheduler", "tcp://127.0.0.1:9"],
     "--workers does nothing here"),
    (["domain", "Sh02-Sd020", "--mu-joint", "0.5"], "--mu-joint does nothing here"),
    (["domain", "Sh02-Sd020", "--engine", "dem", "--restitution", "0.9"], "--restitution does nothing here"),
    (["modes", "Sh02-Sd020", "--kn", "1e8", "--poisson", "0.2"], "--poisson does nothing here"),
    (["assess", "Sh02-Sd020", "--spectrum", "ec8", "--ag", "0.2", "--engine", "mujoco"], "--engine does nothing"),
    (["assess", "Sh02-Sd020", "--spectrum", "ec8", "--ag", "0.2", "--engine", "lmgc90"], "--engine does nothing"),
    (["assess", "Sh02-Sd020", "--spectrum", "ec8", "--ag", "0.2", "--frp-fibre", "glass"], "--frp-fibre does nothing"),
    (["assess", "Sh02-Sd020", "--spectrum", "ec8", "--ag", "0.2", "--frp-face", "intrados"], "--frp-face does nothing"),
    (["assess", "noh-gumbad", "--frp-exposure", "external"], "--frp-exposure does nothing"),
])
def test_an_option_that_does_nothing_is_refused(tmp_path, monkeypatch, capsys, argv, msg):
    _refused_at_once(tmp_path, monkeypatch, capsys, argv, msg)
