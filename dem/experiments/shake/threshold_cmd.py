"""``archdem threshold``: the least collapsing amplitude of a one-cycle sine (amplitude scan and
bisection) and the survival bands above it."""
from __future__ import annotations

import argparse
import math

from analytic.motions.inputs import MIN_PEAK_ACCELERATION
from dem.common.options import default_of, print_json, workers_option
from dem.core.progress import terminal
from dem.experiments.shake.run import ShakeProtocol
from dem.experiments.shake.shake_cmd import (
    MAX_AMPLITUDE_G,
    MAX_SINE_HZ,
    add_shake_arguments,
    check_sine,
    model_and_settings,
)
from dem.experiments.shake.thresholds import SCAN_TOP, static_onset, threshold
from specimens.constants import G
from foundation.errors import ArchdemInputError


def _run_threshold(args: argparse.Namespace) -> int:
    check_sine(args)
    label, arch, _, model, settings = model_and_settings(args)
    lam = static_onset(model, settings)
    for name, v in (("--a-min", args.a_min), ("--a-max", args.a_max)):
        if v is not None and not (math.isfinite(v) and 0 < v <= MAX_AMPLITUDE_G):
            raise ArchdemInputError(f"{name} must be in (0, {MAX_AMPLITUDE_G:g}] g, got {v:g}")
    if not (math.isfinite(args.scan_ratio) and 1 < args.scan_ratio <= 10):
        raise ArchdemInputError(f"--scan-ratio must be in (1, 10], got {args.scan_ratio:g}")
    if not (math.isfinite(args.tol) and 1e-3 <= args.tol <= 0.5):
        raise ArchdemInputError(f"--tol must be a relative tolerance in [0.001, 0.5], got {args.tol}")
    with terminal(f"threshold {label} {args.sine:g} Hz", unit="runs", enabled=not args.json) as line:
        res = threshold(model, args.sine, settings, ShakeProtocol(tail=args.tail, load=args.load), a_min_g=args.a_min,
                        a_max_g=args.a_max, scan_ratio=args.scan_ratio, tol=args.tol, workers=args.workers,
                        scheduler=args.scheduler, progress=line)
    a_max = res.a_range_g[1]
    s = {"id": label, "lambda": lam, "config": args.config, "contact": model.source.get("contact", 1.0),
         "mu_joint": settings.mu_joint, "mu_base": settings.mu_base, **res.summary()}
    if args.json:
        print_json(s)
        return 0
    if res.amplitude_g is None:
        print(f"{label} {args.sine:g} Hz: no collapse up to {a_max:.3f} g ({res.n_sims} runs, {res.wall_s:.1f} s)")
        return 0
    above = ", ".join(f"{b['from_g']:.3f}-{b['to_g']:.3f} g" for b in res.survival_bands_above)
    print(f"{label} {args.sine:g} Hz: least collapsing amplitude {res.amplitude_g:.4f} g "
          f"(bracket {res.bracket_g[0]:.4f}-{res.bracket_g[1]:.4f}, {res.mode}, {res.phase}); static lambda {lam:.4f}"
          + (f"; survives again {above}" if above else "") + f"; {res.n_sims} runs, {res.wall_s:.1f} s")
    return 0


def register(sub) -> None:
    q = sub.add_parser("threshold", help="least collapsing one-cycle sine amplitude (scan + bisection)",
                       description="Least collapsing amplitude of a one-cycle sine: amplitude scan, bisection of "
                                   "the lowest collapsing bracket, and every survival band above it.")
    add_shake_arguments(q)
    q.add_argument("--sine", type=float, required=True, metavar="FREQ", help=f"sine frequency [Hz], up to {MAX_SINE_HZ:g}")
    q.add_argument("--a-min", dest="a_min", type=float, default=None, help=f"scan start [g], at least {MIN_PEAK_ACCELERATION / G:g} (default: static lambda)")
    q.add_argument("--a-max", dest="a_max", type=float, default=None, help=f"scan end [g] (default {SCAN_TOP:g} x start)")
    q.add_argument("--scan-ratio", dest="scan_ratio", type=float, default=default_of(threshold, "scan_ratio"),
                   help=f"scan step ratio (default {default_of(threshold, 'scan_ratio'):g})")
    q.add_argument("--tol", type=float, default=default_of(threshold, "tol"),
                   help=f"relative bisection tolerance (default {default_of(threshold, 'tol'):g})")
    q.add_argument("--workers", type=workers_option, default=None, help="processes for the scan (default: all cores)")
    q.add_argument("--scheduler", default=None, help="Dask scheduler address tcp://HOST:PORT (instead of local workers)")
    q.set_defaults(func=_run_threshold)
