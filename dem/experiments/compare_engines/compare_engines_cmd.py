"""``archdem compare-engines``: tilt lambda and mode of each specimen from both engines, at no
sliding and at the reference friction, next to the discrete limit analysis.

The library call is :meth:`~dem.experiments.compare_engines.run.CompareSpec.run` (or
:func:`~dem.experiments.compare_engines.run.compare`)."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, answer, default_of, figure_file
from dem.core.progress import terminal
from dem.experiments.compare_engines.run import CompareSpec, compare
from dem.experiments.contract import add_spec_options, spec_from_args


def _run(args: argparse.Namespace) -> int:
    spec = spec_from_args(CompareSpec, args, config=args.config, dt=args.dt)
    if args.plot:
        figure_file(args.plot)
    with terminal("compare-engines", unit="specimens", enabled=not args.json) as line:
        res = spec.run(args.workers, progress=line)
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.compare_engines.figure import save_engine_comparison

        save_engine_comparison(res.rows, args.plot)
    answer(args.json, res.describe(), res.lines())
    return 0


def register(sub) -> None:
    p = sub.add_parser("compare-engines", help="tilt lambda from both engines vs limit analysis, per specimen")
    add_spec_options(p, CompareSpec)
    add_options(p, "compare-engines", config=default_of(compare, "config"), workers=1)
    p.set_defaults(func=_run)
