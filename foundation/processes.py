"""Worker processes that end with the process that started them (the pools of every sweep)."""
from __future__ import annotations

import os
import signal
import threading
import time

#: How often a worker looks whether its parent is still there [s] (it ends within about this).
PARENT_POLL_S = 1.0


def die_with_parent() -> None:
    """Start a watchdog thread that ends this process when its parent is gone (its parent id
    changes: a SIGKILLed parent leaves no one to stop the pool otherwise)."""
    parent = os.getppid()

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(PARENT_POLL_S)
        os._exit(1)

    threading.Thread(target=watch, name="die-with-parent", daemon=True).start()


def pool_worker_init() -> None:
    """Initialiser of every pool worker: Ctrl-C is the main process's to handle, and the worker
    ends with its parent."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    die_with_parent()


__all__ = ["die_with_parent", "pool_worker_init", "PARENT_POLL_S"]
