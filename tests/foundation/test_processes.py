"""Workers end with the process that started them: a SIGKILLed command leaves no process behind,
and its study resumes with nothing lost or repeated."""
import os
import subprocess
import sys

import pytest

from tests.kill import kill_once_stored, outlived, stored_ok

pytestmark = pytest.mark.slow  # every test here simulates, spawns processes or runs a campaign


def test_a_sigkilled_map_leaves_no_worker_and_resumes(tmp_path):
    """A real `archdem map` on 2 workers, SIGKILLed once a case is stored: every worker is gone
    within a few seconds (PARENT_POLL_S is 1 s), and `--resume` runs only what was missing."""
    study = tmp_path / "m.h5"
    args = [sys.executable, "-m", "dem.cli", "map", "--specimens", "Sh02-Sd020", "--mu", "0.3,0.5,0.7,0.9",
            "--refine", "0", "--workers", "2"]
    kids = kill_once_stored(args + ["--out", str(study)], study, workers=2)
    assert not outlived(kids), "workers still running 10 s after the kill"
    before = stored_ok(study)
    assert 1 <= len(before) < 4
    done = subprocess.run(args + ["--resume", str(study)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    after = stored_ok(study)
    assert len(after) == 4
    assert {k: after[k] for k in before} == before  # the cases stored before the kill were not run again


def test_a_closed_reader_of_stdout_is_told_and_stdout_then_goes_nowhere(monkeypatch):
    from foundation.processes import stdout_reader_gone

    r, w = os.pipe()
    with os.fdopen(r, "r") as reader, os.fdopen(w, "w") as out:
        monkeypatch.setattr(sys, "stdout", out)
        assert stdout_reader_gone() is False  # its reader is there
        reader.close()
        assert stdout_reader_gone() is True
        out.write("x")
        out.flush()  # the null device now: no BrokenPipeError
    monkeypatch.setattr(sys, "stdout", None)
    assert stdout_reader_gone() is False  # no file descriptor
