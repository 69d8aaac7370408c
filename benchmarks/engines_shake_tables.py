"""Markdown tables of the engines' shake study (docs/validation.md#19-three-engine-shake-study) from
one or more study files of ``archdem compare-shake``: per friction case and specimen, a row per
frequency with each engine's first collapse and bands at each time step; then the features'
classes (common to the engines or not) counted and listed.

    python benchmarks/engines_shake_tables.py STUDY.h5 [STUDY.h5 ...] [--out FILE.md]
"""
from __future__ import annotations

import argparse
import math
from pathlib import Path

from dem.experiments.compare_engines.shake import bands, case_dt, class_counts, classify, pairwise, step_agreement
from dem.studies.sweep import load_study

SHORT = {"pybullet": "PB", "mujoco": "MJ", "lmgc90": "LM"}


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


def tables(records) -> str:
    # a study file may hold cases of another step definition (another dt for the same factor): left out
    ok = [r for r in records if r.ok and math.isclose(r.params["dt"], case_dt(r.params["engine"], r.params["step"]))]
    cols = sorted({(r.params["engine"], r.params["step"]) for r in ok},
                  key=lambda c: (list(SHORT).index(c[0]) if c[0] in SHORT else 9, -c[1]))
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
    sa = step_agreement(ok)
    if sa:
        names = list(next(iter(sa.values())))
        out += ["", "**Each engine at its two steps** (groups where the readings of both steps agree / groups run at "
                "both):", "", "| engine | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
        for e, v in sa.items():
            out.append(f"| {e} | " + " | ".join(f"{a} / {n}" for a, n in v.values()) + " |")
    return "\n".join(out) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("studies", nargs="+")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    records = [r for p in a.studies for r in load_study(p).records]
    text = tables(records)
    if a.out:
        Path(a.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
