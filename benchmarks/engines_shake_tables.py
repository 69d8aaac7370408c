"""Markdown tables of the engines' shake study (docs/validation.md#19-three-engine-shake-study) from
one or more study files of ``archdem compare-shake``: per friction case and specimen, a row per
frequency with each engine's first collapse and bands at each time step; then the features'
classes (common to the engines or not) counted and listed; then, over every step in the files, how
often each engine's readings hold from one of its steps to the next and the first thresholds of
the groups where an engine moves with its step.

    python benchmarks/engines_shake_tables.py STUDY.h5 [STUDY.h5 ...] [--steps 1,0.5]
        [--moves mujoco,lmgc90] [--out FILE.md]

``--steps``: the steps of the tables by specimen and of the classes (default all in the files);
``--moves``: the engines of the last table (default all).
"""
from __future__ import annotations

import argparse
import math
from pathlib import Path

from dem.experiments.compare_engines.shake import (
    COMPARED,
    bands,
    case_dt,
    class_counts,
    classify,
    pairwise,
    step_agreement,
    step_moves,
)
from dem.studies.sweep import load_study

SHORT = {"pybullet": "PB", "mujoco": "MJ", "lmgc90": "LM"}
NAMES = {"pybullet": "PyBullet", "mujoco": "MuJoCo", "lmgc90": "LMGC90"}


def _cell(res: dict) -> str:
    first = res["amplitude_g"]
    head = "none" if not math.isfinite(first) else f"**{first:.3f}**"
    rest = []
    for b in bands(res)[1:]:
        if b["from_g"] <= first * (1 + 1e-9):
            continue
        mode = f" {b['modes'][0][0]}" if b["modes"] else ""
        rest.append(f"{'C' if b['collapse'] else 'S'}{b['from_g']:.2f}{mode}")
    m = f" {res['mode'][0]}" if math.isfinite(first) and res.get("mode") else ""
    return head + m + (" " + " ".join(rest) if rest else "")


def _value(v: float) -> str:
    return "none" if not math.isfinite(v) else f"{v:.3f}"


def _order(engine_step: tuple) -> tuple:
    return (list(SHORT).index(engine_step[0]) if engine_step[0] in SHORT else 9, -engine_step[1])


def tables(records, steps: set[float] | None = None, moves_of: tuple[str, ...] | None = None) -> str:
    # a study file may hold cases of another step definition (another dt for the same factor): left out
    every = [r for r in records if r.ok and math.isclose(r.params["dt"], case_dt(r.params["engine"], r.params["step"]))]
    ok = [r for r in every if steps is None or r.params["step"] in steps]
    cols = sorted({(r.params["engine"], r.params["step"]) for r in ok}, key=_order)
    out = []
    for fr in dict.fromkeys(r.params["friction"] for r in ok):
        mj, mb = next((r.params["mu_joint"], r.params["mu_base"]) for r in ok if r.params["friction"] == fr)
        for sid in dict.fromkeys(r.params["id"] for r in ok if r.params["friction"] == fr):
            rs = {(r.params["freq"], r.params["engine"], r.params["step"]): r.results for r in ok
                  if r.params["friction"] == fr and r.params["id"] == sid}
            lam = next(iter(rs.values()))["lambda"]
            top = next(iter(rs.values()))["a_max_g"]
            out += [f"**{sid}**, friction {fr} ({mj:g} / {mb:g}), lambda {lam:.3f}, scan to {top:.2f} g", "",
                    "| f [Hz] | " + " | ".join(f"{SHORT.get(e, e)} ×{s:g}" for e, s in cols) + " |",
                    "|---" * (len(cols) + 1) + "|"]
            for f in sorted({k[0] for k in rs}):
                out.append(f"| {f:g} | " + " | ".join(_cell(rs[(f, e, s)]) if (f, e, s) in rs else "–"
                                                     for e, s in cols) + " |")
            out.append("")
    groups = classify(ok)
    out += ["**Features by class** (groups of specimen and frequency with more than one engine):", "",
            "| friction | feature | common | step-dependent | engine-dependent |", "|---|---|---|---|---|"]
    for fr, feats in class_counts(groups).items():
        for name, c in feats.items():
            out.append(f"| {fr} | {name} | {c.get('common', 0)} | {c.get('step-dependent', 0)} | "
                       f"{c.get('engine-dependent', 0)} |")
    for step in sorted({r.params["step"] for r in ok}, reverse=True):
        pw = pairwise(ok, step)
        if not pw:
            continue
        names = list(next(iter(pw.values())))
        out += ["", f"**Engines two by two** at {step:g} × the default step (groups where both agree / both ran):", "",
                "| engines | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
        for pair, v in pw.items():
            out.append(f"| {pair} | " + " | ".join(f"{a} / {n}" for a, n in v.values()) + " |")
    finer = _finer_steps(every, moves_of)
    sa = step_agreement(ok)
    if sa and not finer:
        names = list(next(iter(sa.values())))
        out += ["", "**Each engine at its two steps** (groups where the readings of both steps agree / groups run at "
                "both):", "", "| engine | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
        for e, v in sa.items():
            out.append(f"| {e} | " + " | ".join(f"{a} / {n}" for a, n in v.values()) + " |")
    out += finer
    return "\n".join(out) + "\n"


def _finer_steps(records, moves_of) -> list[str]:
    """From one step to the next of each engine over every step in the files, and the groups where
    an engine's first threshold moves with its step."""
    by_engine: dict[str, set] = {}
    for r in records:
        by_engine.setdefault(r.params["engine"], set()).add(r.params["step"])
    if not any(len(s) > 2 for s in by_engine.values()):
        return []
    rows, by_pair = [], {}
    for e in sorted(by_engine, key=lambda e: _order((e, 0))):
        st = sorted(by_engine[e], reverse=True)
        for pair in zip(st, st[1:]):
            if pair not in by_pair:  # one count per pair of steps serves every engine
                by_pair[pair] = step_agreement(records, pair)
            coarse, fine = pair
            v = by_pair[pair].get(e)
            if v:
                rows.append(f"| {e} | ×{coarse:g} → ×{fine:g} | " + " | ".join(f"{a} / {n}" for a, n in v.values()) + " |")
    out = ["", "**From one step to the next** (groups where both steps' readings agree / groups run at both):", "",
           "| engine | steps | " + " | ".join(COMPARED) + " |", "|---" * (len(COMPARED) + 2) + "|", *rows]
    moves = step_moves(records, moves_of)
    if not moves:
        return out
    cols = sorted({k for m in moves for k in m["values"]}, key=_order)
    who = [NAMES.get(e, e) for e in sorted(moves_of or by_engine, key=lambda e: _order((e, 0)))]
    out += ["", "**Where an engine moves with its step**: first thresholds [g] of every group where "
            + " or ".join(who) + " reads it differently at two of its steps (\"none\": no collapse to the top "
            "of the scan; \"–\": not run):", "",
            "| group | " + " | ".join(f"{SHORT.get(e, e)} ×{s:g}" for e, s in cols) + " |", "|---" * (len(cols) + 1) + "|"]
    for m in sorted(moves, key=lambda m: (m["friction"], m["id"], m["freq"])):
        out.append(f"| {m['id']}, {m['freq']:g} Hz, {m['friction']} | "
                   + " | ".join(_value(m["values"][c]) if c in m["values"] else "–" for c in cols) + " |")
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("studies", nargs="+")
    ap.add_argument("--steps", default=None, help="steps of the tables by specimen, e.g. 1,0.5 (default: all)")
    ap.add_argument("--moves", default=None, help="engines of the table of moving groups, e.g. mujoco,lmgc90")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    records = [r for p in a.studies for r in load_study(p).records]
    steps = None if a.steps is None else {float(x) for x in a.steps.split(",")}
    text = tables(records, steps, None if a.moves is None else tuple(a.moves.split(",")))
    if a.out:
        Path(a.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
