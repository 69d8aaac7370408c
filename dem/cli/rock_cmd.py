"""``archdem rock``: one time history of a rocking linkage (analytic: the four-bar, the two-bar or a
block) under a pulse, a sine or a record (:func:`dem.experiments.shake.linkage.rock`)."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, answer, arch_request, figure_file
from dem.experiments.contract import add_spec_options, spec_from_args
from dem.experiments.shake.linkage import RockSpec, rock


def _run_rock(args: argparse.Namespace) -> int:
    spec = spec_from_args(RockSpec, args, request=arch_request(args))
    if args.plot:
        figure_file(args.plot)
    res = rock(spec)
    if args.plot:
        res.plot(args.plot)
    answer(args.json, res.to_json(), res.lines())
    return 0


def register(sub) -> None:
    q = sub.add_parser("rock", help="one time history of a rocking linkage",
                       description="One time history: rotation / phi_cr against time, impacts, collapse rule.")
    add_options(q, "rock")
    add_spec_options(q, RockSpec)
    q.set_defaults(func=_run_rock)
