"""``archdem map --resume``: the study's definition comes from its file."""
from __future__ import annotations

import json
import shutil
import time

import h5py
import pytest

from dem.cli import main

# two cheap tilts of one specimen: a map the tests can afford to run three times
MAP = ["map", "--specimens", "Sh02-Sd020", "--mu", "0.4,0.8", "--refine", "0", "--tol", "0.5", "--workers", "1"]


def _answer(capsys) -> list:
    return json.loads(capsys.readouterr().out)


def _interrupted(src, dst) -> None:
    """A copy of a finished map holding its first case only, as an interrupted run leaves it."""
    shutil.copy(src, dst)
    with h5py.File(dst, "a") as f:
        del f["cases"][sorted(f["cases"])[0]]


@pytest.mark.slow  # three maps of two cases
def test_resume_with_and_without_its_arguments_gives_the_uninterrupted_map(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main([*MAP, "--out", "full.h5", "--json"]) == 0
    full = _answer(capsys)
    for name, extra in (("bare.h5", []), ("same.h5", MAP[1:])):
        _interrupted("full.h5", name)
        with h5py.File(name, "r") as f:
            assert len(f["cases"]) == 1
        assert main(["map", "--resume", name, "--json", *extra]) == 0
        resumed = _answer(capsys)
        # the default study (every specimen on the default grid) would hold 140 cases, not 2
        with h5py.File(name, "r") as f:
            assert len(f["cases"]) == 2
        assert [[(p["mu"], p["lambda"], p["mode"]) for p in s["points"]] for s in resumed] == \
               [[(p["mu"], p["lambda"], p["mode"]) for p in s["points"]] for s in full]
        assert [s["mu_star_dem"] for s in resumed] == [s["mu_star_dem"] for s in full]


@pytest.mark.slow  # a map run before the refusals
def test_an_argument_that_disagrees_with_the_study_is_refused_at_once(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main([*MAP, "--mu", "0.4", "--out", "m.h5", "--json"]) == 0
    capsys.readouterr()
    stamp = (tmp_path / "m.h5").stat().st_mtime_ns
    for bad in (["--mu", "0.3:1.2:0.3"], ["--specimens", "all"], ["--config", "free"], ["--mu-base", "0.6"]):
        t0 = time.perf_counter()
        assert main(["map", "--resume", "m.h5", *bad]) == 2
        assert time.perf_counter() - t0 < 1.0
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and f"{bad[0]} {bad[1]} is not the study's" in err
    assert (tmp_path / "m.h5").stat().st_mtime_ns == stamp
    # the default given by hand is an argument too: glued is the study's, so it is taken
    assert main(["map", "--resume", "m.h5", "--config", "glued", "--json"]) == 0
