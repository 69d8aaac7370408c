"""``archdem compare-engines``: tilt lambda and mode of each specimen from both engines, at no
sliding and at the reference friction, next to the discrete limit analysis."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, default_of, figure_file, print_json
from dem.core.engines import available_engines
from dem.core.progress import terminal
from dem.core.settings import Settings
from dem.experiments.compare_engines.run import FRICTIONS, compare, summary
from specimens.catalogue import select_specimens
from foundation.errors import ArchdemInputError


def _run(args: argparse.Namespace) -> int:
    ids = [s.id for s in select_specimens(args.specimens)]
    engines = tuple(e.strip() for e in args.engines.split(",") if e.strip())
    for e in engines:
        if e not in available_engines():
            raise ArchdemInputError(f"unknown engine {e!r}; available: {', '.join(available_engines())}")
    if len(set(engines)) != 2 or len(engines) != 2:
        raise ArchdemInputError(f"give two different engines to compare, got {args.engines!r}")
    frictions = ("none", "reference") if args.friction == "both" else (args.friction,)
    base = Settings() if args.dt is None else Settings(dt=args.dt)
    if args.plot:
        figure_file(args.plot)
    with terminal("compare-engines", unit="specimens", enabled=not args.json) as line:
        rows = compare(ids, args.config, engines, frictions, base, workers=args.workers, progress=line)
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.compare_engines.figure import save_engine_comparison

        save_engine_comparison(rows, args.plot)
    if args.json:
        print_json({"rows": [r.to_dict() for r in rows], "summary": summary(rows), "config": args.config,
                    "dt": base.dt})
        return 0
    e1, e2 = engines
    print(f"{'id':<12} {'friction':<9} {'LP':>7} {e1:>9} {'err':>7} {e2:>9} {'err':>7} {'diff':>7}  modes")
    for r in rows:
        a, b = r.results[e1], r.results[e2]
        print(f"{r.id:<12} {r.friction:<9} {r.lp_lam:7.4f} {a.lam:9.4f} {100 * r.err_vs_lp(e1):+6.2f}% "
              f"{b.lam:9.4f} {100 * r.err_vs_lp(e2):+6.2f}% {100 * r.rel_diff:+6.2f}%  {a.mode}/{b.mode}")
    print("err = (lambda - LP) / LP (an error at no sliding only); diff = (e2 - e1) / e1")
    return 0


def register(sub) -> None:
    engines = ",".join(default_of(compare, "engines"))
    p = sub.add_parser("compare-engines", help="tilt lambda from both engines vs limit analysis, per specimen")
    p.add_argument("--specimens", default="all", help="all or comma-separated ids (default all)")
    p.add_argument("--engines", default=engines, help=f"two engines (default {engines})")
    p.add_argument("--friction", choices=("both", "none", "reference"), default="both",
                   help="no sliding, reference friction "
                        f"{'/'.join(f'{m:g}' for m in FRICTIONS['reference'])}, or both (default)")
    add_options(p, "compare-engines", config=default_of(compare, "config"), workers=1)
    p.set_defaults(func=_run)
