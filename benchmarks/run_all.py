"""Run every benchmark script (benchmarks/bench_*.py) and write a JSON + markdown summary.

Each script writes its own JSON into benchmarks/results/; this runner calls them one after
another (so they do not compete for cores), then gathers the JSON files into
benchmarks/results/summary.json and summary.md. Usage: ``make bench`` or
``python benchmarks/run_all.py [--only NAME,...]``.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"


def _md_value(v) -> str:
    if isinstance(v, float):
        return f"{v:.4g}"
    if isinstance(v, (dict, list)):
        s = json.dumps(v)
        return s if len(s) < 120 else s[:117] + "..."
    return str(v)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", default=None, help="comma-separated script names without bench_ and .py")
    args = ap.parse_args()
    RESULTS.mkdir(exist_ok=True)
    scripts = sorted(HERE.glob("bench_*.py"))
    if args.only:
        keep = {f"bench_{n.strip()}.py" for n in args.only.split(",")}
        scripts = [s for s in scripts if s.name in keep]
    runs = {}
    for s in scripts:
        print(f"== {s.name}", flush=True)
        t0 = time.perf_counter()
        r = subprocess.run([sys.executable, str(s)], cwd=HERE.parent)
        runs[s.stem] = {"exit_code": r.returncode, "wall_s": time.perf_counter() - t0}
    summary = {"runs": runs, "results": {}}
    for f in sorted(RESULTS.glob("*.json")):
        if f.name != "summary.json":
            summary["results"][f.stem] = json.loads(f.read_text())
    (RESULTS / "summary.json").write_text(json.dumps(summary, indent=2))
    lines = ["# archdem benchmark summary", ""]
    for name, res in summary["results"].items():
        lines += [f"## {name}", "", "| quantity | value |", "|---|---|"]
        flat = res.items() if isinstance(res, dict) else [("value", res)]
        lines += [f"| {k} | {_md_value(v)} |" for k, v in flat]
        lines.append("")
    (RESULTS / "summary.md").write_text("\n".join(lines))
    print(f"summary: {RESULTS / 'summary.md'}")
    return 0 if all(r["exit_code"] == 0 for r in runs.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
