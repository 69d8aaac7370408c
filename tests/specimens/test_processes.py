"""Workers end with the process that started them: a SIGKILLed command leaves no process behind."""
import os
import signal
import subprocess
import sys
import time


def _children(pid: int) -> list[int]:
    out = subprocess.run(["ps", "-o", "pid=", "--ppid", str(pid)], capture_output=True, text=True).stdout
    return [int(x) for x in out.split()]


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as fh:  # a zombie is not alive: it only waits to be reaped
            return fh.read().split(")")[-1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def test_a_sigkilled_map_leaves_no_worker(tmp_path):
    """A real `archdem map` on 2 workers, killed with SIGKILL once its workers run: every worker
    is gone within a few seconds (PARENT_POLL_S is 1 s)."""
    p = subprocess.Popen([sys.executable, "-m", "dem.cli", "map", "--specimens", "Sh02-Sd020", "--mu", "0.3,0.6,0.9",
                          "--refine", "0", "--workers", "2", "--out", str(tmp_path / "m.h5")],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        t0, kids = time.monotonic(), []
        while time.monotonic() - t0 < 60 and len(kids) < 2:
            time.sleep(0.2)
            kids = _children(p.pid)
        assert len(kids) >= 2, "the map started no workers"
        time.sleep(1.0)  # the workers have run their initialiser
        os.kill(p.pid, signal.SIGKILL)
        p.wait()
        t0 = time.monotonic()
        while time.monotonic() - t0 < 10 and any(_alive(k) for k in kids):
            time.sleep(0.2)
        assert not any(_alive(k) for k in kids), f"workers still running {time.monotonic() - t0:.1f} s after the kill"
    finally:
        if p.poll() is None:
            p.kill()
