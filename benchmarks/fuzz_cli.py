"""Fuzz the command line with bad input: every run must end within 30 s with exit 2, one line on
stderr, no traceback and no file left behind.

Each case is a valid minimal command line with one option given a bad value (not a number,
NaN, infinite, negative, zero, absurdly large, an empty or broken grid...), or a command reading
one of the real record files with one field damaged, drawn with a seeded generator; each runs as
its own process in an empty folder (but for the record it reads). Writes benchmarks/results/fuzz_cli.json.

    python benchmarks/fuzz_cli.py [--n 500] [--seed 1] [--workers 2]
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

OUT = Path(__file__).resolve().parent / "results"
ARCH = ["Sh02-Sd020"]
PIER_OPTIONS = ["--pier-height", "--pier-width", "--pier-depth", "--pier-offset", "--pier-courses", "--pier-load"]
# (command, the valid rest of its command line, options to corrupt)
COMMANDS = [
    ("mesh", ARCH + ["--out", "m"], ["--contact", "--width", "--voussoirs", "--density"]),
    ("draw", ARCH + ["--out", "d.png"], ["--contact", "--width", "--voussoirs", "--density"]),
    ("analytic", ARCH, ["--contact", "--mu-joint", "--mu-base", "--effective-thickness", "--min-spacing", "--width",
                        "--voussoirs", "--density"]),
    ("tilt", ARCH + ["--out", "t"], ["--contact", "--mu-joint", "--mu-base", "--dt", "--width", "--voussoirs",
                                     "--density", "--ensemble"]),
    ("map", ["--specimens", "Sh02-Sd020", "--out", "m.h5"], ["--mu", "--mu-base", "--contact", "--tol", "--workers"]),
    ("domain", ARCH, ["--contact", "--freq", "--amax", "--scan", "--tol", "--workers", "--width", "--density"]),
    ("rock", ARCH + ["--freq", "4", "--amplitude", "0.5"], ["--contact", "--freq", "--amplitude", "--width", "--density"]),
    ("shake", ARCH + ["--sine", "4", "--amplitude", "0.3", "--out", "s"], ["--contact", "--mu-joint", "--mu-base", "--dt",
                                                                          "--tail", "--sine", "--amplitude", "--duration",
                                                                          "--width", "--voussoirs", "--density"]),
    ("threshold", ARCH + ["--sine", "4"], ["--contact", "--mu-joint", "--mu-base", "--dt", "--tail", "--sine", "--a-min",
                                           "--a-max", "--scan-ratio", "--tol", "--workers"]),
    ("draw", ["--Sh", "0.6", "--Sd", "0.2", "--Rc", "0.2", "--out", "d.png"], ["--Sh", "--Sd", "--Rc", "--width"]),
    ("analytic", ["--Ri", "0.2", "--Re", "0.25", "--e", "0.1"], ["--Ri", "--Re", "--e", "--voussoirs"]),
    ("map", ["--specimens", "Sh02-Sd020"], ["--resume"]),
    ("assess", ARCH + ["--spectrum", "ntc2018", "--ag", "0.25", "--F0", "2.4", "--Tc-star", "0.3"],
     ["--ag", "--F0", "--Tc-star", "--damping", "--FC", "--q", "--soil", "--topography", "--frp", "--z-ratio", "--T1",
      "--floors", "--building-damping", "--limit-state", "--match-periods", "--spectrum"]),
    ("assess", ["noh-gumbad"], ["--FC", "--q", "--frp", "--spectrum", "--limit-state"]),
    ("draw", ARCH + ["--out", "d.png", "--pier-height", "0.2", "--pier-width", "0.1"], PIER_OPTIONS),
    ("analytic", ARCH + ["--pier-height", "0.2", "--pier-width", "0.1"], PIER_OPTIONS),
    ("rock", ARCH + ["--freq", "4", "--amplitude", "0.5", "--pier-height", "0.2", "--pier-width", "0.1"], PIER_OPTIONS),
    ("tilt", ARCH + ["--out", "t", "--pier-height", "0.2", "--pier-width", "0.1"], PIER_OPTIONS),
    ("campaign", ["--out", "c", "--specimens", "Sh02-Sd020"], ["--contact", "--workers", "--steps", "--specimens"]),
    ("compare-engines", ["--specimens", "Sh02-Sd020"], ["--dt", "--workers", "--engines", "--specimens"]),
]
#: Commands that read a record file: the value corrupted is a field of one of the real files.
RECORD_COMMANDS = [("rock", ARCH + ["--freq", "4", "--scale", "1"]),
                   ("shake", ARCH + ["--scale", "1", "--duration", "0.2", "--out", "s"])]
RECORDS = Path(__file__).resolve().parents[1] / "tests" / "data" / "ground_motions"
BAD = ["abc", "nan", "inf", "-inf", "-1", "0", "-0.0", "1e30", "1e-30", "", " ", "1,,2", "1:1e9:1e-9", "2:1:0.5",
       "1e309", "0x10", "99999999999999999999", "-1e30"]


def corrupt_record(rng: np.random.Generator) -> tuple[str, bytes]:
    """One of the real record files with one field of its header or data replaced by a bad value."""
    files = sorted(p for p in RECORDS.iterdir() if p.suffix.lower() in (".at2", ".smc"))
    path = files[rng.integers(len(files))]
    lines = path.read_text(errors="replace").splitlines()
    i = int(rng.integers(min(len(lines), 40)))  # the header, or the first data lines
    words = lines[i].split() or [""]
    words[rng.integers(len(words))] = BAD[rng.integers(len(BAD))]
    lines[i] = " ".join(words)
    return path.name, ("\n".join(lines) + "\n").encode()


def run(case: tuple[list[str], int, dict]) -> dict:
    argv, k, inputs = case
    with tempfile.TemporaryDirectory() as tmp:
        for name, data in inputs.items():
            Path(tmp, name).write_bytes(data)
        t0 = time.perf_counter()
        try:
            p = subprocess.run([sys.executable, "-m", "dem.cli", *argv], cwd=tmp, capture_output=True, text=True,
                               timeout=30)
            rc, err, out = p.returncode, p.stderr, p.stdout
        except subprocess.TimeoutExpired:
            rc, err, out = None, "", ""
        left = sorted(str(f.relative_to(tmp)) for f in Path(tmp).rglob("*") if f.name not in inputs)
    lines = [ln for ln in err.splitlines() if ln.strip() and "pybullet build time" not in ln]
    return {"argv": argv, "rc": rc, "stderr_lines": len(lines), "traceback": "Traceback" in err,
            "files_left": left, "wall_s": time.perf_counter() - t0, "err": lines[-1] if lines else "", "stdout": out[-200:]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=500)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--workers", type=int, default=2)
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    cases = []
    for k in range(a.n):
        if rng.random() < 0.1:  # a damaged record file
            cmd, rest = RECORD_COMMANDS[rng.integers(len(RECORD_COMMANDS))]
            name, data = corrupt_record(rng)
            cases.append(([cmd, *rest, "--record", name], k, {name: data}))
            continue
        cmd, rest, opts = COMMANDS[rng.integers(len(COMMANDS))]
        opt = opts[rng.integers(len(opts))]
        cases.append(([cmd, *rest, opt, BAD[rng.integers(len(BAD))]], k, {}))
    t0 = time.perf_counter()
    with ThreadPoolExecutor(a.workers) as ex:
        rows = list(ex.map(run, cases))
    ok = [r for r in rows if r["rc"] == 2 and r["stderr_lines"] == 1 and not r["traceback"] and not r["files_left"]]
    # a bad value the command accepts (exit 0) is listed apart: some "bad" values are valid for some options
    accepted = [r for r in rows if r["rc"] == 0 and not r["traceback"]]
    res = {"n": len(rows), "refused_in_one_line": len(ok), "accepted": len(accepted),
           "tracebacks": sum(r["traceback"] for r in rows), "hangs": sum(r["rc"] is None for r in rows),
           "left_files": sum(bool(r["files_left"]) for r in rows),
           "several_lines": sum(r["rc"] == 2 and r["stderr_lines"] != 1 for r in rows),
           "other_exit": sum(r["rc"] not in (0, 2, None) for r in rows), "wall_s": time.perf_counter() - t0,
           "problems": [r for r in rows if r not in ok and r not in accepted], "accepted_cases": [r["argv"] for r in accepted]}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "fuzz_cli.json").write_text(json.dumps(res, indent=1))
    print({k: v for k, v in res.items() if k not in ("problems", "accepted_cases")})
    for r in res["problems"][:40]:
        print(r["rc"], r["stderr_lines"], r["traceback"], r["files_left"][:3], " ".join(r["argv"]), "|", r["err"][:150])
    print("accepted:", *(" ".join(x) for x in res["accepted_cases"][:40]), sep="\n  ")


if __name__ == "__main__":
    main()
