"""``archdem tilt``: the virtual tilt test of one arch."""
from __future__ import annotations

import argparse
import math

from dem.cli.common import (
    add_arch_arguments,
    add_engine_argument,
    arch_from_args,
    default_of,
    discretisation_kwargs,
    print_json,
    writable_dir,
    writable_file,
)
from specimens.errors import ArchdemInputError


def _run(args: argparse.Namespace) -> int:
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.tilt import TiltProtocol, tilt
    from dem.formats.tilt import save_result
    from specimens.blocks import discretise
    from specimens.io import unique_run_path

    label, arch = arch_from_args(args)
    if args.id is None and args.Ri is None and args.Sh is None:
        raise ArchdemInputError("give a specimen id or the arch parameters")
    for name in ("mu_joint", "mu_base"):
        v = getattr(args, name)
        if not (math.isfinite(v) and v > 0):
            raise ArchdemInputError(f"--{name.replace('_', '-')} must be a positive number, got {v}")
    asm = discretise(arch, config=args.config, **discretisation_kwargs(args))
    kw = {"mu_joint": args.mu_joint, "mu_base": args.mu_base, "planar": args.planar, "engine": args.engine}
    if args.dt is not None:
        kw["dt"] = args.dt
    settings = Settings(**kw)
    out = writable_dir(args.out)
    if args.plot:
        writable_file(args.plot)
    res = tilt(from_assembly(asm, name=label), settings, TiltProtocol(kind=args.protocol, start=args.start,
                                                               **({"rest_after": None} if args.full_hold else {})),
               label=label, assembly=asm)
    path = save_result(res, unique_run_path(out, f"tilt-{label}-{args.config}"))
    if args.plot:
        from dem.plotting.tilt import save_tilt_figure

        save_tilt_figure(res, args.plot)
    s = res.summary()
    if args.json:
        print_json(s)
    else:
        hinges = ", ".join(f"{j['joint']}:{j['state']}" for j in s["joints"] if j["state"] != "closed")
        print(f"{label} ({args.config}, mu {args.mu_joint:g}/{args.mu_base:g}, {args.protocol}): "
              f"lambda = {res.lam:.4f} (theta = {res.theta_deg:.2f} deg), bracket [{res.bracket[0]:.4f}, "
              f"{res.bracket[1]:.4f}], {res.mode} [{hinges}], {res.n_sims} simulations, {res.wall_s:.1f} s -> {path}")
    return 0


def register(sub) -> None:
    from dem.core.settings import Settings
    from dem.experiments.tilt import TiltProtocol
    from specimens.blocks import discretise

    p = sub.add_parser("tilt", help="virtual tilt test (collapse multiplier lambda = tan theta and failure mode)")
    add_arch_arguments(p)
    p.add_argument("--config", choices=("glued", "free"), default=default_of(discretise, "config"))
    p.add_argument("--mu-joint", dest="mu_joint", type=float, default=default_of(Settings, "mu_joint"),
                   help=f"block-block friction (default {default_of(Settings, 'mu_joint'):g})")
    p.add_argument("--mu-base", dest="mu_base", type=float, default=default_of(Settings, "mu_base"),
                   help=f"block-base friction (default {default_of(Settings, 'mu_base'):g})")
    p.add_argument("--protocol", choices=("hold", "staircase", "ramp"), default=default_of(TiltProtocol, "kind"),
                   help=f"tilt protocol (default {default_of(TiltProtocol, 'kind')})")
    p.add_argument("--start", choices=("auto", "lp", "scan"), default=default_of(TiltProtocol, "start"),
                   help="hold: first bracket around the static LP of the blocks (lp) or from a fast ramp (scan); "
                        f"default {default_of(TiltProtocol, 'start')}, which is lp here (the blocks are known)")
    p.add_argument("--full-hold", dest="full_hold", action="store_true",
                   help=f"hold: hold every level the full {default_of(TiltProtocol, 'hold_time'):g} s (by default a "
                        f"level at rest {default_of(TiltProtocol, 'rest_after'):g} s into the hold ends there)")
    p.add_argument("--planar", action="store_true", help="constrain the blocks to the arch plane")
    p.add_argument("--dt", type=float, default=None, help=f"time step [s] (default {default_of(Settings, 'dt'):g})")
    add_engine_argument(p)
    p.add_argument("--out", default="runs/tilt", help="directory for the result file (default runs/tilt)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--plot", default=None, help="figure file (.png/.pdf/.svg)")
    p.set_defaults(func=_run)
