"""Progress of long work: the callback every long call takes, and the one terminal line that draws it.

A long call (:func:`dem.experiments.tilt.run.tilt`, :func:`dem.experiments.shake.thresholds.threshold`
and ``failure_domain``, :func:`dem.experiments.shake.run.shake`, a study of :mod:`dem.studies.sweep`)
takes ``progress``, a :data:`Progress` callable::

    progress(done, total, note)

called as the work advances: ``done`` units finished so far (simulations, frequencies, cases, or
simulated seconds of one run), ``total`` the number expected (None while unknown; an estimate may grow,
never below ``done``), ``note`` a few words on what is happening now (the level just run and the
bracket, the amplitude). It must be quick and must not raise.

:func:`terminal` is the line every command draws from it: a tqdm bar on stderr, overwritten in place,
with the elapsed time and, when ``total`` is known, the time left; it draws nothing (and costs
nothing) when disabled (``--json``) or when stderr is not a terminal (a pipe, a file, a log).
"""
from __future__ import annotations

import io
import os
import sys
import time
from typing import Callable, TextIO

#: ``progress(done, total, note)``: see the module docstring.
Progress = Callable[[float, "float | None", str], None]

#: The line's layout: what, how far, elapsed < left, the note.
BAR_FORMAT = "{desc}: {n_fmt}/{total_fmt} {unit} [{elapsed}<{remaining}]{postfix}"
BAR_FORMAT_OPEN = "{desc}: {n_fmt} {unit} [{elapsed}]{postfix}"  # no total known yet

#: Width of the line on a terminal that gives none.
WIDTH = 100


def _columns(stream: TextIO) -> int:
    try:
        size = os.get_terminal_size(stream.fileno())
        return size.columns if size.lines > 0 else 0
    except (AttributeError, ValueError, OSError, io.UnsupportedOperation):
        return 0


def is_terminal(stream: TextIO | None = None) -> bool:
    """True if ``stream`` (default: stderr) is a terminal."""
    stream = sys.stderr if stream is None else stream
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):  # no isatty, or a closed stream
        return False


class TerminalLine:
    """One progress line on ``stream`` (default stderr), a :data:`Progress` callable; see :func:`terminal`."""

    def __init__(self, desc: str, unit: str = "sims", enabled: bool = True, stream: TextIO | None = None):
        self.desc, self.unit = desc, unit
        self.stream = sys.stderr if stream is None else stream
        self.active = bool(enabled) and is_terminal(self.stream)
        self._bar = None

    def __call__(self, done: float, total: float | None = None, note: str = "") -> None:
        if not self.active:
            return
        if self._bar is None:
            # deferred: `archdem --help` imports this module, not tqdm (docs/architecture.md#imports)
            from tqdm import tqdm

            # a terminal that gives no size (a bare pseudo-terminal: 0 x 0, on which tqdm draws nothing) gets one
            sized = _columns(self.stream) > 0
            self._bar = tqdm(total=None, desc=self.desc, unit=self.unit, file=self.stream, dynamic_ncols=sized,
                             ncols=None if sized else WIDTH, nrows=None if sized else 24, leave=False,
                             bar_format=BAR_FORMAT_OPEN, mininterval=0.2)
        bar = self._bar
        if total is not None and bar.total != max(total, done):
            bar.total = max(total, done)
            bar.bar_format = BAR_FORMAT
        bar.n = done
        bar.set_postfix_str(note, refresh=False)
        bar.refresh()

    def write(self, message: str) -> None:
        """Print ``message`` on its own line above the progress line (or plainly on the stream)."""
        if self._bar is not None:
            self._bar.write(message, file=self.stream)
        else:
            print(message, file=self.stream)

    def close(self) -> None:
        """Clear the line (the answer printed next stands alone)."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None

    def __enter__(self) -> "TerminalLine":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def terminal(desc: str, unit: str = "sims", enabled: bool = True, stream: TextIO | None = None) -> TerminalLine:
    """The progress line of a command: ``with terminal("tilt Sh06-Sd010", enabled=not args.json) as line:
    tilt(..., progress=line)``. Draws only when ``enabled`` and ``stream`` (stderr) is a terminal."""
    return TerminalLine(desc, unit, enabled, stream)


class TimedEngine:
    """An engine backend that reports the simulated time as it steps: ``simulate(..., engine=TimedEngine(
    get_engine(name), dt, on_time))`` calls ``on_time(t)`` [s] at most every ``every`` [s] of wall time.
    Everything else is the backend's own (the run is the same, step for step)."""

    def __init__(self, engine, dt: float, on_time: Callable[[float], None], every: float = 0.25):
        self._engine, self._dt, self._on_time, self._every = engine, float(dt), on_time, float(every)
        self._steps, self._last = 0, time.monotonic()

    def step(self, n: int = 1) -> None:
        self._engine.step(n)
        self._steps += n
        now = time.monotonic()
        if now - self._last >= self._every:
            self._last = now
            self._on_time(self._steps * self._dt)

    def __getattr__(self, name):
        return getattr(self._engine, name)


__all__ = ["Progress", "TerminalLine", "TimedEngine", "terminal", "is_terminal"]
