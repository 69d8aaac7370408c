"""A study stopped at any moment: its file and definition exist before the first case, a command's
own work is kept in it, and a write cut by a SIGKILL leaves a spare copy to resume from."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys

import pytest

from dem.studies.selftest_cases import evaluate
from dem.studies.sweep import (
    load_study,
    lock_path,
    open_study,
    run_study,
    spare_path,
    store_note,
    stored_definition,
    stored_note,
    study_lock,
)
from foundation.errors import ArchdemInputError

pytestmark = pytest.mark.slow  # each test starts a pool of worker processes

CASES = [{"x": x} for x in range(4)]


def _results(study) -> dict:
    return {r.key: (r.status, r.results["y"], list(r.results["series"])) for r in load_study(study)}


def test_the_file_and_its_definition_exist_before_the_first_case(tmp_path):
    study = tmp_path / "s.h5"
    seen = []

    def progress(done, total, note):  # its first call comes before any case is submitted
        seen.append((done, stored_definition(study)))

    run_study(CASES, evaluate, study, workers=1, progress=progress, definition={"n": 4})
    assert seen[0] == (0, {"n": 4}) and not spare_path(study).exists() and not lock_path(study).exists()


def test_work_before_the_cases_is_kept_and_the_lock_held_throughout(tmp_path):
    study = tmp_path / "s.h5"
    with study_lock(study):
        open_study(study, evaluate, {"a": 1}, 7, definition={"n": 4})
        assert stored_definition(study) == {"n": 4} and lock_path(study).exists()
        store_note(study, "reference", {"3 Hz": 0.36, "5 Hz": float("nan")})
        code = "import sys; from dem.studies.sweep import study_lock\nwith study_lock(sys.argv[1]): pass"
        other = subprocess.run([sys.executable, "-c", code, str(study)], capture_output=True, text=True)
        assert other.returncode != 0 and "another archdem process" in other.stderr  # held between the calls
        run_study(CASES, evaluate, study, workers=1, resume=True, study_attrs={"a": 1}, seed=7, progress=False)
    note = stored_note(study, "reference")
    assert note["3 Hz"] == 0.36 and note["5 Hz"] != note["5 Hz"]  # NaN kept
    assert len(load_study(study)) == 4 and not lock_path(study).exists() and not spare_path(study).exists()


def test_a_file_damaged_by_a_cut_write_is_resumed_from_its_spare(tmp_path):
    """As a SIGKILL in the middle of an HDF5 write can leave it: the study file unreadable, its
    spare (written first) whole; the resume takes the spare and ends with every case."""
    study = tmp_path / "s.h5"
    run_study(CASES[:2], evaluate, study, workers=1, progress=False)
    want = _results(study)
    shutil.copyfile(study, spare_path(study))
    with open(study, "r+b") as fh:  # a superblock and root group half written
        fh.seek(64)
        fh.write(os.urandom(512))
    assert stored_definition(study) is None  # read from the spare: no traceback, no refusal
    res = run_study(CASES, evaluate, study, workers=1, resume=True, progress=False)
    assert len(res) == 4 and all(r.ok for r in res)
    assert {k: v for k, v in _results(study).items() if k in want} == want
    assert not spare_path(study).exists()


def test_a_damaged_file_without_a_whole_copy_is_refused_in_one_line(tmp_path):
    study = tmp_path / "s.h5"
    run_study(CASES[:1], evaluate, study, workers=1, progress=False)
    spare_path(study).write_bytes(b"\0" * 100)
    with open(study, "r+b") as fh:
        fh.seek(64)
        fh.write(os.urandom(512))
    with pytest.raises(ArchdemInputError, match="damaged"):
        run_study(CASES, evaluate, study, workers=1, resume=True, progress=False)
