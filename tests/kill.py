"""Helpers of the tests that SIGKILL a real archdem command: its worker processes, and whether they
are still alive."""
from __future__ import annotations

import os
import signal
import subprocess
import time
from pathlib import Path
from typing import Callable


def children(pid: int) -> list[int]:
    out = subprocess.run(["ps", "-o", "pid=", "--ppid", str(pid)], capture_output=True, text=True).stdout
    return [int(x) for x in out.split()]


def alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as fh:  # a zombie is not alive: it only waits to be reaped
            return fh.read().split(")")[-1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def stored_ok(study: Path) -> dict[str, str]:
    """``{case key: finished time}`` of the cases stored with status ok; empty while the file is
    missing or being written by another process."""
    import h5py

    try:
        with h5py.File(study, "r") as f:
            return {k: str(g.attrs["finished"]) for k, g in f.get("cases", {}).items() if g.attrs.get("status") == "ok"}
    except (OSError, KeyError):
        return {}


def kill_when(proc: subprocess.Popen, ready: Callable[[], bool], workers: int, timeout: float = 120.0) -> list[int]:
    """SIGKILL ``proc`` once it runs ``workers`` worker processes and ``ready()`` holds; wait until
    it is dead and return the pids of its workers at that moment."""
    t0, kids = time.monotonic(), []
    while time.monotonic() - t0 < timeout:
        kids = children(proc.pid)
        if len(kids) >= workers and ready():
            break
        assert proc.poll() is None, "the command ended before it could be killed"
        time.sleep(0.2)
    else:
        raise AssertionError(f"not ready to be killed within {timeout:.0f} s ({len(kids)} workers)")
    kids = children(proc.pid)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    return kids


def outlived(kids: list[int], grace: float = 10.0) -> list[int]:
    """The processes of ``kids`` still alive ``grace`` seconds after their parent was killed
    (the workers poll their parent every second)."""
    t0 = time.monotonic()
    while time.monotonic() - t0 < grace and any(alive(k) for k in kids):
        time.sleep(0.2)
    return [k for k in kids if alive(k)]


def kill_once_stored(args: list[str], study: Path, workers: int) -> list[int]:
    """Run the command ``args``, SIGKILL it once a case is stored in ``study``; its workers' pids."""
    p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        return kill_when(p, lambda: len(stored_ok(study)) >= 1, workers=workers)
    finally:
        if p.poll() is None:
            p.kill()


def stop_at(args: list[str], sig: int, ready: Callable[[], bool], delay: float = 0.0, timeout: float = 120.0,
            log: Path | None = None, group: bool = False) -> tuple[int | None, str, list[int]]:
    """Run the command ``args``; once ``ready()`` holds, wait ``delay`` seconds and send it ``sig`` (to
    its whole process group with ``group``, as a terminal's Ctrl-C and ``timeout`` do). Returns its
    exit code (None: it had ended before the signal), its stderr (kept in ``log``) and the pids of
    its workers at the signal."""
    log = log or Path(os.devnull)
    with open(log, "w") as err:
        # stdin from /dev/null: under pytest-xdist it is otherwise the worker's pipe, which no user's run has
        p = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err,
                             start_new_session=group)
        try:
            t0 = time.monotonic()
            while not ready():
                assert p.poll() is None, "the command ended before it was ready to be stopped"
                assert time.monotonic() - t0 < timeout, f"not ready to be stopped within {timeout:.0f} s"
                time.sleep(0.05)
            time.sleep(delay)
            kids = children(p.pid)
            ended = p.poll() is not None
            if not ended:
                os.killpg(p.pid, sig) if group else p.send_signal(sig)
            code = p.wait(timeout=timeout)
        finally:
            if p.poll() is None:
                p.kill()
    return (None if ended else code), (log.read_text() if log != Path(os.devnull) else ""), kids
