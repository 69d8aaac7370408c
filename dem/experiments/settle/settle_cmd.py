"""``archdem settle ID``: an arch left under gravity on its base, how far its blocks move, and whether they rest.

The library call is :func:`dem.experiments.settle.run.run` with a :class:`~dem.experiments.settle.run.SettleSpec`.
"""
from __future__ import annotations

import argparse

from dem.common.options import default_of, print_json
from dem.experiments.settle.run import SettleSpec, run


def _run(args: argparse.Namespace) -> int:
    kw = {k: v for k, v in (("config", args.config), ("duration", args.duration)) if v is not None}
    res = run(SettleSpec(args.id, **kw))
    if args.json:
        print_json(res.to_json()[0])
        return 0
    print(f"{res.id} ({res.config}, {res.engine}), {res.duration_s:g} s under gravity: "
          f"{'at rest' if res.at_rest else ('collapsed' if res.collapsed else 'still moving')}; largest block "
          f"displacement {res.max_displacement_mm:.4g} mm, rotation {res.max_rotation_mrad:.4g} mrad; "
          f"kinetic energy at the end {res.final_kinetic_energy_J:.3g} J")
    return 0


def register(sub) -> None:
    p = sub.add_parser("settle", help="the rest state of an arch under gravity", description=__doc__.splitlines()[0])
    p.add_argument("id", help="specimen id (see `archdem specimens`)")
    p.add_argument("--config", choices=("glued", "free"), default=None,
                   help=f"block configuration (default {default_of(SettleSpec, 'config')})")
    p.add_argument("--duration", type=float, default=None, metavar="S",
                   help=f"time under gravity [s] (default {default_of(SettleSpec, 'duration'):g})")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=_run)
