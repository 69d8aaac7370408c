"""Shared by the benchmark scripts: print a result dict and store it as JSON in results/."""
from __future__ import annotations

import json
from pathlib import Path

from foundation.io import atomic_path, unique_run_path


def report(name: str, res: dict, digits: int = 3) -> Path:
    """Print ``res`` one quantity a line and write it to ``results/<name>[-N].json`` (never overwritten)."""
    for k, v in res.items():
        print(f"{k:32s} {v:.{digits}f}" if isinstance(v, float) else f"{k:32s} {v}")
    out = unique_run_path(Path(__file__).parent / "results", name, ".json")
    with atomic_path(out) as tmp:
        tmp.write_text(json.dumps(res, indent=2))
    print(f"written {out.name}")
    return out


def timed_threshold(sid: str, freq: float, engine: str = "pybullet", workers: int = 2, config: str = "glued"):
    """One shake threshold of a one-cycle sine at ``freq`` [Hz], as ``archdem threshold`` runs it:
    scanned from the static onset lambda (LP, reference friction) up to 5 x it, bisected to 1 %, on
    ``workers`` processes. Returns ``(ThresholdResult, lambda, wall_s)``; the wall time leaves out
    the LP and the model build."""
    import time

    from dem.core.model import as_model
    from dem.core.settings import Settings
    from dem.experiments.shake.thresholds import static_onset, threshold

    st = Settings(engine=engine)
    model = as_model(sid, config=config)
    lam = static_onset(model, st)
    t0 = time.perf_counter()
    th = threshold(model, freq, st, workers=workers)  # the defaults of archdem threshold
    return th, lam, time.perf_counter() - t0
