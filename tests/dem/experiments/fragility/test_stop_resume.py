"""A fragility study stopped at any moment — Ctrl-C, SIGTERM, SIGKILL — leaves a study file that
``--resume`` continues to the uninterrupted result: the same case outputs and the same curves."""
from __future__ import annotations

import json
import random
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from dem.studies.sweep import load_study, lock_path, stored_definition
from tests.kill import outlived, stop_at, stored_ok

#: A small study that takes every path of the issue's one (the nominal thresholds before the
#: realisations, two workers): one frequency, two amplitudes around its threshold, three realisations.
ARGS = ["fragility", "--block", "0.05", "0.2", "--sine", "5", "--amplitudes", "0.8,0.9", "--realizations", "3",
        "--seed", "3", "--workers", "2", "--json"]
#: What differs between two runs of one study: when and how long, and where.
VOLATILE = {"wall_s", "result_file", "csv"}


def _archdem(*args: str) -> list[str]:
    return [sys.executable, "-m", "dem.cli", *args]


def _curves(stdout: str) -> dict:
    return {k: v for k, v in json.loads(stdout).items() if k not in VOLATILE}


def _cases(study: Path) -> dict:
    return {r.key: (r.status, {k: v for k, v in r.results.items() if k not in VOLATILE}) for r in load_study(study)}


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The uninterrupted study: its curves and its case outputs."""
    study = tmp_path_factory.mktemp("reference") / "ref.h5"
    done = subprocess.run(_archdem(*ARGS, "--out", str(study)), capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return _curves(done.stdout), _cases(study)


@pytest.mark.slow
@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM, signal.SIGKILL], ids=lambda s: s.name)
def test_a_stopped_study_resumes_to_the_uninterrupted_result(reference, tmp_path, sig):
    """Stopped at a random instant — the Ctrl-C as soon as the file appears (in the nominal
    thresholds), SIGTERM once 0 to 3 of the 6 cases are stored, SIGKILL once 1 to 3 are, each up to
    0.5 s later — the study file is there with its definition; SIGINT and SIGTERM end in one line
    (130, 143) without a traceback, a leaked semaphore or the lock; no worker outlives the stop;
    ``--resume FILE`` alone then gives the reference's curves and case outputs."""
    curves, cases = reference
    study = tmp_path / "s.h5"
    seed = random.randrange(10**6)
    rng = random.Random(seed)
    stored = 0 if sig == signal.SIGINT else rng.randint(0 if sig == signal.SIGTERM else 1, 3)
    delay = 0.0 if sig == signal.SIGINT else rng.uniform(0.0, 0.5)

    def ready() -> bool:
        return study.exists() and (stored == 0 or len(stored_ok(study)) >= stored)

    # Ctrl-C and SIGTERM to the process group, as a terminal and `timeout` send them: the workers too
    code, err, kids = stop_at(_archdem(*ARGS, "--out", str(study)), sig, ready, delay=delay,
                              log=tmp_path / "stderr.txt", group=sig != signal.SIGKILL)
    why = f"{sig.name} {delay:.1f} s after {stored} cases were stored (seed {seed})"
    assert code is not None, f"the study had ended before the {why}"
    assert stored_definition(study)["realizations"] == 3, why
    if sig == signal.SIGKILL:
        assert code == -signal.SIGKILL
        assert not outlived(kids), f"workers still running 10 s after the {why}"
    else:
        assert code == 128 + sig, (why, err)
        lines = err.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("archdem: interrupted"), (why, err)
        assert not lock_path(study).exists(), why
        assert not outlived(kids, grace=5.0), f"workers still running 5 s after the {why}"
    done = subprocess.run(_archdem("fragility", "--resume", str(study), "--json"), capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, (why, done.stderr)
    assert _curves(done.stdout) == curves, why
    assert _cases(study) == cases, why
    assert not lock_path(study).exists()


def test_resume_names_a_missing_file_or_one_that_is_no_study(tmp_path, capsys):
    """``--resume`` of a file that is not there, or not a study, is refused in one line that says
    so — not by asking for the options such a study would have held."""
    from dem.cli import main

    not_hdf5 = tmp_path / "notes.h5"
    not_hdf5.write_text("not a study")
    for path, says in ((tmp_path / "missing.h5", "no such study file"), (not_hdf5, "not a readable HDF5 study file")):
        assert main(["fragility", "--resume", str(path)]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and says in err[0], err
