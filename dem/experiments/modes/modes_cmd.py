"""``archdem modes``: natural frequencies and mode shapes of an arch (on piers or not) or a block on
compliant joints, at rest under gravity (docs/physics/modes.md)."""
from __future__ import annotations

import argparse
import math

from analytic.compliant.modes import POISSON, SPRINGS, ks_over_kn, modes
from dem.common.options import (
    add_options,
    arch_from_args,
    block_from_args,
    default_of,
    discretisation_kwargs,
    figure_file,
    option_used,
    print_json,
)
from dem.core.contact import normal_stiffness
from dem.core.model import from_assembly
from dem.core.model import single_block as block_model
from dem.core.settings import Settings
from specimens.blocks import DEFAULT_DENSITY, discretise
from foundation.errors import ArchdemInputError

#: Most modes a command prints or stores.
MAX_COUNT = 10_000


def _structure(args: argparse.Namespace):
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.frame import single_block

    block = block_from_args(args)
    if block is not None:
        b, h = block
        density = DEFAULT_DENSITY if args.density is None else args.density
        return f"block-b{b:g}-h{h:g}", single_block(b, h, density, 0.1 if args.width is None else args.width)
    label, arch = arch_from_args(args)
    return label, discretise(arch, config=args.config, **discretisation_kwargs(args, arch))


def _stiffness(args: argparse.Namespace, structure) -> tuple[float, float | None]:
    """``(kn, ks)`` given, or from ``--youngs`` and ``--poisson`` over the blocks' length (dem.core.contact)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.frame import Block

    if (args.kn is None) == (args.youngs is None):
        raise ArchdemInputError("give the joints' stiffness as --kn PA_PER_M or as --youngs E_PA")
    option_used(args, "poisson", args.kn is None and args.ks is None, "it gives k_s from --youngs, without --ks")
    if args.kn is not None:
        return args.kn, args.ks
    if not (math.isfinite(args.youngs) and args.youngs > 0):
        raise ArchdemInputError(f"--youngs must be a positive modulus [Pa], got {args.youngs}")
    if not (math.isfinite(args.poisson) and 0.0 <= args.poisson < 0.5):
        raise ArchdemInputError(f"--poisson must be in [0, 0.5), got {args.poisson}")
    model = (block_model(2 * structure.b, 2 * structure.h, structure.width) if isinstance(structure, Block)
             else from_assembly(structure))
    kn = normal_stiffness(Settings(contact_law="compliant", youngs=args.youngs), model)
    return kn, (ks_over_kn(args.poisson) * kn if args.ks is None else args.ks)


def _run(args: argparse.Namespace) -> int:
    if not (isinstance(args.count, int) and 1 <= args.count <= MAX_COUNT):
        raise ArchdemInputError(f"--count must be a whole number from 1 to {MAX_COUNT}, got {args.count!r}")
    if args.plot:
        figure_file(args.plot)
    label, structure = _structure(args)
    kn, ks = _stiffness(args, structure)
    res = modes(structure, kn, ks, springs=args.springs)
    out = {"id": label, **res.describe(args.count)}
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.modes.figure import save_mode_shapes

        save_mode_shapes(structure, res, args.plot, title=label)
        out["plot"] = args.plot
    if args.json:
        print_json(out)
        return 0
    f = res.frequencies_hz[:args.count]
    print(f"{label}: {len(res.frequencies_hz)} modes on joints kn {res.kn:.3g} Pa/m, ks {res.ks:.3g} Pa/m "
          f"(springs at the {'contact ends' if res.springs == 'ends' else 'whole contact'})"
          + (f" ({res.unstable} unstable under gravity)" if res.unstable else ""))
    print("  " + "  ".join(f"{x:.4g}" for x in f) + " Hz")
    return 0


def register(sub) -> None:
    p = sub.add_parser("modes", help="natural frequencies and mode shapes on compliant joints",
                       description=__doc__.splitlines()[0])
    add_options(p, "modes")
    p.add_argument("--poisson", type=float, default=POISSON,
                   help=f"the blocks' Poisson's ratio, for ks = (5/6) G / length with --youngs (default {POISSON:g})")
    p.add_argument("--springs", choices=tuple(SPRINGS), default=default_of(modes, "springs"),
                   help="a joint's springs at its contact's two ends, as the DEM's corner contacts (default), "
                        "or spread over it")
    p.add_argument("--count", type=int, default=80, help="modes printed (default 80)")
    p.set_defaults(func=_run)
