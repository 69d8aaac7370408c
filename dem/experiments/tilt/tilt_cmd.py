"""``archdem tilt``: the virtual tilt test of one arch."""
from __future__ import annotations

import argparse
import math
import sys

from dem.common.joints import ensemble_imperfection
from dem.common.options import (
    add_arch_arguments,
    add_contact_law_arguments,
    add_engine_argument,
    arch_from_args,
    can_make_dir,
    contact_law_settings,
    default_of,
    discretisation_kwargs,
    figure_file,
    option_used,
    print_json,
    require_standing,
    workers_option,
    writable_dir,
)
from dem.core.model import from_assembly
from dem.core.progress import terminal
from dem.core.settings import Settings
from dem.experiments.tilt.run import TiltProtocol, tilt
from specimens.blocks import discretise
from foundation.errors import ArchdemInputError
from foundation.io import unique_run_path


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.tilt.file import save_result

    label, arch = arch_from_args(args)
    if args.id is None and args.Ri is None and args.Sh is None and args.geometry is None:
        raise ArchdemInputError("give a specimen id or the arch parameters")
    for name in ("mu_joint", "mu_base"):
        v = getattr(args, name)
        if not (math.isfinite(v) and v > 0):
            raise ArchdemInputError(f"--{name.replace('_', '-')} must be a positive number, got {v}")
    law = contact_law_settings(args, args.id)
    require_standing(label, arch, **discretisation_kwargs(args, arch))
    if args.ensemble is not None:
        if law:
            raise ArchdemInputError("an ensemble runs rigid joints: drop --contact-law/--kn/--damping-*/--joints")
        return _run_ensemble(args, label, arch)
    if args.seed is not None or args.scatter is not None or args.workers is not None:
        raise ArchdemInputError("--seed, --scatter and --workers go with --ensemble N")
    for dest in ("start", "full_hold"):
        option_used(args, dest, args.protocol == "hold", "it belongs to --protocol hold")
    asm = discretise(arch, config=args.config, **discretisation_kwargs(args, arch))
    kw = {"mu_joint": args.mu_joint, "mu_base": args.mu_base, "planar": args.planar, "engine": args.engine, **law}
    if args.dt is not None:
        kw["dt"] = args.dt
    settings = Settings(**kw)
    if args.plot:
        figure_file(args.plot)
    can_make_dir(args.out)
    with terminal(f"tilt {label}", enabled=not args.json) as line:
        res = tilt(from_assembly(asm, name=label), settings,
                   TiltProtocol(kind=args.protocol, start=args.start, **({"rest_after": None} if args.full_hold else {})),
                   label=label, assembly=asm, progress=line)
    path = save_result(res, unique_run_path(writable_dir(args.out), f"tilt-{label}-{args.config}"))
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.tilt.figure import save_tilt_figure

        save_tilt_figure(res, args.plot)
    s = res.summary()
    if args.json:
        print_json(s)
    else:
        hinges = ", ".join(f"{j['joint']}:{j['state']}" for j in s["joints"] if j["state"] != "closed")
        print(f"{label} ({args.config}, mu {args.mu_joint:g}/{args.mu_base:g}, {args.protocol}): "
              f"lambda = {res.lam:.4f} (theta = {res.theta_deg:.2f} deg), bracket [{res.bracket[0]:.4f}, "
              f"{res.bracket[1]:.4f}], {res.mode} [{hinges}], {res.n_sims} simulations, {res.wall_s:.1f} s -> {path}")
        if (res.protocol.time_scale or 1.0) > 1.0:
            print(f"  protocol {res.protocol.time_scale:.2f} x slower than at the catalogue's scale (a larger arch moves "
                  "more slowly: docs/physics/dem.md#75-arches-larger-than-the-catalogue)")
        print(lp_check_line(res.lp_check))
    if res.lp_check is not None and res.lp_check.warning:
        print(f"archdem: warning: {res.lp_check.warning}", file=sys.stderr)
    return 0


def lp_check_line(chk) -> str:
    """The tilt's own check, as printed under its answer."""
    if chk is None:
        return "  limit analysis: none for this model (no blocks to solve)"
    if chk.agrees is None:
        return f"  limit analysis of the same blocks: no multiplier (lambda = {chk.lp_lam:g}); the tilt is unchecked"
    return (f"  limit analysis of the same blocks{' (no sliding)' if chk.no_sliding else ''}: lambda = {chk.lp_lam:.4f}; "
            f"the tilt is {100 * chk.rel_err:+.1f} % from it "
            f"({'within' if chk.agrees else 'beyond'} {100 * chk.tolerance:g} %)")


def _run_ensemble(args: argparse.Namespace, label: str, arch) -> int:
    """``archdem tilt ID --ensemble N --seed S [--contact C|calibrated] [--scatter MM]``."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.tilt.ensemble import tilt_ensemble

    if args.protocol != "hold" or args.start != "auto" or args.full_hold or args.planar or args.dt is not None:
        raise ArchdemInputError("an ensemble runs the default hold protocol: drop --protocol/--start/--full-hold/--planar/--dt")
    if args.density is not None:
        raise ArchdemInputError("an ensemble uses the default density: drop --density")
    if args.seed is None:
        raise ArchdemInputError("--ensemble needs --seed S (every realisation is reproducible from it)")
    if args.scatter is not None and not (math.isfinite(args.scatter) and 0 <= args.scatter <= 1e3 * arch.t / 2):
        raise ArchdemInputError(f"--scatter must be between 0 and half the ring thickness [mm], got {args.scatter:g}")
    imp = ensemble_imperfection(args.contact, arch, None if args.scatter is None else args.scatter / 1e3)
    scatter_mm = imp.edge_loss_sd * 1e3
    out = writable_dir(args.out)
    path = unique_run_path(out, f"ensemble-{label}-{args.config}-seed{args.seed}")
    res = tilt_ensemble(label, arch, imp, args.ensemble, args.seed, path, config=args.config, mu_joint=args.mu_joint,
                        mu_base=args.mu_base, engine=args.engine, workers=args.workers, progress=not args.json,
                        **({"n_voussoirs": args.voussoirs} if args.voussoirs is not None else {}))
    s = res.summary() | {"config": args.config, "mu_joint": args.mu_joint, "mu_base": args.mu_base,
                         "engine": args.engine, "seed": args.seed}
    if args.json:
        print_json(s)
        return 0
    modes = ", ".join(f"{m} {k}" for m, k in s["modes"].items())
    print(f"{label} ({args.config}, contact {res.contact:.3f}, edge-loss scatter {scatter_mm:g} mm, seed {args.seed}): "
          f"lambda {res.lambda_mean:.4f} +- {res.lambda_sd:.4f} over {len(res.lambdas)} realisations ({modes}); "
          f"{res.wall_s:.0f} s -> {path}")
    for f in res.failed:
        print(f"  failed: {f}")
    return 0


def register(sub) -> None:
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
    add_contact_law_arguments(p)
    p.add_argument("--out", default="runs/tilt", help="directory for the result file (default runs/tilt)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--plot", default=None, help="figure file (.png/.pdf/.svg)")
    g = p.add_argument_group("ensemble of imperfect realisations (like repeated laboratory tests)")
    g.add_argument("--ensemble", type=int, default=None, metavar="N", help="tilt N realisations of the imperfect joints")
    g.add_argument("--seed", type=int, default=None, metavar="S", help="seed of the realisations (required with --ensemble)")
    g.add_argument("--scatter", type=float, default=None, metavar="MM",
                   help="standard deviation of each joint edge's contact loss [mm] (default with --contact "
                        "calibrated: the calibrated scatter)")
    g.add_argument("--workers", type=workers_option, default=None, help="processes (default: all cores)")
    p.set_defaults(func=_run)
