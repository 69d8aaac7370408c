"""``archdem fragility``: sine stripes and a record suite, the JSON answer, the tables, resume."""
import json
import shutil

import h5py
import pytest

from dem.cli import main

BLOCK = ["--block", "0.05", "0.2", "--planar", "--mu-base", "10"]  # a block has no joint: no --mu-joint


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.slow
def test_sine_stripes_json_tables_and_resume(tmp_path, capsys):
    study = tmp_path / "f.h5"
    argv = ["fragility", *BLOCK, "--sine", "2", "--amplitudes", "0.29,0.31,0.33", "--realizations", "3",
            "--workers", "2", "--json"]
    d = _json(capsys, [*argv, "--out", str(study)])
    for key in ("points", "fit", "deterministic_threshold", "n_runs", "wall_s", "result_file"):
        assert key in d
    assert d["n_runs"] == 9 and [p["intensity"] for p in d["points"]] == [0.29, 0.31, 0.33]
    assert set(d["points"][0]) >= {"intensity", "n_runs", "n_collapsed", "p", "ci_low", "ci_high"}
    assert d["points"][0]["n_collapsed"] == 0 and d["points"][-1]["n_collapsed"] == 3
    assert 0.29 < d["deterministic_threshold"] < 0.33
    rows = (tmp_path / "f-stripes.csv").read_text().splitlines()
    assert len(rows) == 4 and (tmp_path / "f-fits.csv").exists()
    again = _json(capsys, [*argv, "--resume", str(study)])  # nothing left to run: the same answer
    assert again["points"] == d["points"]
    # interrupted (one run missing) and resumed with the file alone: the study it holds, not a default
    cut = tmp_path / "cut.h5"
    shutil.copy(study, cut)
    with h5py.File(cut, "a") as f:
        del f["cases"][sorted(f["cases"])[0]]
    bare = _json(capsys, ["fragility", "--resume", str(cut), "--json"])
    assert bare["points"] == d["points"] and bare["deterministic_threshold"] == d["deterministic_threshold"]
    assert main(["fragility", "--resume", str(cut), "--realizations", "2"]) == 2
    assert "--realizations 2 is not the study's" in capsys.readouterr().err


@pytest.mark.slow
def test_a_record_suite_in_stripes_of_pga_and_sa(tmp_path, short_records, capsys):
    files = short_records
    for im in ("pga", "sa:0.4"):
        d = _json(capsys, ["fragility", *BLOCK, "--records", *files, "--im", im, "--stripes", "0.1,0.8",
                           "--realizations", "2", "--workers", "2", "--out", str(tmp_path / f"{im[:2]}.h5"), "--json"])
        assert [p["n_runs"] for p in d["points"]] == [4, 4] and d["deterministic_threshold"] is None
        assert d["points"][0]["n_collapsed"] == 0  # a tenth of a g does not lift a b/h = 0.25 block


@pytest.mark.parametrize("extra, msg", [
    (["--sine", "2", "--amplitudes", "0.3", "--realizations", "0"], "realisations must be a whole number from 1"),
    (["--sine", "2", "--realizations", "3"], "--sine goes with --amplitudes"),
    (["--records", "nope.AT2", "--im", "pga", "--stripes", "0.1", "--realizations", "2"], "nope.AT2: no such file"),
    (["--records", "nope.AT2", "--im", "sa:-1", "--stripes", "0.1", "--realizations", "2"], "--im sa:T needs a period"),
    (["--sine", "2", "--amplitudes", "0.3", "--realizations", "2", "--scheduler", "tcp://127.0.0.1:9"],
     "cannot connect to the Dask scheduler"),
    (["--sine", "2", "--amplitudes", "0.3", "--realizations", "2", "--edge-loss-sd", "0.2"], "a block takes --size-sd"),
    (["--sine", "2", "--amplitudes", "0.3", "--realizations", "2", "--friction-cov", "2"],
     "friction coefficient of variation"),
    (["--sine", "2", "--amplitudes", "0.3,0.3", "--realizations", "2"], "--amplitudes repeats a value"),
])
def test_bad_input_is_one_line(tmp_path, monkeypatch, capsys, extra, msg):
    monkeypatch.chdir(tmp_path)
    assert main(["fragility", *BLOCK, *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and msg in err
    assert list(tmp_path.rglob("*")) == []
