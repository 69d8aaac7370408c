"""The speed table of docs/timings.md#7-the-speed-table, every row re-measured on demand.

Rows (``--rows``, comma-separated; ``cheap``, the default, is the rows of a few minutes; ``all``):

* ``test``: ``make test`` from a fresh clone (environment created, whole suite on every core);
* ``test-fast``: ``make test-fast`` in this tree (its aim: at most 60 s);
* ``tilt``: ``archdem tilt Sh06-Sd015`` (3 simulations), the least of ``--repeat`` runs;
* ``demo``: ``make demo`` from a fresh clone, with the campaign's own time of each step;
* ``full-estimate``: the full campaign's estimate for this machine, as it prints it before it starts;
* ``full``: the full campaign, run (about 25 min on 2 cores);
* ``engine-share``: the share of one fragility run's wall time inside the engine's step
  (``bench_fragility.py``, cProfile of one run);
* ``dask``: the efficiency of a local Dask cluster of 2 workers against 1 local worker
  (``bench_fragility.py --dask``, 4 realisations of each stripe).

Wall times on a shared machine are upper bounds: each row prints the load average beside it, and
``--repeat N`` keeps the least of N runs. Runs go to temporary folders; the rows of
``bench_fragility.py`` leave its JSON in benchmarks/results/, as it always does.

    python benchmarks/speed_table.py [--rows cheap|all|ROW,...] [--repeat 3]
"""
from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(sys.executable).parent
CHEAP = ("test-fast", "tilt", "full-estimate", "engine-share")
ALL = ("test", "test-fast", "tilt", "demo", "full-estimate", "full", "engine-share", "dask")


def _timed(cmd: list[str], cwd: Path, env: dict | None = None) -> tuple[float, subprocess.CompletedProcess]:
    t0 = time.perf_counter()
    out = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, env={**os.environ, **(env or {})})
    return time.perf_counter() - t0, out


def _load() -> str:
    return f"load {os.getloadavg()[0]:.1f}"


def _clone(d: Path) -> Path:
    subprocess.run(["git", "clone", "-q", str(ROOT), str(d / "archdem")], check=True)
    return d / "archdem"


def _pytest_line(text: str) -> str:
    lines = [x for x in text.splitlines() if re.search(r"\d+ passed", x)]
    return lines[-1].strip("= ") if lines else "no pytest summary"


def row_test(a) -> str:
    with tempfile.TemporaryDirectory(prefix="archdem-speed-") as d:
        src = _clone(Path(d))
        wall, out = _timed(["make", "test"], src)
    return f"{wall / 60:.1f} min ({_pytest_line(out.stdout)}), exit {out.returncode}"


def row_test_fast(a) -> str:
    walls = []
    for _ in range(a.repeat):
        wall, out = _timed([str(BIN / "python"), "-m", "pytest", "-q", "-p", "no:cacheprovider", "-n", "auto",
                            "--dist", "worksteal", "-m", "not slow"], ROOT)
        walls.append(wall)
    return f"{min(walls):.0f} s (least of {len(walls)}: {', '.join(f'{w:.0f}' for w in walls)}; " \
           f"{_pytest_line(out.stdout)}), exit {out.returncode}"


def row_tilt(a) -> str:
    walls, cpu = [], []
    with tempfile.TemporaryDirectory(prefix="archdem-speed-") as d:
        for k in range(a.repeat):
            r0 = os.times()
            wall, out = _timed([str(BIN / "archdem"), "tilt", "Sh06-Sd015", "--json", "--out", f"{d}/{k}"], ROOT)
            r1 = os.times()
            if out.returncode:
                return f"failed: {out.stderr.strip().splitlines()[-1]}"
            walls.append(wall)
            cpu.append(r1.children_user - r0.children_user + r1.children_system - r0.children_system)
            res = json.loads(out.stdout)
    return (f"{min(walls):.2f} s (least of {len(walls)}: {', '.join(f'{w:.2f}' for w in walls)}; CPU "
            f"{min(cpu):.2f} s), lambda {res['lambda']:.4f}, {res['n_sims']} simulations")


def _steps(campaign: Path) -> str:
    steps = json.loads((campaign / "campaign.json").read_text()).get("steps", {})
    return ", ".join(f"{k} {v['wall_s']:.0f} s" for k, v in steps.items() if isinstance(v.get("wall_s"), (int, float)))


def row_demo(a) -> str:
    with tempfile.TemporaryDirectory(prefix="archdem-speed-") as d:
        src = _clone(Path(d))
        wall, out = _timed(["make", "demo"], src)
        steps = _steps(src / "runs" / "demo") if out.returncode == 0 else out.stderr.strip()[-200:]
    return f"{wall / 60:.1f} min in all, exit {out.returncode}; campaign steps: {steps}"


def row_full_estimate(a) -> str:
    with tempfile.TemporaryDirectory(prefix="archdem-speed-") as d:
        p = subprocess.Popen([str(BIN / "archdem"), "campaign", "--out", f"{d}/full"], cwd=ROOT,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            for line in p.stdout:
                if line.startswith("full campaign"):
                    return line.strip()
        finally:
            p.kill()
            p.wait()
    return "no estimate printed"


def row_full(a) -> str:
    with tempfile.TemporaryDirectory(prefix="archdem-speed-") as d:
        wall, out = _timed([str(BIN / "archdem"), "campaign", "--out", f"{d}/full"], ROOT)
        steps = _steps(Path(d) / "full") if out.returncode == 0 else out.stderr.strip()[-200:]
    return f"{wall / 60:.1f} min, exit {out.returncode}; steps: {steps}"


def _bench_fragility(*args: str) -> dict:
    wall, out = _timed([str(BIN / "python"), "benchmarks/bench_fragility.py", *args], ROOT)
    vals = {}
    for line in out.stdout.splitlines():
        parts = line.split()
        if len(parts) == 2:
            vals[parts[0]] = parts[1]
    vals["exit"] = out.returncode
    return vals


def row_engine_share(a) -> str:
    v = _bench_fragility("--n", "1", "--efficiency-n", "1", "--amplitudes", "0.35")
    return f"{float(v.get('engine_step_share', 'nan')) * 100:.0f} % of {float(v.get('one_run_s', 'nan')):.2f} s " \
           f"(build {float(v.get('engine_build_s', 'nan')):.2f} s), exit {v['exit']}"


def row_dask(a) -> str:
    v = _bench_fragility("--n", "1", "--efficiency-n", "4", "--dask")
    return (f"{float(v.get('efficiency_dask_2', 'nan')):.2f} (1 worker {float(v.get('t_1_worker_s', 'nan')):.1f} s, "
            f"Dask 2 workers {float(v.get('t_dask_2_workers_s', 'nan')):.1f} s; local pool of 2: "
            f"{float(v.get('efficiency_local_2', 'nan')):.2f}), exit {v['exit']}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", default="cheap", help=f"cheap ({', '.join(CHEAP)}), all, or any of {', '.join(ALL)}")
    ap.add_argument("--repeat", type=int, default=3, help="runs of the repeated rows (tilt, test-fast); the least is kept")
    a = ap.parse_args()
    rows = CHEAP if a.rows == "cheap" else ALL if a.rows == "all" else tuple(r.strip() for r in a.rows.split(","))
    bad = [r for r in rows if r not in ALL]
    if bad:
        print(f"unknown row {bad[0]!r}: one of {', '.join(ALL)}", file=sys.stderr)
        return 2
    print(f"archdem speed table, {os.cpu_count()} cores, {time.strftime('%Y-%m-%d %H:%M')}", flush=True)
    for r in rows:
        res = globals()[f"row_{r.replace('-', '_')}"](a)
        print(f"| {r} | {res} | {_load()} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
