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
  with its original arguments, with none, or with one that disagrees;
* ``interrupt``: a small map or fragility study, or a quick campaign of one cheap step, stopped at a random
  instant by SIGINT, SIGTERM (to its process group, as a terminal and ``timeout`` send them) or SIGKILL,
  then resumed: the resume ends with exit 0 and the uninterrupted run's answer, and nothing is left over
  (a lock, a ``.part`` folder, a spare copy, a leaked-semaphore warning);
* ``oversized``: a record of 10 million samples, ``/dev/zero``, an endless FIFO or pipe, a record
  longer than 1200 s, a drawing 5e9 m across or of 5000 blocks: refused in one line under 1 s of CPU time;
* ``mutated``: truncated and byte-mutated copies of the shipped drawing, of drawings written by
  ``write_assembly`` and of the test records, read by ``analytic``/``tilt --geometry`` and ``record``:
  read or refused in one line, never a traceback or a library's warning;
* ``pairs``: a (command, option) pair of the option table where the option does not apply (a command
  without it, or a context where its condition fails), given by hand: refused in one line.

Writes benchmarks/results/fuzz_cli.json (``--results``: another name there).

    python benchmarks/fuzz_cli.py [--n 500] [--seed 1] [--workers 2] [--kinds interrupt,pairs] [--every-pair]
"""
from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import h5py
import numpy as np

OUT = Path(__file__).resolve().parent / "results"
ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the pairs' contexts are the applicability test's
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


#: The interrupted commands (cheap: a two-case map, a two-case fragility study, a campaign of the catalogue
#: step), each with the file or folder it writes: the map and fragility ones are the resumed studies'.
CAMPAIGN = ["campaign", "--quick", "--steps", "catalogue", "--specimens", "Sh02-Sd020"]
INTERRUPTED = {"map": (STUDIES["map"][0], "s.h5"), "fragility": (STUDIES["fragility"][0], "s.h5"),
               "campaign": (CAMPAIGN, "c")}
STOPS = {"SIGINT": signal.SIGINT, "SIGTERM": signal.SIGTERM, "SIGKILL": signal.SIGKILL}


def _campaign_answer(folder: Path):
    """A campaign's answer: its steps and the contents of their tables."""
    m = json.loads((folder / "campaign.json").read_text())
    return {name: {t["csv"]: (folder / t["csv"]).read_text() for t in step["outputs"].get("tables", [])}
            for name, step in m["steps"].items()}


def run_interrupt(case: dict) -> dict:
    """Stop a study at ``case["at"]`` s with ``case["sig"]``, then resume it: the stop's and the resume's exit
    codes and stderr, whether the resume gives the uninterrupted answer, what is left over."""
    kind, sig = case["study"], STOPS[case["sig"]]
    argv, target = INTERRUPTED[kind]
    with tempfile.TemporaryDirectory() as tmp:
        private = Path(tmp) / ".tmp"
        private.mkdir()
        env = {**os.environ, "TMPDIR": str(private)}
        first = archdem([*argv, "--out", target] + (["--json"] if kind != "campaign" else []), tmp, env, 600,
                        stop=(sig, case["at"]))
        if sig == signal.SIGKILL:
            time.sleep(2.0)  # its workers end within a second of their parent (they watch it)
        if kind != "campaign" and Path(tmp, target).exists():
            again = [kind, "--resume", target, "--json"]
        else:  # nothing to resume (stopped before the study's file): the command again, as its user would
            again = [*argv, "--out", target] + (["--json"] if kind != "campaign" else [])
        second = archdem(again, tmp, env, 600)
        try:
            same = (_campaign_answer(Path(tmp, target)) if kind == "campaign" else _answer(kind, second["out"])) \
                == case["truth"]
        except (ValueError, KeyError, TypeError, OSError):
            same = False
        left = sorted(str(f.relative_to(tmp)) for f in Path(tmp).rglob("*")
                      if f.name.startswith(".") and f.name != ".tmp" or f.name.endswith((".lock", ".part", ".spare"))
                      or str(f.relative_to(tmp)).startswith(".tmp/"))
    lines1 = [ln for ln in first["err"].splitlines() if ln.strip() and "pybullet build time" not in ln]
    lines2 = [ln for ln in second["err"].splitlines() if ln.strip() and "pybullet build time" not in ln]
    return {"kind": f"interrupt-{kind}-{case['sig']}", "argv": argv, "at_s": case["at"], "expect": "resumed",
            "stop_rc": first["rc"], "stop_err": lines1[-3:], "stop_traceback": "Traceback" in first["err"],
            "stop_leaked": any("leaked" in ln for ln in lines1), "rc": second["rc"], "stderr_lines": len(lines2),
            "traceback": "Traceback" in second["err"], "leaked": any("leaked" in ln for ln in lines2),
            "files_left": left, "wall_s": first["wall_s"] + second["wall_s"], "cpu_s": second["cpu_s"], "same": same,
            "warned": False, "err": lines2[-1] if lines2 else "", "foreign": _foreign(lines2)[:3], "stdout": ""}


def interrupt_verdict(r: dict) -> str:
    """ok, or what went wrong with a stop and its resume."""
    if r["rc"] is None or r["stop_rc"] is None:
        return "hang"
    if r["stop_traceback"] or r["traceback"]:
        return "traceback"
    if r["leaked"] or r["files_left"] or (r["stop_leaked"] and r["kind"].split("-")[-1] != "SIGKILL"):
        return "leftover"
    sig = STOPS[r["kind"].split("-")[-1]]
    # Ctrl-C and SIGTERM: 130 and 143 with one line (or 0: the run had ended); SIGKILL: killed
    # (killed by the signal itself: it came before the program took it over, while Python started; nothing to clean)
    if sig != signal.SIGKILL and (r["stop_rc"] not in (0, 128 + sig, -sig) or r["stop_rc"] == 128 + sig
                                  and len(r["stop_err"]) != 1):
        return "stop-not-clean"
    return "ok" if r["rc"] == 0 and r["same"] else "resume-differs"


def _answer(kind: str, out: str):
    """The part of a study's JSON answer that must not depend on an interruption."""
    d = json.loads(out)
    if kind == "map":
        return [[(p["mu"], p["lambda"], p["mode"]) for p in s["points"]] for s in d]
    return [[(p["intensity"], p["n_collapsed"], p["n_runs"], p["modes"]) for p in c["points"]] for c in d["curves"]]


def archdem(argv: list[str], cwd: str, env: dict, timeout: float, stop: tuple[int, float] | None = None,
            feed: bytes | None = None) -> dict:
    """Run ``archdem argv`` in its own session: exit code (None: killed at ``timeout``, with its whole group),
    stdout, stderr, wall and CPU seconds; ``stop``: ``(signal, after s)``, SIGINT/SIGTERM to its group,
    SIGKILL to it alone; ``feed``: written to its stdin over and over until it closes it."""
    with tempfile.TemporaryFile() as fo, tempfile.TemporaryFile() as fe:
        t0 = time.perf_counter()
        p = subprocess.Popen([sys.executable, "-m", "dem.cli", *argv], cwd=cwd, env=env, stdout=fo, stderr=fe,
                             stdin=subprocess.PIPE if feed else subprocess.DEVNULL, start_new_session=True)
        if feed:
            threading.Thread(target=_endless, args=(p.stdin, feed), daemon=True).start()
        status, usage, stopped = None, None, False
        while True:
            pid, st, ru = os.wait4(p.pid, os.WNOHANG)
            if pid:
                status, usage = st, ru
                break
            now = time.perf_counter() - t0
            if stop and not stopped and now >= stop[1]:
                stopped = True
                if stop[0] == signal.SIGKILL:
                    os.kill(p.pid, signal.SIGKILL)
                else:
                    os.killpg(p.pid, stop[0])
            if now > timeout:
                with contextlib.suppress(ProcessLookupError):
                    os.killpg(p.pid, signal.SIGKILL)
                _, st, ru = os.wait4(p.pid, 0)
                usage = ru
                break
            time.sleep(0.02)
        p.returncode = 0  # reaped here: Popen must not wait for it again
        wall = time.perf_counter() - t0
        fo.seek(0)
        fe.seek(0)
        return {"rc": None if status is None else os.waitstatus_to_exitcode(status),
                "out": fo.read().decode(errors="replace"), "err": fe.read().decode(errors="replace"), "wall_s": wall,
                "cpu_s": usage.ru_utime + usage.ru_stime, "signalled": stopped}


def _endless(pipe, chunk: bytes) -> None:
    """Write ``chunk`` into ``pipe`` until its reader closes it (an endless stream)."""
    with contextlib.suppress(OSError, ValueError):
        while True:
            pipe.write(chunk)


def _fifo_writer(path: Path, chunk: bytes) -> threading.Thread:
    """An endless writer of the FIFO ``path``, once a reader opens it."""
    def write() -> None:
        with contextlib.suppress(OSError):
            with open(path, "wb") as fh:
                _endless(fh, chunk)
    t = threading.Thread(target=write, daemon=True)
    t.start()
    return t


def _unblock(fifo: Path) -> None:
    """Let a FIFO's writer go when nobody opened it: open its reading end, close it."""
    with contextlib.suppress(OSError):
        os.close(os.open(fifo, os.O_RDONLY | os.O_NONBLOCK))


#: Lines a library or Python prints (a warning, a leaked semaphore): never on archdem's stderr.
def _foreign(lines: list[str]) -> list[str]:
    return [ln for ln in lines if not ln.startswith("archdem") or "Warning" in ln or "leaked" in ln]


def run(case: dict) -> dict:
    if case["kind"].startswith("interrupt"):
        return run_interrupt(case)
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
        fifo, writer = None, None
        if case.get("fifo"):
            fifo = Path(tmp) / case["fifo"]
            os.mkfifo(fifo)
            writer = _fifo_writer(fifo, STREAM_CHUNK)
        r = archdem(argv, tmp, env, case["timeout"], feed=STREAM_CHUNK if case.get("stdin") else None)
        if fifo is not None:
            _unblock(fifo)
            writer.join(5)
        rc, err, out, wall = r["rc"], r["err"], r["out"], r["wall_s"]
        # the same command refused for a missing file: its start (imports) is not the reading's cost
        base = archdem(case["baseline"], tmp, env, case["timeout"])["cpu_s"] if case.get("baseline") else 0.0
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
    if expect == "read_or_refused" and (rc == 0 or rc is None and case.get("running_ok")):
        allowed = lambda f: not f.startswith(".tmp/") or rc is None  # noqa: E731 (a read file's run made these)
    left = [f for f in made if (not allowed(f) or f.endswith((".lock", ".part"))) and f != case.get("fifo")]
    lines = [ln for ln in err.splitlines() if ln.strip() and "pybullet build time" not in ln]
    return {"kind": case["kind"], "argv": argv, "expect": expect, "rc": rc, "stderr_lines": len(lines),
            "traceback": "Traceback" in err, "files_left": left, "wall_s": wall, "cpu_s": r["cpu_s"], "same": same,
            "warned": any("warning" in ln.lower() for ln in lines), "err": lines[-1] if lines else "",
            "foreign": _foreign(lines)[:3], "running_ok": bool(case.get("running_ok")), "cpu_limit": case.get("cpu_limit"),
            "start_cpu_s": base,
            "names": case.get("names"), "stdout": out[-200:]}


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


#: An endless stream of valid CSV samples (a FIFO's or a pipe's).
STREAM_CHUNK = b"".join(b"0.01,0.1\n" for _ in range(4096))
#: Record commands of the oversized and mutated kinds ("F": the record file).
OVERSIZED_RECORD_COMMANDS = [["record", "F"], ["shake", *ARCH, "--record", "F", "--scale", "1", "--out", "s"],
                             ["rock", *ARCH, "--record", "F", "--scale", "1"],
                             ["fragility", "--block", "0.05", "0.2", "--records", "F", "--im", "pga", "--stripes", "0.3",
                              "--realizations", "1"]]
#: Drawing commands of the oversized kind (refused before any work) and of the mutated kind.
DRAWING_COMMANDS = [["analytic", "--geometry", "F"], ["tilt", "--geometry", "F", "--out", "t"],
                    ["draw", "--geometry", "F", "--out", "d.png"], ["mesh", "--geometry", "F", "--out", "m"]]
#: Mutated drawings: analytic reads them to the end; tilt until it has read them (its run is cut, not a hang).
MUTATED_COMMANDS = [(["analytic", "--geometry", "F", "--depth", "0.1"], 60, False),
                    (["tilt", "--geometry", "F", "--depth", "0.1", "--out", "t"], 20, True)]
NOISE = [b"", b"-", b"nan", b"inf", b"1e999", b"-1e308", b"0", b"\x00", b"\xff\xfe", b"\n", b"0\nSECTION\n", b"x",
         b",", b"#", b"NPTS=", b"9999999999"]


def oversized_inputs(work: Path) -> dict[str, tuple[str, str]]:
    """The oversized inputs, made once in ``work``: name -> (path or special, kind: record or drawing)."""
    n = 10_000_000
    compact = work / "samples10M.csv"  # under 64 MB: refused by its count of samples
    with open(compact, "wb") as fh:
        fh.write(b"t [s],a [g]\n" + b"0,0\n" * n)
    timed = work / "timed10M.csv"  # 10 M samples with their times: refused by its size
    with open(timed, "w") as fh:
        fh.write("t [s],a [g]\n")
        for k in range(0, n, 100_000):
            fh.write("".join(f"{j * 0.01:.2f},0.1\n" for j in range(k, k + 100_000)))
    longer = work / "long1500s.csv"
    longer.write_text("t [s],a [g]\n" + "".join(f"{k * 0.01:.2f},{0.1 * math.sin(k * 0.3):.4f}\n"
                                                   for k in range(150_001)))
    header = work / "npts10M.AT2"  # a header announcing 10 M samples (the reader believes no count it cannot hold)
    header.write_text("PEER NGA STRONG MOTION DATABASE RECORD\nfuzz\nACCELERATION TIME SERIES IN UNITS OF G\n"
                      "NPTS=10000000, DT= .0100 SEC\n" + "  .1000000E-01" * 5 + "\n")
    wide = work / "wide5e9.csv"
    wide.write_text("block,x,z,layer\n" + "".join(f"b,{x},{z},depth 0.1\n" for x, z in ((0, 0), (5e9, 0), (5e9, 1),
                                                                                           (0, 1))))
    many = work / "blocks5000.csv"
    many.write_text("block,x,z,layer\n" + "".join(f"b{k},{x},{z},depth 0.1\n" for k in range(5000)
                                                   for x, z in ((k * 0.2, 0), (k * 0.2 + 0.1, 0), (k * 0.2 + 0.1, 0.1),
                                                                (k * 0.2, 0.1))))
    import ezdxf  # the same two drawings as DXF

    for name, boxes in (("wide5e9", [[(0, 0), (5e9, 0), (5e9, 1), (0, 1)]]),
                        ("blocks5000", [[(k * 0.2, 0), (k * 0.2 + 0.1, 0), (k * 0.2 + 0.1, 0.1), (k * 0.2, 0.1)]
                                        for k in range(5000)])):
        doc = ezdxf.new(units=6)
        for box in boxes:
            doc.modelspace().add_lwpolyline(box, close=True, dxfattribs={"layer": "blocks depth 0.1"})
        doc.saveas(work / f"{name}.dxf")
    return {"samples10M": (str(compact), "record"), "timed10M": (str(timed), "record"), "devzero": ("/dev/zero", "record"),
            "fifo": ("FIFO", "record"), "stdin": ("/dev/stdin", "record"), "long1500s": (str(longer), "record"),
            "npts10M": (str(header), "record"), "wide5e9": (str(wide), "drawing"), "blocks5000": (str(many), "drawing"),
            "wide5e9dxf": (str(work / "wide5e9.dxf"), "drawing"), "blocks5000dxf": (str(work / "blocks5000.dxf"), "drawing")}


def mutation_sources() -> dict[str, bytes]:
    """The valid files the mutated kind damages: the shipped drawing, a catalogue arch on piers written as DXF,
    CSV and OBJ, and the test records."""
    # deferred: the fuzz's other kinds need no library of the project in this process
    from specimens import Piers, discretise, get_specimen
    from specimens.exchange import EXAMPLE_DRAWING, write_assembly

    out = {"survey.dxf": EXAMPLE_DRAWING.read_bytes()}
    asm = discretise(get_specimen("Sh06-Sd015").arch, piers=Piers(0.3, 0.1, courses=2))
    with tempfile.TemporaryDirectory() as d:
        for fmt in ("dxf", "csv", "obj"):
            out[f"arch.{fmt}"] = write_assembly(asm, Path(d) / f"arch.{fmt}").read_bytes()
    for f in sorted(RECORDS.iterdir()):
        if f.suffix.lower() in (".at2", ".smc"):
            out[f.name] = f.read_bytes()
    return out


def mutate(raw: bytes, rng: np.random.Generator) -> tuple[str, bytes]:
    """``raw`` truncated, or with a span replaced by noise, deleted or duplicated."""
    how = ["truncate", "replace", "delete", "duplicate"][rng.integers(4)]
    at = int(rng.integers(len(raw) + 1))
    span = int(rng.integers(1, 64))
    if how == "truncate":
        return how, raw[:at]
    if how == "replace":
        return how, raw[:at] + NOISE[rng.integers(len(NOISE))] + raw[at + span:]
    if how == "delete":
        return how, raw[:at] + raw[at + span:]
    return how, raw[:at + span] + raw[at:]


def option_pairs() -> list[tuple[str, str, list[str]]]:
    """Every (command, option) pair of the option table where the option does nothing: a command that has no
    such option, or one whose condition fails in one of the applicability test's contexts; with its argv."""
    from dem.common.options import OPTIONS
    from tests.dem.cli.test_applicability import CASES, _applies, _argv, _parsed

    commands = sorted({c for o in OPTIONS for c in o.where})
    absent = [(c, o.dest, _argv(c, o.dest, 0)) for o in OPTIONS for c in commands if c not in o.where]
    unused = sorted({(c, d, k) for c, d, k in CASES if not _applies(c, d, _parsed(_argv(c, d, k)))})
    return absent + [(c, d, _argv(c, d, k)) for c, d, k in unused]


def make_cases(n: int, rng: np.random.Generator, studies: dict, sources: dict | None = None) -> list[dict]:
    rec_csv = ("t [s],a [g]\n" + "\n".join(f"{k * 0.01:.2f},{0.3 * math.sin(k * 0.5):.6g}" for k in range(300))
               + "\n").encode()
    common = {"old.png": b"old", "old.html": b"old", "old.h5": b"old", "rec.csv": rec_csv}
    cases = []
    sources = sources or {}  # the inputs of the later kinds (oversized files, mutated sources, pairs)
    for k in range(n):
        u = rng.random()
        if u >= 0.70:  # the kinds added later, drawn from their own generator's stream
            cases.append(_new_case(u, rng, studies, sources))
            continue
        u = u / 0.70  # the first kinds, in their first proportions
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


def _new_case(u: float, rng: np.random.Generator, studies: dict, sources: dict) -> dict:
    """One case of the kinds interrupt (u < 0.76), oversized (< 0.84), mutated (< 0.92) or pairs."""
    if u < 0.76:
        kind = ["map", "fragility", "campaign"][rng.integers(3)]
        sig = ["SIGINT", "SIGTERM", "SIGKILL"][rng.integers(3)]
        truth, wall = studies.get(f"interrupt-{kind}", (None, 10.0))
        return {"kind": f"interrupt-{kind}-{sig}", "study": kind, "sig": sig, "at": float(rng.uniform(0, 1.1 * wall)),
                "truth": truth, "expect": "resumed", "inputs": {}, "argv": INTERRUPTED[kind][0], "timeout": 600}
    if u < 0.84:
        big = sources.get("oversized", {})
        names = sorted(big) or ["devzero"]
        name = names[rng.integers(len(names))]
        path, what = big.get(name, ("/dev/zero", "record"))
        cmds = OVERSIZED_RECORD_COMMANDS if what == "record" else DRAWING_COMMANDS
        cmd = cmds[rng.integers(len(cmds))]
        argv = [path if a == "F" else a for a in cmd]
        missing = "missing" + (Path(path).suffix if what == "drawing" else ".csv")
        return {"kind": f"oversized-{name}", "argv": argv, "inputs": {}, "expect": "refused", "timeout": 60,
                "cpu_limit": 1.0, "baseline": [missing if a == "F" else a for a in cmd], "fifo": "big.fifo" if path == "FIFO" else None, "stdin": path == "/dev/stdin",
                **({"argv": ["big.fifo" if a == "FIFO" else a for a in argv]} if path == "FIFO" else {})}
    if u < 0.92:
        src = sources.get("mutated", {})
        name = sorted(src)[rng.integers(len(src))] if src else "survey.dxf"
        how, data = mutate(src.get(name, b""), rng)
        if name.lower().endswith((".at2", ".smc")):
            argv, timeout, running_ok = ["record", "F"], 60, False
        else:
            argv, timeout, running_ok = MUTATED_COMMANDS[rng.integers(len(MUTATED_COMMANDS))]
        return {"kind": f"mutated-{how}", "argv": [name if a == "F" else a for a in argv], "inputs": {name: data},
                "expect": "read_or_refused", "timeout": timeout, "running_ok": running_ok}
    pairs = sources.get("pairs", [])
    command, dest, argv = pairs[rng.integers(len(pairs))] if pairs else ("map", "id", ["map", "x"])
    return {"kind": "pairs", "argv": argv, "inputs": {}, "expect": "refused", "timeout": 60, "names": [command, dest]}


def verdict(r: dict) -> str:
    """ok, or what went wrong with a case."""
    if r["kind"].startswith("interrupt"):
        return interrupt_verdict(r)
    if r["rc"] is None:
        return "ok-running" if r.get("running_ok") and not r["traceback"] and not r.get("foreign") else "hang"
    if r["traceback"]:
        return "traceback"
    if r.get("foreign") and r["expect"] == "read_or_refused":
        return "library-warning"
    if r.get("cpu_limit") and r["rc"] == 2 and r["cpu_s"] - r["start_cpu_s"] > r["cpu_limit"]:
        return "slow-refusal"
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


def _prepare_interrupts(work: Path) -> dict:
    """Each interrupted command once, uninterrupted: its answer and its wall time (the stops fall within it)."""
    out = {}
    for kind, (argv, target) in INTERRUPTED.items():
        folder = work / kind
        folder.mkdir()
        r = archdem([*argv, "--out", target] + (["--json"] if kind != "campaign" else []), str(folder),
                    dict(os.environ), 900)
        if r["rc"] != 0:
            raise SystemExit(f"the {kind} command did not run: {r['err'][-500:]}")
        out[f"interrupt-{kind}"] = (_campaign_answer(folder / target) if kind == "campaign" else _answer(kind, r["out"]),
                                    r["wall_s"])
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=500)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--kinds", default=None, help="run only these kinds of the n cases (comma-separated, e.g. output,record)")
    ap.add_argument("--every-pair", action="store_true", help="add every pair of the pairs kind once, beside the n cases")
    ap.add_argument("--results", default="fuzz_cli.json", help="file name of the results, in benchmarks/results")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    t0 = time.perf_counter()
    kinds = None if a.kinds is None else set(a.kinds.split(","))
    studies = {}
    with tempfile.TemporaryDirectory() as work:
        if kinds is None or "resume" in kinds:
            studies = _prepare_studies(Path(work))
        if kinds is None or "interrupt" in kinds:
            studies |= _prepare_interrupts(Path(work))
        pairs = option_pairs()
        sources = {"oversized": oversized_inputs(Path(work)) if kinds is None or "oversized" in kinds else {},
                 "mutated": mutation_sources(), "pairs": pairs}
        cases = make_cases(a.n, rng, studies, sources)
        if kinds is not None:  # the same cases as the full run, drawn the same way, only some of them run
            cases = [c for c in cases if c["kind"].split("-")[0] in kinds]
        if a.every_pair:
            cases += [{"kind": "pairs", "argv": argv, "inputs": {}, "expect": "refused", "timeout": 60,
                       "names": [c, d]} for c, d, argv in pairs]
        for c in cases:
            c["studies"] = studies
        with ThreadPoolExecutor(a.workers) as ex:
            rows = list(ex.map(run, cases))
    for r in rows:
        r["verdict"] = verdict(r)
    table: dict = {}
    for r in rows:
        kind = r["kind"].split("-")[0]
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
           "slowest_refusal_cpu_s": max((r["cpu_s"] for r in rows if r["rc"] == 2), default=0.0),
           "oversized_refusal_cpu_s": max((r["cpu_s"] for r in rows if r["kind"].startswith("oversized")), default=0.0),
           "oversized_refusal_wall_s": max((r["wall_s"] for r in rows if r["kind"].startswith("oversized")), default=0.0),
           "library_warnings": sum(r["verdict"] == "library-warning" for r in rows),
           "slow_refusals": sum(r["verdict"] == "slow-refusal" for r in rows),
           "stops_not_clean": sum(r["verdict"] == "stop-not-clean" for r in rows),
           "by_kind": {k: dict(v) for k, v in table.items()},
           # how the stops ended (0: the run had ended first; -N: killed by signal N before Python handed it over)
           "interrupt_stops": {k: dict(Counter(r["stop_rc"] for r in rows if r["kind"].endswith(k) and "stop_rc" in r))
                               for k in STOPS},
           "interrupt_resumed_from": dict(Counter(r["kind"] for r in rows if r["kind"].startswith("interrupt"))),
           "pairs_refused_by": dict(Counter("usage (no such option)" if "unrecognized arguments" in r["err"] else
                                            "the table (does nothing here)" if "does nothing here" in r["err"] else
                                            f"other: {r['err'][:80]}" for r in rows if r["kind"] == "pairs" and r["rc"] == 2)),
           # CPU seconds of the refusal: the whole process, and beyond the same command's start
           "oversized_by_input": {k: [max(r["cpu_s"] for r in rows if r["kind"] == k),
                                      max(r["cpu_s"] - r["start_cpu_s"] for r in rows if r["kind"] == k)] for k in
                                  sorted({r["kind"] for r in rows if r["kind"].startswith("oversized")})},
           "problems": [r for r in rows if not r["verdict"].startswith("ok")],
           "accepted_cases": [r["argv"] for r in rows if r["verdict"] == "ok-accepted"]}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / a.results).write_text(json.dumps(res, indent=1))
    print({k: v for k, v in res.items() if k not in ("problems", "accepted_cases", "by_kind")})
    for k, v in res["by_kind"].items():
        print(f"  {k:<12}", dict(v))
    for r in res["problems"][:40]:
        print(r["verdict"], r["rc"], r["stderr_lines"], r["files_left"][:3], " ".join(x[:60] for x in r["argv"]), "|",
              r["err"][:150])


if __name__ == "__main__":
    main()
