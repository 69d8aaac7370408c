"""Cheap case functions for testing the sweep engine (:mod:`dem.studies.sweep`).

They live in the installed package (not in ``tests/``) so that every worker process —
a local process pool started with ``spawn`` or a Dask worker — imports them by the name
``dem.studies.selftest_cases.evaluate`` by reference whatever their working directory or ``sys.path``.

``evaluate(case)`` needs ``case["x"]`` (a number) and understands optional test hooks:

* ``count_dir``: write one file per evaluation into this folder (to count evaluations);
* ``fail``: raise ``ValueError`` (a failing case);
* ``fail_marker`` / ``crash_marker`` / ``interrupt_marker``: if that file exists, delete it
  and then raise ``ValueError`` / kill the worker process with ``os._exit`` /
  raise ``KeyboardInterrupt`` — once, so that a resumed study gets past it;
* ``sleep``: seconds to wait before returning.
"""
from __future__ import annotations

import math
import os
import time
import uuid
from pathlib import Path

import numpy as np


def _take(marker: str | None) -> bool:
    if not marker:
        return False
    try:
        os.remove(marker)
    except FileNotFoundError:
        return False
    return True


def evaluate(case: dict) -> dict:
    """A result dict of every supported kind, computed from ``case["x"]``."""
    x = case["x"]
    if case.get("count_dir"):
        Path(case["count_dir"], f"{x}-{os.getpid()}-{uuid.uuid4().hex}").touch()
    if case.get("sleep"):
        time.sleep(case["sleep"])
    if _take(case.get("crash_marker")):
        os._exit(3)
    if _take(case.get("interrupt_marker")):
        raise KeyboardInterrupt
    if _take(case.get("fail_marker")) or case.get("fail"):
        raise ValueError(f"case x={x} fails on purpose")
    return {
        "y": x * x,
        "root": math.sqrt(abs(x)),
        "label": f"x={x}",
        "even": int(x) % 2 == 0,
        "series": np.linspace(0.0, 1.0, 5) * x,
        "none": None,
        "nested": {"neg": -x, "names": ["a", "b"]},
    }
