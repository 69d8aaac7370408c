"""Shared by the benchmark scripts: print a result dict and store it as JSON in results/."""
from __future__ import annotations

import json
from pathlib import Path

from dem.atomic import atomic_path, unique_run_path


def report(name: str, res: dict, digits: int = 3) -> Path:
    """Print ``res`` one quantity a line and write it to ``results/<name>[-N].json`` (never overwritten)."""
    for k, v in res.items():
        print(f"{k:32s} {v:.{digits}f}" if isinstance(v, float) else f"{k:32s} {v}")
    out = unique_run_path(Path(__file__).parent / "results", name, ".json")
    with atomic_path(out) as tmp:
        tmp.write_text(json.dumps(res, indent=2))
    print(f"written {out.name}")
    return out
