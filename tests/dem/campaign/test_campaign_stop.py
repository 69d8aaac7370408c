"""A campaign stopped by SIGTERM (``timeout``, a service manager) cleans up as after Ctrl-C: no lock,
no half-built step folder, no worker left, one line and exit code 143; its parameters are on disk."""
from __future__ import annotations

import json
import signal
import sys

import pytest

from dem.campaign.runner import LOCK_FILE
from tests.kill import outlived, stop_at


@pytest.mark.slow
def test_a_sigtermed_campaign_leaves_no_lock_and_no_part_folder(tmp_path):
    out = tmp_path / "c"
    args = [sys.executable, "-m", "dem.cli", "campaign", "--quick", "--steps", "tilt", "--workers", "2",
            "--specimens", "Sh02-Sd020,Sh06-Sd020,Sh1-Sd020", "--out", str(out)]
    # to the process group, as `timeout` sends it: the workers get it too
    code, err, kids = stop_at(args, signal.SIGTERM, (out / ".tilt.part").is_dir, delay=1.0, group=True,
                              log=tmp_path / "stderr.txt")
    assert code == 143, err
    lines = err.strip().splitlines()
    assert lines == ["archdem: interrupted"], err
    assert not (out / LOCK_FILE).exists()
    assert not list(out.glob(".*.part")) and not (out / "tilt").exists()
    assert not list(out.glob("studies/.*"))  # the tilt study's lock and spare copy
    assert json.loads((out / "campaign.json").read_text())["parameters"]["quick"] is True
    assert not outlived(kids, grace=5.0), "workers still running 5 s after the SIGTERM"
