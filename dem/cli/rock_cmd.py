"""``archdem rock``: one time history of a rocking linkage (analytic: the four-bar, the two-bar or a
block) under a pulse, a sine or a record."""
from __future__ import annotations

import argparse
import math

from analytic.motions.records import read_record
from analytic.rocking.domain import make_input
from dem.common.options import figure_file, option_used, print_json
from dem.experiments.shake.domain_cmd import add_linkage_arguments, build_mechanism, restitution_option
from specimens.constants import G
from foundation.errors import ArchdemInputError


def _run_rock(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.dynamics import simulate

    rest = restitution_option(args.restitution)
    pulses = args.input in ("A", "B")
    record = args.record is not None
    option_used(args, "scale", record, "it scales a --record")
    option_used(args, "amplitude", not record, "a --record is scaled by --scale")
    option_used(args, "input", not record, "a --record is the input")
    option_used(args, "freq", not record and not pulses, "it is a sine's (pulses A/B take --duration)")
    option_used(args, "duration", not record and pulses, "it is the length of pulses A/B (a sine takes --freq)")
    if record:
        if args.scale is None or not (args.scale > 0 and math.isfinite(args.scale)):
            raise ArchdemInputError("--scale (a positive factor) is needed with --record")
        if args.plot:
            figure_file(args.plot)
        motion = read_record(args.record).scaled(args.scale)
        label, mech = build_mechanism(args)
        what = f"record {motion.name or args.record} x {args.scale:g}"
    else:
        if args.amplitude is None or not (math.isfinite(args.amplitude) and 0 < args.amplitude <= 100):
            raise ArchdemInputError(f"--amplitude (in g) must be a positive number up to 100, got {args.amplitude}")
        x = args.duration if pulses else args.freq
        if x is None:
            raise ArchdemInputError("--duration (s) is needed for pulses A/B" if pulses else "--freq (Hz) is needed for sines")
        if not (math.isfinite(x) and 0.01 <= x <= 100):
            raise ArchdemInputError(f"{'--duration [s]' if pulses else '--freq [Hz]'} must be in [0.01, 100], got {x:g}")
        if args.plot:
            figure_file(args.plot)
        label, mech = build_mechanism(args)
        a = args.amplitude * G
        if args.input == "sine" and a < abs(mech.onset):
            raise ArchdemInputError(f"the phased sine needs amplitude >= onset lambda = {mech.lam:.4f} g")
        motion = make_input(args.input, a, x, abs(mech.onset))
        what = f"{args.input} {x:g} {'s' if pulses else 'Hz'}, {args.amplitude:g} g"
    r = simulate(mech, motion, restitution=rest, record=True)
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.rocking.figures import plot_response

        plot_response(r, args.plot, title=f"{label}: {what}", input_end=motion.duration)
    out = {"model": mech.summary(), "input": motion.describe(), **r.summary()}
    if args.json:
        print_json(out)
        return 0
    print(f"{label}  {mech.label}  lambda {mech.lam:.4f}  phi_cr {mech.phi_cr:.4g} rad")
    print(f"{'COLLAPSE' if r.collapsed else 'survival'} ({r.rule}{', ' + r.mode if r.mode else ''})  "
          f"max phi/phi_cr {r.max_ratio:.4f}  impacts {r.n_impacts}"
          + (f"  t_collapse {r.t_collapse:.4f} s" if r.t_collapse is not None else ""))
    return 0


def register(sub) -> None:
    q = sub.add_parser("rock", help="one time history of a rocking linkage",
                       description="One time history: rotation / phi_cr against time, impacts, collapse rule.")
    add_linkage_arguments(q, "rock")
    q.add_argument("--freq", type=float, default=None, help="sine frequency [Hz]")
    q.add_argument("--duration", type=float, default=None, help="pulse duration t_i [s] (pulses A/B)")
    q.add_argument("--amplitude", type=float, default=None, help="amplitude [g]")
    q.add_argument("--record", default=None, metavar="FILE",
                   help="recorded accelerogram (AT2, SMC, ESM, CSV) instead of --input")
    q.add_argument("--scale", type=float, default=None, help="factor applied to the record")
    q.set_defaults(func=_run_rock)
