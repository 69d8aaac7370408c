"""``archdem modes``: natural frequencies and mode shapes of an arch (on piers or not) or a block on
compliant joints, at rest under gravity (docs/physics/modes.md)."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, answer, arch_request, figure_file
from dem.experiments.contract import add_spec_options, spec_from_args
from dem.experiments.modes.spec import ModesSpec, modes_structure


def _run(args: argparse.Namespace) -> int:
    spec = spec_from_args(ModesSpec, args, kn=args.kn, ks=args.ks, youngs=args.youngs)
    if args.plot:
        figure_file(args.plot)
    res = spec.run(*modes_structure(arch_request(args), args.config))
    if args.plot:
        res.save_figure(args.plot)
    answer(args.json, res.to_json(), res.lines())
    return 0


def register(sub) -> None:
    p = sub.add_parser("modes", help="natural frequencies and mode shapes on compliant joints",
                       description=__doc__.splitlines()[0])
    add_options(p, "modes")
    add_spec_options(p, ModesSpec)
    p.set_defaults(func=_run)
