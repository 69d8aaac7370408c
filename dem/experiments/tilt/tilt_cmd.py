"""``archdem tilt``: the virtual tilt test of one arch."""
from __future__ import annotations

import argparse
import math
import sys

from dem.common.joints import ensemble_imperfection
from dem.common.options import (
    add_options,
    arch_from_args,
    can_make_dir,
    default_of,
    discretisation_kwargs,
    figure_file,
    option_used,
    print_json,
    require_standing,
    settings_kwargs,
    writable_dir,
)
from dem.core.model import from_assembly
from dem.core.progress import terminal
from dem.core.settings import Settings
from dem.experiments.tilt.run import TiltProtocol, TiltSpec, run
from specimens.blocks import discretise
from foundation.errors import ArchdemInputError
from foundation.io import unique_run_path


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.tilt.file import save_result

    label, arch = arch_from_args(args)
    if args.id is None and args.Ri is None and args.Sh is None and args.geometry is None:
        raise ArchdemInputError("give a specimen id or the arch parameters")
    settings = Settings(**settings_kwargs(args))  # the friction's and the step's checks, an ensemble's too
    require_standing(label, arch, **discretisation_kwargs(args, arch))
    if args.ensemble is not None:
        return _run_ensemble(args, label, arch)
    if args.seed is not None or args.scatter is not None:
        raise ArchdemInputError("--seed and --scatter go with --ensemble N")
    for dest in ("start", "full_hold"):
        option_used(args, dest, args.protocol == "hold", "it belongs to --protocol hold")
    asm = discretise(arch, config=args.config, **discretisation_kwargs(args, arch))
    if args.plot:
        figure_file(args.plot)
    can_make_dir(args.out)
    spec = TiltSpec(from_assembly(asm, name=label), settings,
                    TiltProtocol(kind=args.protocol, start=args.start, **({"rest_after": None} if args.full_hold else {})),
                    label=label, assembly=asm)
    with terminal(f"tilt {label}", enabled=not args.json) as line:
        res = run(spec, progress=line)
    save_result(res, unique_run_path(writable_dir(args.out), f"tilt-{label}-{args.config}"))
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.tilt.figure import save_tilt_figure

        save_tilt_figure(res, args.plot)
    if args.json:
        print_json(res.summary())
    else:
        print("\n".join(res.lines()))
    if res.lp_check is not None and res.lp_check.warning:
        print(f"archdem: warning: {res.lp_check.warning}", file=sys.stderr)
    return 0


def _run_ensemble(args: argparse.Namespace, label: str, arch) -> int:
    """``archdem tilt ID --ensemble N --seed S [--contact C|calibrated] [--scatter MM]``."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.tilt.ensemble import tilt_ensemble

    if args.protocol != "hold" or args.start != "auto" or args.full_hold:
        raise ArchdemInputError("an ensemble runs the default hold protocol: drop --protocol/--start/--full-hold")
    if args.seed is None:
        raise ArchdemInputError("--ensemble needs --seed S (every realisation is reproducible from it)")
    if args.scatter is not None and not (math.isfinite(args.scatter) and 0 <= args.scatter <= 1e3 * arch.t / 2):
        raise ArchdemInputError(f"--scatter must be between 0 and half the ring thickness [mm], got {args.scatter:g}")
    imp = ensemble_imperfection(args.contact, arch, None if args.scatter is None else args.scatter / 1e3)
    path = unique_run_path(writable_dir(args.out), f"ensemble-{label}-{args.config}-seed{args.seed}")
    res = tilt_ensemble(label, arch, imp, args.ensemble, args.seed, path, config=args.config, mu_joint=args.mu_joint,
                        mu_base=args.mu_base, engine=args.engine, workers=args.workers, progress=not args.json,
                        **({"n_voussoirs": args.voussoirs} if args.voussoirs is not None else {}))
    if args.json:
        print_json(res.summary() | {"config": args.config, "mu_joint": args.mu_joint, "mu_base": args.mu_base,
                                    "engine": args.engine, "seed": args.seed})
    else:
        print("\n".join(res.lines()))
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
