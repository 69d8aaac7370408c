"""``archdem threshold``: its progress on a terminal, and none with ``--json`` or off a terminal."""
import json
import subprocess
import sys

import pytest

from tests.dem.core.test_progress import run_on_terminal

# the small arch of the tilt command's tests (3 bodies), a coarse scan and tolerance: 5 runs of about 0.4 s
ARGS = ["threshold", "--Sh", "0.6", "--Sd", "0.25", "--Rc", "0.2", "--voussoirs", "2", "--sine", "4",
        "--scan-ratio", "3", "--tol", "0.3", "--workers", "1"]


@pytest.mark.slow
def test_threshold_shows_progress_on_a_terminal_only():
    rc, out, err = run_on_terminal(ARGS)
    assert rc == 0 and "least collapsing amplitude" in out and ("settled (half step" in out or "range " in out)
    assert "threshold Sh0.6-Sd0.25-Rc0.2 4 Hz: " in err and "runs [" in err
    assert " g survived" in err and " g collapsed; bracket [" in err and "scan 0.7425-3.7124 g" in err
    rc, out, err = run_on_terminal(ARGS + ["--json"])
    assert rc == 0 and json.loads(out)["n_sims"] == 5 and err == ""
    # checked by default: 4 Hz asks the half step only (no LMGC90), every run listed
    v = json.loads(out)["verdict"]
    assert v["checks"] == ["half step"] and v["status"] in ("settled", "range")
    assert {r["check"] for r in v["readings"]} == {"search", "half step"}
    p = subprocess.run([sys.executable, "-m", "dem.cli", *ARGS], capture_output=True, text=True, timeout=240)
    assert p.returncode == 0 and p.stderr == ""
