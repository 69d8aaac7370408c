"""``archdem threshold``: the least collapsing amplitude of a one-cycle sine (amplitude scan and
bisection) and the survival bands above it.

The library call is :func:`dem.experiments.shake.thresholds.run` with a
:class:`~dem.experiments.shake.thresholds.ThresholdSpec` (or :func:`~dem.experiments.shake.thresholds.threshold`).
"""
from __future__ import annotations

import argparse
import math

from analytic.motions.inputs import MIN_PEAK_ACCELERATION
from dem.common.limits import MAX_SINE_HZ
from dem.common.options import default_of, print_json
from dem.core.progress import terminal
from dem.experiments.shake.run import ShakeProtocol
from dem.experiments.shake.shake_cmd import (
    add_shake_arguments,
    check_sine,
    model_and_settings,
    sine_fn,
)
from dem.experiments.shake.thresholds import SCAN_TOP, ThresholdSpec, run, static_onset, threshold
from specimens.constants import G
from foundation.errors import ArchdemInputError


def _run_threshold(args: argparse.Namespace) -> int:
    check_sine(args)
    label, arch, _, model, settings = model_and_settings(args)
    lam = static_onset(model, settings)
    if not (math.isfinite(args.scan_ratio) and 1 < args.scan_ratio <= 10):
        raise ArchdemInputError(f"--scan-ratio must be in (1, 10], got {args.scan_ratio:g}")
    if not (math.isfinite(args.tol) and 1e-3 <= args.tol <= 0.5):
        raise ArchdemInputError(f"--tol must be a relative tolerance in [0.001, 0.5], got {args.tol}")
    spec = ThresholdSpec(model, args.sine, settings, ShakeProtocol(tail=args.tail, load=args.load), args.a_min,
                         args.a_max, args.scan_ratio, args.tol, check=not args.no_check, motion_fn=sine_fn(args))
    with terminal(f"threshold {label} {args.sine:g} Hz", unit="runs", enabled=not args.json) as line:
        res = run(spec, args.workers, args.scheduler, progress=line)
    if args.json:
        print_json({"id": label, "lambda": lam, "config": args.config, "contact": model.source.get("contact", 1.0),
                    "mu_joint": settings.mu_joint, "mu_base": settings.mu_base, **res.summary()})
    else:
        print(res.text(label, lam))
    return 0


def register(sub) -> None:
    q = sub.add_parser("threshold", help="least collapsing one-cycle sine amplitude (scan + bisection)",
                       description="Least collapsing amplitude of a one-cycle sine: amplitude scan, bisection of "
                                   "the lowest collapsing bracket, and every survival band above it.")
    add_shake_arguments(q, "threshold")
    q.add_argument("--sine", type=float, required=True, metavar="FREQ", help=f"sine frequency [Hz], up to {MAX_SINE_HZ:g}")
    q.add_argument("--a-min", dest="a_min", type=float, default=None, help=f"scan start [g], at least {MIN_PEAK_ACCELERATION / G:g} (default: static lambda)")
    q.add_argument("--a-max", dest="a_max", type=float, default=None, help=f"scan end [g] (default {SCAN_TOP:g} x start)")
    q.add_argument("--scan-ratio", dest="scan_ratio", type=float, default=default_of(threshold, "scan_ratio"),
                   help=f"scan step ratio (default {default_of(threshold, 'scan_ratio'):g})")
    q.add_argument("--tol", type=float, default=default_of(threshold, "tol"),
                   help=f"relative bisection tolerance (default {default_of(threshold, 'tol'):g})")
    q.add_argument("--no-check", dest="no_check", action="store_true",
                   help="skip the settled-or-range check (the bracket rerun at half the step, and on LMGC90 at "
                        "6-8 Hz with sliding joints)")
    q.set_defaults(func=_run_threshold)
