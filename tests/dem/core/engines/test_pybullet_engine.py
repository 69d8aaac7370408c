"""The PyBullet engine's mesh folders: a killed run's folder is removed by the next run."""
from __future__ import annotations

import signal
import subprocess
import sys
from pathlib import Path

from dem.core.engines.pybullet_engine import mesh_dir


def test_the_mesh_folder_of_a_killed_run_is_removed_by_the_next_one(tmp_path, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    import tempfile

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    code = ("import sys, time; from dem.core.engines.pybullet_engine import mesh_dir; "
            "print(mesh_dir(), flush=True); time.sleep(60)")
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    left = Path(p.stdout.readline().strip())
    p.send_signal(signal.SIGKILL)  # no handler runs: the folder stays behind
    p.wait()
    assert left.is_dir() and left.parent == tmp_path
    mine = mesh_dir()
    assert not left.exists() and mine.is_dir() and mine.parent == tmp_path
    other = mesh_dir()  # a live process's folder (this one's) is kept
    assert mine.is_dir() and other.is_dir()
