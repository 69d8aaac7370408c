"""``archdem threshold``: the least collapsing amplitude of a one-cycle sine (amplitude scan and
bisection) and the survival bands above it.

The library call is :func:`dem.experiments.shake.thresholds.run` with a
:class:`~dem.experiments.shake.thresholds.ThresholdSpec` (or :func:`~dem.experiments.shake.thresholds.threshold`),
here the run spec of a :class:`~dem.experiments.shake.spec.ThresholdOptions`.
"""
from __future__ import annotations

import argparse

from dem.common.options import add_options, answer
from dem.core.progress import terminal
from dem.experiments.contract import add_spec_options, spec_from_args
from dem.experiments.shake.shake_cmd import model_and_settings
from dem.experiments.shake.spec import ThresholdOptions
from dem.experiments.shake.thresholds import run, static_onset


def _run_threshold(args: argparse.Namespace) -> int:
    opts = spec_from_args(ThresholdOptions, args, check=not args.no_check)
    label, _, _, model, settings = model_and_settings(args)
    lam = static_onset(model, settings)
    with terminal(f"threshold {label} {args.sine:g} Hz", unit="runs", enabled=not args.json) as line:
        res = run(opts.run_spec(model, settings), args.workers, args.scheduler, progress=line)
    answer(args.json, res.describe(label, lam, args.config, model, settings), [res.text(label, lam)])
    return 0


def register(sub) -> None:
    q = sub.add_parser("threshold", help="least collapsing one-cycle sine amplitude (scan + bisection)",
                       description="Least collapsing amplitude of a one-cycle sine: amplitude scan, bisection of "
                                   "the lowest collapsing bracket, and every survival band above it.")
    add_options(q, "threshold")
    add_spec_options(q, ThresholdOptions)
    q.set_defaults(func=_run_threshold)
