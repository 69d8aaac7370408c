"""``archdem compare-shake``: the engines' shake study (:mod:`dem.experiments.compare_engines.shake`):
thresholds and bands of one-cycle sines per specimen, frequency, engine, time step and friction, in a
resumable study file, with each feature classified as common to the engines or not.

The library call is :meth:`~dem.experiments.compare_engines.shake.ShakeStudySpec.run`."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, default_of, print_json, study_definition, study_stopped
from dem.experiments.compare_engines.shake import ShakeStudySpec, study_cases
from dem.experiments.contract import add_spec_options, spec_from_args
from dem.studies.files import study_file


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import StudyInterrupted

    spec = spec_from_args(ShakeStudySpec, args, config=args.config)
    path, resume = study_file(args.out, args.resume, "runs/compare-shake", "compare-shake")
    try:
        res = spec.run(path, resume, args.workers, args.scheduler, not args.json, study_definition(args))
    except (StudyInterrupted, KeyboardInterrupt) as exc:
        return study_stopped(path, exc)
    if args.json:
        print_json(res.describe())
        return 0
    print("\n".join(res.lines()))
    return 0 if not res.failed else 1


def register(sub) -> None:
    p = sub.add_parser("compare-shake", help="thresholds and bands of one-cycle sines from several engines, per feature "
                                             "common or not",
                       description="The engines' shake study: the least collapsing amplitude of a one-cycle sine and "
                                   "every band above it, per specimen, frequency, engine, time step and friction case "
                                   "(a resumable study file and a CSV); each feature (first threshold, low collapse "
                                   "band, survival band, upper edge) classified as common to the engines or not.")
    add_spec_options(p, ShakeStudySpec)
    add_options(p, "compare-shake", config=default_of(study_cases, "config"))
    p.set_defaults(func=_run)
