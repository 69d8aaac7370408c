"""Fuzz the command line: every run must end within its time limit, bad input with exit 2, one line on
stderr, no traceback and no file left behind; an option that does nothing where it is given must be
refused (or warned about); a resumed study must be the study in its file.

Each case is one of (drawn with a seeded generator, each run as its own process in an empty folder
with its own temporary folder):

* ``value``: a valid minimal command line with one option given a bad value (not a number, NaN,
  infinite, negative, zero, absurdly large, an empty or broken grid...);
* ``record``: a command reading one of the real record files with one field damaged;
* ``degenerate``: a record of zeros, of a PGA far below an accelerometer's resolution, or with a NaN
  sample, read by shake, rock or fragility;
* ``combination``: a command line with an option that does nothing in its context;
* ``output``: an output that exists, is a folder, is empty, lies under a file or on a read-only or
  missing mount, or whose lock file cannot be made (a name too long);
* ``resume``: an interrupted study (a finished map or fragility study with one case removed) resumed
  with its original arguments, with none, or with one that disagrees.

Writes benchmarks/results/fuzz_cli.json.

    python benchmarks/fuzz_cli.py [--n 500] [--seed 1] [--workers 2]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import h5py
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


SINE = ["--sine", "4", "--amplitude", "0.3"]
TILT = ["tilt", *ARCH, "--out", "t"]
#: Options that do nothing in the context of the rest of their command line.
COMBINATIONS = [
    [*TILT, "--protocol", "ramp", "--start", "lp"], [*TILT, "--protocol", "ramp", "--full-hold"],
    [*TILT, "--protocol", "staircase", "--start", "scan"], [*TILT, "--protocol", "staircase", "--full-hold"],
    [*TILT, "--seed", "1"], [*TILT, "--scatter", "1"], [*TILT, "--workers", "2"],
    [*TILT, "--contact-law", "rigid", "--kn", "1e8"], [*TILT, "--contact-law", "rigid", "--damping-beta", "1e-3"],
    [*TILT, "--joints", "table-5.1", "--kn", "1e8"], [*TILT, "--ks", "1e8", "--kn", "1e8"],
    [*TILT, "--ensemble", "2", "--seed", "1", "--scatter", "1", "--planar"],
    ["shake", *ARCH, *SINE, "--baseline", "--out", "s"], ["shake", *ARCH, *SINE, "--units", "g", "--out", "s"],
    ["shake", *ARCH, *SINE, "--scale", "2", "--out", "s"], ["shake", *ARCH, *SINE, "--pga", "0.2", "--out", "s"],
    ["shake", *ARCH, "--record", "rec.csv", "--scale", "1", "--amplitude", "0.3", "--out", "s"],
    ["compare-engines", "--engines", "pybullet,pybullet", "--specimens", "Sh02-Sd020"],
    ["rock", *ARCH, "--freq", "4", "--amplitude", "0.5", "--duration", "0.3"],
    ["rock", *ARCH, "--input", "A", "--duration", "0.3", "--amplitude", "0.5", "--freq", "4"],
    ["rock", *ARCH, "--record", "rec.csv", "--scale", "1", "--amplitude", "0.5"],
    ["rock", *ARCH, "--record", "rec.csv", "--scale", "1", "--freq", "4"],
    ["rock", *ARCH, "--record", "rec.csv", "--scale", "1", "--input", "A"],
    ["rock", *ARCH, "--freq", "4", "--amplitude", "0.5", "--scale", "2"],
    ["map", "--specimens", "Sh02-Sd020", "--workers", "2", "--scheduler", "tcp://127.0.0.1:9"],
    ["threshold", *ARCH, "--sine", "4", "--workers", "2", "--scheduler", "tcp://127.0.0.1:9"],
    ["fragility", "--block", "0.05", "0.2", "--records", "rec.csv", "--im", "pga", "--stripes", "0.3",
     "--realizations", "1", "--no-deterministic"],
    ["fragility", "--block", "0.05", "0.2", "--sine", "4", "--amplitudes", "0.3", "--realizations", "1", "--edge-loss", "1"],
    ["fragility", *ARCH, "--sine", "4", "--amplitudes", "0.3", "--realizations", "1", "--size-sd", "1"],
    ["fragility", "--block", "0.05", "0.2", "--sine", "4", "--amplitudes", "0.3", "--realizations", "1", "--im", "pga"],
    ["assess", *ARCH, "--spectrum", "ec8", "--ag", "0.2", "--engine", "mujoco"],
    ["assess", *ARCH, "--spectrum", "ec8", "--ag", "0.2", "--workers", "2"],
    ["assess", *ARCH, "--spectrum", "ec8", "--ag", "0.2", "--F0", "2.4"],
    ["domain", *ARCH, "--mu-joint", "0.5"], ["domain", *ARCH, "--config", "free"], ["domain", *ARCH, "--mu-base", "0.8"],
    ["domain", *ARCH, "--engine", "dem", "--layout", "discrete"], ["domain", *ARCH, "--engine", "dem", "--restitution", "0.9"],
    ["domain", *ARCH, "--engine", "dem", "--model", "two-bar"], ["domain", *ARCH, "--engine", "dem", "--scan", "10"],
    ["domain", *ARCH, "--input", "sine", "--durations", "0.1"], ["domain", *ARCH, "--kn", "1e8"],
    ["modes", *ARCH, "--kn", "1e8", "--poisson", "0.2"],
    ["analytic", *ARCH, "--pier-height", "0.2", "--pier-width", "0.1", "--effective-thickness", "0.8"],
]
#: Commands with an output, the rest of their command line before it, and the option.
OUTPUTS = [
    (["tilt", *ARCH], "--out", "dir"), (["tilt", *ARCH], "--plot", "file"),
    (["shake", *ARCH, *SINE], "--out", "dir"), (["shake", *ARCH, *SINE], "--plot", "file"),
    (["map", "--specimens", "Sh02-Sd020", "--mu", "0.5"], "--out", "study"),
    (["map", "--specimens", "Sh02-Sd020", "--mu", "0.5", "--out", "m.h5"], "--plot", "dir"),
    (["fragility", "--block", "0.05", "0.2", "--sine", "4", "--amplitudes", "0.3", "--realizations", "1"], "--out", "study"),
    (["fragility", "--block", "0.05", "0.2", "--sine", "4", "--amplitudes", "0.3", "--realizations", "1",
      "--out", "f.h5"], "--plot", "file"),
    (["domain", *ARCH], "--plot", "file"), (["domain", *ARCH, "--engine", "dem", "--freq", "4"], "--plot", "file"),
    (["rock", *ARCH, "--freq", "4", "--amplitude", "0.5"], "--plot", "file"),
    (["modes", *ARCH, "--kn", "1e8"], "--plot", "file"), (["compare-engines", "--specimens", "Sh02-Sd020"], "--plot", "file"),
    (["calibrate", "--no-scatter"], "--out", "file"), (["mesh", *ARCH], "--out", "dir"), (["draw", *ARCH], "--out", "file"),
    (["assess", *ARCH, "--spectrum", "ec8", "--ag", "0.2"], "--report", "html"),
    (["campaign", "--specimens", "Sh02-Sd020", "--steps", "catalogue"], "--out", "dir"),
]
#: Bad values of an output option by kind ("old.*" exist, "dir" is a folder, "old.png/x" lies under a file).
BAD_OUTPUTS = {
    "file": ["old.png", "dir", "", "old.png/x.png", "/proc/x/y.png", "/sys/y.png", "a" * 300 + ".png"],
    "html": ["old.html", "dir", "", "old.png/x.html", "/proc/x/y.html", "/sys/y.html"],
    "study": ["old.h5", "dir", "", "old.png/x.h5", "/proc/x/y.h5", "/sys/y.h5", "a" * 250 + ".h5"],
    "dir": ["old.png", "", "old.png/x", "/proc/x/y", "/sys/y", "a" * 300],
}


def degenerate_record(rng: np.random.Generator) -> tuple[str, bytes, str]:
    """A record file that cannot mean anything: zeros, a PGA far below 1e-6 g, or a NaN sample."""
    kind = ["zeros", "tiny", "nan"][rng.integers(3)]
    n = int(rng.choice([200, 2000, 20000]))  # up to 200 s at 0.01 s
    a = np.sin(np.arange(n) * 0.37) * (3e-10 if kind == "tiny" else 0.3)
    if kind == "zeros":
        a[:] = 0.0
    rows = [f"{k * 0.01:.2f},{v:.6g}" for k, v in enumerate(a)]
    if kind == "nan":
        k = int(rng.integers(n))
        rows[k] = f"{k * 0.01:.2f},nan"
    return "deg.csv", ("t [s],a [g]\n" + "\n".join(rows) + "\n").encode(), kind


DEGENERATE_COMMANDS = [
    ["shake", *ARCH, "--record", "deg.csv", "--scale", "1", "--out", "s"],
    ["shake", *ARCH, "--record", "deg.csv", "--pga", "0.4", "--out", "s"],
    ["rock", *ARCH, "--record", "deg.csv", "--scale", "1"],
    ["fragility", "--block", "0.05", "0.2", "--records", "deg.csv", "--im", "pga", "--stripes", "0.3", "--realizations", "1"],
    ["record", "deg.csv"],
]
#: The studies resumed (cheap: two cases each); their options, and one that disagrees.
STUDIES = {
    "map": (["map", "--specimens", "Sh02-Sd020", "--mu", "0.4,0.8", "--refine", "0", "--tol", "0.5", "--workers", "1"],
            [["--mu", "0.3:1.2:0.3"], ["--specimens", "all"], ["--config", "free"], ["--tol", "0.1"]]),
    "fragility": (["fragility", "--block", "0.05", "0.2", "--sine", "4", "--amplitudes", "0.3,0.5", "--realizations",
                   "1", "--no-deterministic", "--workers", "1"],
                  [["--seed", "3"], ["--amplitudes", "0.3"], ["--realizations", "2"], ["--mu-joint", "0.6"]]),
}


def _answer(kind: str, out: str):
    """The part of a study's JSON answer that must not depend on an interruption."""
    d = json.loads(out)
    if kind == "map":
        return [[(p["mu"], p["lambda"], p["mode"]) for p in s["points"]] for s in d]
    return [[(p["intensity"], p["n_collapsed"], p["n_runs"], p["modes"]) for p in c["points"]] for c in d["curves"]]


def run(case: dict) -> dict:
    argv, inputs, expect = case["argv"], dict(case["inputs"]), case["expect"]
    if "s.h5" in inputs:  # an interrupted study: made here, from the finished one
        kind, i = inputs["s.h5"]
        inputs["s.h5"] = _interrupted(case["studies"][kind][0], i)
    with tempfile.TemporaryDirectory() as tmp:
        for name, data in inputs.items():
            Path(tmp, name).parent.mkdir(parents=True, exist_ok=True)
            Path(tmp, name).write_bytes(data)
        (Path(tmp) / "dir").mkdir(exist_ok=True)
        private = Path(tmp) / ".tmp"  # the engines' temporary folders: whatever stays there is left behind
        private.mkdir()
        env = {**os.environ, "TMPDIR": str(private)}
        t0 = time.perf_counter()
        try:
            p = subprocess.run([sys.executable, "-m", "dem.cli", *argv], cwd=tmp, capture_output=True, text=True,
                               timeout=case["timeout"], env=env)
            rc, err, out = p.returncode, p.stderr, p.stdout
        except subprocess.TimeoutExpired:
            rc, err, out = None, "", ""
        wall = time.perf_counter() - t0
        made = sorted(str(f.relative_to(tmp)) for f in Path(tmp).rglob("*")
                      if str(f.relative_to(tmp)) not in inputs and f.name not in ("dir", ".tmp"))
        same = None
        if expect == "resumed" and rc == 0:
            try:
                same = _answer(case["study"], out) == case["truth"]
            except (ValueError, KeyError, TypeError):
                same = False
    # a finished study leaves its file and tables; anything else (a lock, a .part, an engine's folder) is left over
    allowed = (lambda f: f.startswith(case["study_file"])) if expect == "resumed" else (lambda f: False)
    left = [f for f in made if not allowed(f) or f.endswith((".lock", ".part"))]
    lines = [ln for ln in err.splitlines() if ln.strip() and "pybullet build time" not in ln]
    return {"kind": case["kind"], "argv": argv, "expect": expect, "rc": rc, "stderr_lines": len(lines),
            "traceback": "Traceback" in err, "files_left": left, "wall_s": wall, "same": same,
            "warned": any("warning" in ln.lower() for ln in lines), "err": lines[-1] if lines else "",
            "stdout": out[-200:]}


def _prepare_studies(work: Path) -> dict:
    """Run each resumed study once, uninterrupted: its file and its answer."""
    out = {}
    for kind, (argv, _) in STUDIES.items():
        path = work / f"{kind}.h5"
        p = subprocess.run([sys.executable, "-m", "dem.cli", *argv, "--out", str(path), "--json"], capture_output=True,
                           text=True, timeout=900)
        if p.returncode != 0:
            raise SystemExit(f"the {kind} study did not run: {p.stderr[-500:]}")
        out[kind] = (path.read_bytes(), _answer(kind, p.stdout))
    return out


def _interrupted(data: bytes, key_index: int) -> bytes:
    """The study file with one of its cases removed, as an interrupted run leaves it."""
    with tempfile.TemporaryDirectory() as tmp:
        f = Path(tmp) / "s.h5"
        f.write_bytes(data)
        with h5py.File(f, "a") as h:
            keys = sorted(h["cases"])
            del h["cases"][keys[key_index % len(keys)]]
        return f.read_bytes()


def make_cases(n: int, rng: np.random.Generator, studies: dict) -> list[dict]:
    rec_csv = ("t [s],a [g]\n" + "\n".join(f"{k * 0.01:.2f},{0.3 * math.sin(k * 0.5):.6g}" for k in range(300))
               + "\n").encode()
    common = {"old.png": b"old", "old.html": b"old", "old.h5": b"old", "rec.csv": rec_csv}
    cases = []
    for k in range(n):
        u = rng.random()
        if u < 0.25:
            cmd, rest, opts = COMMANDS[rng.integers(len(COMMANDS))]
            opt = opts[rng.integers(len(opts))]
            cases.append({"kind": "value", "argv": [cmd, *rest, opt, BAD[rng.integers(len(BAD))]], "inputs": {},
                          "expect": "refused_or_accepted", "timeout": 60})
        elif u < 0.32:
            cmd, rest = RECORD_COMMANDS[rng.integers(len(RECORD_COMMANDS))]
            name, data = corrupt_record(rng)
            cases.append({"kind": "record", "argv": [cmd, *rest, "--record", name], "inputs": {name: data},
                          "expect": "refused_or_accepted", "timeout": 60})
        elif u < 0.47:
            name, data, what = degenerate_record(rng)
            argv = DEGENERATE_COMMANDS[rng.integers(len(DEGENERATE_COMMANDS))]
            cases.append({"kind": f"degenerate-{what}", "argv": argv, "inputs": {name: data}, "expect": "refused",
                          "timeout": 60})
        elif u < 0.67:
            cases.append({"kind": "combination", "argv": COMBINATIONS[rng.integers(len(COMBINATIONS))],
                          "inputs": dict(common), "expect": "refused", "timeout": 60})
        elif u < 0.90:
            rest, opt, what = OUTPUTS[rng.integers(len(OUTPUTS))]
            bad = BAD_OUTPUTS[what]
            cases.append({"kind": "output", "argv": [*rest, opt, bad[rng.integers(len(bad))]], "inputs": dict(common),
                          "expect": "refused", "timeout": 60})
        else:
            kind = ["map", "fragility"][rng.integers(2)]
            argv, disagree = STUDIES[kind]
            truth = studies[kind][1] if kind in studies else None
            how = ["bare", "same", "disagree"][rng.integers(3)]
            extra = {"bare": [], "same": argv[1:], "disagree": disagree[rng.integers(len(disagree))]}[how]
            cases.append({"kind": f"resume-{kind}-{how}", "argv": [kind, "--resume", "s.h5", "--json", *extra],
                          "inputs": {"s.h5": (kind, int(rng.integers(2)))}, "study": kind, "truth": truth,
                          "study_file": "s", "expect": "refused" if how == "disagree" else "resumed", "timeout": 300})
    return cases


def verdict(r: dict) -> str:
    """ok, or what went wrong with a case."""
    if r["rc"] is None:
        return "hang"
    if r["traceback"]:
        return "traceback"
    # a run that ends well leaves its results; a refused one nothing, and no run a lock, a .part or an engine's folder
    if [f for f in r["files_left"] if r["rc"] != 0 or f.endswith((".lock", ".part")) or f.startswith(".tmp/")]:
        return "leftover"
    if r["expect"] == "refused":
        if r["rc"] == 0:
            return "ok-warned" if r["warned"] else "ignored"
        return "ok" if r["rc"] == 2 and r["stderr_lines"] == 1 else "not-one-line"
    if r["expect"] == "resumed":
        return "ok" if r["rc"] == 0 and r["same"] else "resume-differs"
    if r["rc"] == 2:
        return "ok" if r["stderr_lines"] == 1 else "not-one-line"
    return "ok-accepted" if r["rc"] == 0 else "other-exit"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=500)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--kinds", default=None, help="run only these kinds of the n cases (comma-separated, e.g. output,record)")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    t0 = time.perf_counter()
    kinds = None if a.kinds is None else set(a.kinds.split(","))
    studies = {}
    if kinds is None or "resume" in kinds:
        with tempfile.TemporaryDirectory() as work:
            studies = _prepare_studies(Path(work))
    cases = make_cases(a.n, rng, studies)
    if kinds is not None:  # the same cases as the full run, drawn the same way, only some of them run
        cases = [c for c in cases if c["kind"].split("-")[0] in kinds]
    for c in cases:
        c["studies"] = studies
    with ThreadPoolExecutor(a.workers) as ex:
        rows = list(ex.map(run, cases))
    for r in rows:
        r["verdict"] = verdict(r)
    table: dict = {}
    for r in rows:
        kind = r["kind"].split("-")[0] if not r["kind"].startswith("resume") else "resume"
        t = table.setdefault(kind, Counter())
        t["cases"] += 1
        t[r["verdict"]] += 1
    res = {"n": len(rows), "wall_s": time.perf_counter() - t0,
           "tracebacks": sum(r["verdict"] == "traceback" for r in rows), "hangs": sum(r["verdict"] == "hang" for r in rows),
           "leftovers": sum(r["verdict"] == "leftover" for r in rows),
           "options_ignored": sum(r["verdict"] == "ignored" for r in rows),
           "resumes_differing": sum(r["verdict"] == "resume-differs" for r in rows),
           "not_one_line": sum(r["verdict"] == "not-one-line" for r in rows),
           "other_exit": sum(r["verdict"] == "other-exit" for r in rows),
           "slowest_refusal_s": max((r["wall_s"] for r in rows if r["rc"] == 2), default=0.0),
           "by_kind": {k: dict(v) for k, v in table.items()},
           "problems": [r for r in rows if not r["verdict"].startswith("ok")],
           "accepted_cases": [r["argv"] for r in rows if r["verdict"] == "ok-accepted"]}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "fuzz_cli.json").write_text(json.dumps(res, indent=1))
    print({k: v for k, v in res.items() if k not in ("problems", "accepted_cases", "by_kind")})
    for k, v in res["by_kind"].items():
        print(f"  {k:<12}", dict(v))
    for r in res["problems"][:40]:
        print(r["verdict"], r["rc"], r["stderr_lines"], r["files_left"][:3], " ".join(x[:60] for x in r["argv"]), "|",
              r["err"][:150])


if __name__ == "__main__":
    main()
