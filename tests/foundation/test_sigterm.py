"""SIGTERM raised as Ctrl-C is, and pools stopped at once when their work is abandoned."""
from __future__ import annotations

import os
import signal
import time

import pytest

from foundation.processes import Terminated, raise_if_stopped, stop_signals, worker_pool


def test_sigterm_raises_a_keyboard_interrupt_not_lost_and_the_old_handlers_come_back():
    """Raised as Ctrl-C is; dropped once (as where Python cannot propagate it), it is raised again
    before new work starts; the exit code says SIGTERM."""
    before = signal.getsignal(signal.SIGTERM), signal.getsignal(signal.SIGINT)
    with stop_signals() as stop:
        with pytest.raises(Terminated):
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(1.0)  # the handler runs here
        with pytest.raises(Terminated):
            raise_if_stopped()
        assert stop.signum == signal.SIGTERM and stop.exit_code == 143
        os.kill(os.getpid(), signal.SIGTERM)  # a second one is ignored while the first is cleaned up
        time.sleep(0.2)
    raise_if_stopped()  # outside, nothing is remembered
    assert (signal.getsignal(signal.SIGTERM), signal.getsignal(signal.SIGINT)) == before


def test_an_abandoned_pool_is_stopped_not_waited_for():
    """An exception inside the pool (Ctrl-C here) terminates its workers at once instead of running
    the queued work (60 s of it) to the end."""
    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        with worker_pool(2) as ex:
            for _ in range(6):
                ex.submit(time.sleep, 10.0)
            procs = list(ex._processes.values())
            raise KeyboardInterrupt
    assert time.monotonic() - t0 < 8.0
    assert len(procs) == 2 and not any(p.is_alive() for p in procs)
