"""The progress line (dem/core/progress.py): drawn on a terminal only, overwritten in place, cleared at
the end; the engine wrapper that reports simulated time. ``run_on_terminal`` runs a command with its
stderr on a pseudo-terminal, for the commands' tests."""
from __future__ import annotations

import fcntl
import io
import os
import pty
import struct
import subprocess
import sys
import termios

import pytest

from dem.core.progress import TerminalLine, TimedEngine, terminal


class FakeTerminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def run_on_terminal(args: list[str], size: tuple[int, int] | None = (24, 120), timeout: float = 240,
                    module: bool = True) -> tuple[int, str, str]:
    """``(exit code, stdout, stderr)`` of ``python -m dem.cli ARGS`` (``python ARGS`` if not ``module``) with
    stderr on a pseudo-terminal of ``size`` (rows, columns; None: the bare 0 x 0 of a new one), stdout on a pipe."""
    master, slave = pty.openpty()
    if size is not None:
        fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", size[0], size[1], 0, 0))
    p = subprocess.Popen([sys.executable, *(["-m", "dem.cli"] if module else []), *args], stdout=subprocess.PIPE, stderr=slave,
                         stdin=subprocess.DEVNULL)
    os.close(slave)
    chunks = []
    while True:
        try:
            b = os.read(master, 4096)
        except OSError:  # the other end closed: the command ended
            break
        if not b:
            break
        chunks.append(b)
    out = p.stdout.read().decode()
    p.wait(timeout)
    p.stdout.close()
    os.close(master)
    return p.returncode, out, b"".join(chunks).decode(errors="replace")


def test_draws_on_a_terminal_in_place_and_clears_at_the_end():
    s = FakeTerminal()
    with terminal("tilt X", stream=s) as line:
        line(0, None, "static LP")
        line(1, 3, "level 0.1664 held; bracket [0.1664, 0.1696?]")
        line(2, 3, "level 0.1680 collapsed")
    text = s.getvalue()
    assert "tilt X: 0 sims" in text and "tilt X: 1/3 sims" in text and "level 0.1664 held" in text
    assert "\n" not in text and text.count("\r") >= 4  # one line, rewritten
    assert text.endswith("\r") and text.rstrip("\r").split("\r")[-1].strip() == ""  # cleared


def test_a_total_below_done_grows_to_it():
    s = FakeTerminal()
    line = TerminalLine("x", stream=s)
    line(4, 3, "")
    assert "4/4" in s.getvalue()
    line.close()


def test_silent_off_a_terminal_or_when_disabled():
    pipe = io.StringIO()  # not a terminal
    with terminal("x", stream=pipe) as line:
        line(1, 2, "note")
        assert not line.active
    off = FakeTerminal()
    with terminal("x", enabled=False, stream=off) as line:
        line(1, 2, "note")
    assert pipe.getvalue() == "" and off.getvalue() == ""


def test_write_puts_a_message_above_the_line_or_plainly():
    s = FakeTerminal()
    with terminal("x", stream=s) as line:
        line(1, 2, "")
        line.write("case 3 failed")
    assert "case 3 failed\n" in s.getvalue()
    pipe = io.StringIO()
    terminal("x", stream=pipe).write("case 3 failed")
    assert pipe.getvalue() == "case 3 failed\n"


def test_a_bare_pseudo_terminal_gets_a_size():
    # 0 x 0 (a new pseudo-terminal): tqdm alone would draw nothing
    code = "from dem.core.progress import terminal\nwith terminal('x') as line:\n    line(1, 2, 'hello')\n"
    rc, _, err = run_on_terminal(["-c", code], size=None, module=False)
    assert rc == 0 and "x: 1/2 sims" in err and "hello" in err


class _Backend:
    def __init__(self):
        self.steps, self.closed = 0, False

    def step(self, n: int = 1) -> None:
        self.steps += n

    def close(self) -> None:
        self.closed = True


def test_timed_engine_steps_the_backend_and_reports_simulated_time():
    seen = []
    eng = TimedEngine(_Backend(), 0.001, seen.append, every=0.0)
    eng.step(10)
    eng.step(5)
    eng.close()  # anything else is the backend's
    assert eng.steps == 15 and eng.closed
    assert seen == pytest.approx([0.01, 0.015])
    quiet = []
    TimedEngine(_Backend(), 0.001, quiet.append, every=3600).step(10)
    assert quiet == []  # at most every `every` seconds of wall time
