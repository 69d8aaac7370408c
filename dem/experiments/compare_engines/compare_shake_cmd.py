"""``archdem compare-shake``: the engines' shake study (:mod:`dem.experiments.compare_engines.shake`):
thresholds and bands of one-cycle sines per specimen, frequency, engine, time step and friction, in a
resumable study file, with each feature classified as common to the engines or not."""
from __future__ import annotations

import argparse
import csv
import math
from pathlib import Path

from dem.common.options import (
    add_options,
    default_of,
    parse_grid,
    print_json,
    study_definition,
    study_path,
    study_stopped,
)
from dem.core.engines import available_engines, check_engine
from dem.experiments.compare_engines.run import FRICTIONS
from dem.experiments.compare_engines.shake import (
    case_rows,
    class_counts,
    classify,
    pairwise,
    shake_case,
    step_agreement,
    study_attrs,
    study_cases,
    verdict_counts,
    verdicts,
)
from specimens.catalogue import select_specimens
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path


def _listed(values) -> str:
    return ",".join(v if isinstance(v, str) else f"{v:g}" for v in values)


def _names(text: str, what: str, allowed) -> tuple[str, ...]:
    names = tuple(t.strip() for t in text.split(",") if t.strip())
    if not names or len(set(names)) != len(names):
        raise ArchdemInputError(f"{what}: give distinct names separated by commas, got {text!r}")
    for n in names:
        if n not in allowed:
            raise ArchdemInputError(f"{what}: unknown {n!r}; one of {', '.join(allowed)}")
    return names


def write_csv(rows: list[dict], path: Path) -> Path:
    """One row per finished case, written whole (atomically) beside the study file."""
    with atomic_path(path, overwrite=True) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]) if rows else ["id"])
        w.writeheader()
        w.writerows(rows)
    return path


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import StudyInterrupted

    ids = [s.id for s in select_specimens(args.specimens)]
    engines = _names(args.engines, "--engines", available_engines())
    frictions = _names(args.friction, "--friction", tuple(FRICTIONS))
    steps = [float(s) for s in parse_grid(args.steps, "--steps")]
    freqs = parse_grid(args.freq)
    if any(not (0 < f <= 50) for f in freqs):
        raise ArchdemInputError(f"--freq: one-cycle sines from above 0 to 50 Hz, got {args.freq!r}")
    cases = study_cases(ids, freqs, engines, steps, frictions, args.config)
    for e in engines:
        check_engine(e)
    path, resume = study_path(args, "runs/compare-shake", "compare-shake")
    try:
        res = run_study_cases(cases, path, args, resume)
    except (StudyInterrupted, KeyboardInterrupt) as exc:
        return study_stopped(path, exc)
    rows, groups = case_rows(res.records), classify(res.records)
    pairs = {f"{s:g}": pairwise(res.records, s) for s in steps}
    steadiness = step_agreement(res.records)
    flags = verdicts(res.records)
    csv_path = write_csv(rows, Path(path).with_suffix(".csv"))
    failed = [f"{r.params['id']} {r.params['engine']} {r.params['freq']:g} Hz: {r.error.strip().splitlines()[-1]}"
              for r in res.failed]
    if args.json:
        print_json({"study": str(path), "csv": str(csv_path), "cases": rows, "features": groups,
                    "counts": class_counts(groups), "pairwise": pairs, "step_agreement": steadiness,
                    "verdicts": flags, "verdict_counts": verdict_counts(flags), "failed": failed})
        return 0
    print(f"{len(rows)} of {len(res)} cases -> {path} (table: {csv_path})")
    for r in rows:
        first = "none" if not math.isfinite(r["first_g"]) else f"{r['first_g']:.3f} g"
        print(f"{r['id']:<11} {r['friction']:<6} {r['freq']:4g} Hz {r['engine']:<8} x{r['step']:<4g} "
              f"first {first:<9} {r['bands']}")
    for name, counts in class_counts(groups).items():
        print(f"{name}: " + "; ".join(f"{f} " + ", ".join(f"{c} {k}" for k, c in sorted(v.items()))
                                     for f, v in counts.items()))
    for s, pw in pairs.items():
        for pair, v in pw.items():
            print(f"x{s} {pair} agree: " + ", ".join(f"{k} {a}/{n}" for k, (a, n) in v.items()))
    for e, v in steadiness.items():
        print(f"{e} at its steps agrees: " + ", ".join(f"{k} {a}/{n}" for k, (a, n) in v.items()))
    for v in flags:
        lo, hi = v["range_g"]
        rng = "" if v["status"] != "range" else f" {lo:.3f}-" + ("none" if hi is None else f"{hi:.3f}") + " g"
        print(f"{v['id']:<11} {v['friction']:<6} {v['freq']:4g} Hz default threshold {v['status']}{rng}"
              + (f" ({v['why']})" if v["why"] else ""))
    for f in failed:
        print(f"failed: {f}")
    return 0 if not failed else 1


def run_study_cases(cases: list[dict], path: str, args: argparse.Namespace, resume: bool):
    """The study's cases through the sweep engine (local cores or ``--scheduler``)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import run_study

    return run_study(cases, shake_case, path, workers=args.workers, scheduler=args.scheduler, resume=resume,
                     progress=not args.json, study_attrs=study_attrs(args.config), definition=study_definition(args))


def register(sub) -> None:
    p = sub.add_parser("compare-shake", help="thresholds and bands of one-cycle sines from several engines, per feature "
                                             "common or not",
                       description="The engines' shake study: the least collapsing amplitude of a one-cycle sine and "
                                   "every band above it, per specimen, frequency, engine, time step and friction case "
                                   "(a resumable study file and a CSV); each feature (first threshold, low collapse "
                                   "band, survival band, upper edge) classified as common to the engines or not.")
    d = {k: _listed(default_of(study_cases, k)) for k in ("ids", "engines", "freqs", "steps", "frictions")}
    p.add_argument("--specimens", default=d["ids"], help="all or comma-separated ids (default: the Sd 0.15 and 0.20 "
                                                         f"specimens, {d['ids']})")
    p.add_argument("--engines", default=d["engines"], help=f"engines (default {d['engines']})")
    p.add_argument("--freq", default=d["freqs"], help=f"sine frequencies [Hz] (default {d['freqs']})")
    p.add_argument("--steps", default=d["steps"], help=f"time steps as multiples of the default one (default {d['steps']})")
    p.add_argument("--friction", default=d["frictions"],
                   help="friction cases: " + ", ".join(f"{k} {v[0]:g}/{v[1]:g}" for k, v in FRICTIONS.items())
                        + f" (joint/base; default {d['frictions']})")
    add_options(p, "compare-shake", config=default_of(study_cases, "config"))
    p.set_defaults(func=_run)
