"""``archdem tilt``: the virtual tilt test of one arch."""
from __future__ import annotations

import argparse
import sys

from dem.common.options import (
    add_options,
    answer,
    arch_request,
    can_make_dir,
    default_of,
    figure_file,
    given,
    settings_kwargs,
    writable_dir,
)
from dem.core.model import from_assembly
from dem.core.progress import terminal
from dem.core.settings import Settings
from dem.experiments.tilt.run import TiltProtocol, TiltSpec, run
from dem.experiments.tilt.spec import TiltOptions
from specimens.blocks import discretise
from foundation.io import unique_run_path


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.tilt.file import save_result

    req = arch_request(args)
    label, arch = req.structure()
    settings = Settings(**settings_kwargs(args))  # the friction's and the step's checks, an ensemble's too
    req.require_standing(label, arch)
    opts = TiltOptions(args.protocol, args.start, args.full_hold, args.ensemble, args.seed, args.scatter, given(args))
    if opts.ensemble is not None:
        res = opts.run_ensemble(label, arch, args.contact, args.out, args.config, args.voussoirs, mu_joint=args.mu_joint,
                                mu_base=args.mu_base, engine=args.engine, workers=args.workers, progress=not args.json)
        answer(args.json, res.describe(), res.lines())
        return 0
    asm = discretise(arch, config=args.config, **req.discretise_kwargs(arch))
    if args.plot:
        figure_file(args.plot)
    can_make_dir(args.out)
    spec = TiltSpec(from_assembly(asm, name=label), settings, opts.tilt_protocol(), label=label, assembly=asm)
    with terminal(f"tilt {label}", enabled=not args.json) as line:
        res = run(spec, progress=line)
    save_result(res, unique_run_path(writable_dir(args.out), f"tilt-{label}-{args.config}"))
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.tilt.figure import save_tilt_figure

        save_tilt_figure(res, args.plot)
    answer(args.json, res.summary(), res.lines())
    if res.lp_check is not None and res.lp_check.warning:
        print(f"archdem: warning: {res.lp_check.warning}", file=sys.stderr)
    return 0


def register(sub) -> None:
    p = sub.add_parser("tilt", help="virtual tilt test (collapse multiplier lambda = tan theta and failure mode)")
    add_options(p, "tilt", out="runs/tilt")
    p.add_argument("--protocol", choices=("hold", "staircase", "ramp"), default=default_of(TiltProtocol, "kind"),
                   help=f"tilt protocol (default {default_of(TiltProtocol, 'kind')})")
    p.add_argument("--start", choices=("auto", "lp", "scan"), default=default_of(TiltProtocol, "start"),
                   help="hold: first bracket around the static LP of the blocks (lp) or from a fast ramp (scan); "
                        f"default {default_of(TiltProtocol, 'start')}, which is lp here (the blocks are known)")
    p.add_argument("--full-hold", dest="full_hold", action="store_true",
                   help=f"hold: hold every level the full {default_of(TiltProtocol, 'hold_time'):g} s (by default a "
                        f"level at rest {default_of(TiltProtocol, 'rest_after'):g} s into the hold ends there)")
    g = p.add_argument_group("ensemble of imperfect realisations (like repeated laboratory tests)")
    g.add_argument("--ensemble", type=int, default=None, metavar="N", help="tilt N realisations of the imperfect joints")
    g.add_argument("--seed", type=int, default=None, metavar="S", help="seed of the realisations (required with --ensemble)")
    g.add_argument("--scatter", type=float, default=None, metavar="MM",
                   help="standard deviation of each joint edge's contact loss [mm] (default with --contact "
                        "calibrated: the calibrated scatter)")
    p.set_defaults(func=_run)
