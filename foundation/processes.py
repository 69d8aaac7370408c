"""Worker processes that end with the process that started them (the pools of every sweep), the
program's stop on SIGTERM, handled as Ctrl-C is (docs/decisions/010-input-rules.md#interruption), and
a standard output whose reader went away."""
from __future__ import annotations

import contextlib
import multiprocessing
import os
import select
import signal
import sys
import threading
import time
from concurrent.futures import ProcessPoolExecutor
from typing import Iterator

#: How often a worker looks whether its parent is still there [s] (it ends within about this).
PARENT_POLL_S = 1.0


def die_with_parent() -> None:
    """Start a watchdog thread that ends this process when its parent is gone (its parent id
    changes: a SIGKILLed parent leaves no one to stop the pool otherwise)."""
    # the parent multiprocessing names, not getppid(): a parent killed while this worker was still
    # starting has already left it to the reaper, which getppid() would take for the parent
    started_by = multiprocessing.parent_process()
    parent = started_by.pid if started_by is not None else os.getppid()

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(PARENT_POLL_S)
        os._exit(1)

    threading.Thread(target=watch, name="die-with-parent", daemon=True).start()


def pool_worker_init() -> None:
    """Initialiser of every pool worker: Ctrl-C is the main process's to handle (a worker prints no
    KeyboardInterrupt traceback), SIGTERM ends the worker at once (a forked worker would inherit the
    main process's handler), and the worker ends with its parent."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    die_with_parent()


class Terminated(KeyboardInterrupt):
    """SIGTERM received: raised in the main thread like Ctrl-C's ``KeyboardInterrupt`` (a subclass),
    so that every cleanup written for Ctrl-C runs for it too."""

    def __init__(self, signum: int = signal.SIGTERM):
        super().__init__(signal.Signals(signum).name)
        self.signum = signum


class _Stop:
    """Which signal stopped the program (0: none yet)."""

    signum: int = 0

    @property
    def exit_code(self) -> int:
        """128 + the signal's number (130 for Ctrl-C, 143 for SIGTERM), the shell's convention."""
        return 128 + self.signum


_stop = _Stop()  # of the program running now (stop_signals); a fresh one for each


def raise_if_stopped() -> None:
    """Raise the interrupt again if a stop signal arrived: Python drops an exception raised where it
    cannot propagate (an at-fork callback while a pool forks, a finalizer), and a stop must not be
    lost there. Called before new work starts."""
    signum = _stop.signum
    if signum:
        raise Terminated(signum) if signum == signal.SIGTERM else KeyboardInterrupt()


@contextlib.contextmanager
def stop_signals() -> Iterator[_Stop]:
    """While inside, Ctrl-C raises ``KeyboardInterrupt`` and SIGTERM :class:`Terminated` in the main
    thread, and each is remembered (:func:`raise_if_stopped`); later SIGTERMs are ignored so that the
    cleanup finishes. Outside the main thread this does nothing. Yields which signal arrived."""
    global _stop
    stop = _Stop()
    if threading.current_thread() is not threading.main_thread():
        yield stop
        return

    def handler(signum, frame) -> None:
        if signum == signal.SIGTERM:
            signal.signal(signal.SIGTERM, signal.SIG_IGN)
        stop.signum = stop.signum or signum
        raise Terminated(signum) if signum == signal.SIGTERM else KeyboardInterrupt()

    previous = {sig: signal.signal(sig, handler) for sig in (signal.SIGINT, signal.SIGTERM)}
    _stop = stop
    try:
        yield stop
    finally:
        _stop = _Stop()
        for sig, h in previous.items():
            signal.signal(sig, h)


class StoppablePool(ProcessPoolExecutor):
    """A process pool that starts no new work once the program is stopped (:func:`raise_if_stopped`)."""

    def submit(self, fn, /, *args, **kwargs):
        raise_if_stopped()
        fut = super().submit(fn, *args, **kwargs)
        raise_if_stopped()  # a Ctrl-C during the fork of its workers is dropped there
        return fut


def stop_pool(ex: ProcessPoolExecutor) -> None:
    """Stop a pool now: cancel its queued work and terminate its processes, which would otherwise go
    on with work nobody collects (``ProcessPoolExecutor`` has no public API for this before 3.14)."""
    procs = list((getattr(ex, "_processes", None) or {}).values())
    ex.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        if p.is_alive():
            p.terminate()
    for p in procs:
        p.join(5.0)  # reaped here, so that nothing is left for the interpreter's exit to wait on


@contextlib.contextmanager
def worker_pool(workers: int, start: str | None = None) -> Iterator[ProcessPoolExecutor]:
    """A pool of ``workers`` processes initialised by :func:`pool_worker_init` (``start``: the start
    method, default the platform's); on an exception (Ctrl-C, SIGTERM, an error) its processes are
    terminated at once instead of finishing the queue, else it waits for its work."""
    ctx = multiprocessing.get_context(start) if start else None
    ex = StoppablePool(max_workers=workers, mp_context=ctx, initializer=pool_worker_init)
    try:
        yield ex
        ex.shutdown(wait=True)
    except BaseException:
        stop_pool(ex)
        raise


def stdout_reader_gone() -> bool:
    """Whether standard output is a pipe whose reader has closed it (``| head``); if so it is pointed at
    the null device, so that the interpreter's flush at exit raises no second ``BrokenPipeError``."""
    try:
        poller = select.poll()
        poller.register(sys.stdout.fileno(), select.POLLOUT)
        gone = any(ev & select.POLLERR for _, ev in poller.poll(0))
    except (OSError, ValueError, AttributeError):  # no file descriptor (e.g. captured output)
        return False
    if gone:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    return gone


__all__ = ["die_with_parent", "pool_worker_init", "stop_pool", "worker_pool", "StoppablePool", "Terminated",
           "stop_signals", "raise_if_stopped", "stdout_reader_gone", "PARENT_POLL_S"]
