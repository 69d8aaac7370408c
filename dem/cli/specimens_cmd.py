"""``archdem specimens``: the table of the specimen catalogue."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, print_json
from specimens.catalogue import JSON_KEYS, catalogue_rows


def _specimens(args: argparse.Namespace) -> int:
    rows = catalogue_rows()
    if args.json:
        print_json([{k: r[k] for k in JSON_KEYS} for r in rows])
        return 0
    hdr = f"{'id':<11} {'Ri':>6} {'Re':>6} {'e':>6} {'t':>6} {'Sh':>5} {'Sd':>5} {'span':>6} {'rise':>6} {'mass':>6} {'bodies':>11}"
    print(hdr)
    print(f"{'':<11} {'[mm]':>6} {'[mm]':>6} {'[mm]':>6} {'[mm]':>6} {'':>5} {'':>5} {'[mm]':>6} {'[mm]':>6} {'[kg]':>6} {'free/glued':>11}")
    for r in rows:
        print(f"{r['id']:<11} {r['Ri']*1e3:6.0f} {r['Re']*1e3:6.0f} {r['e']*1e3:6.0f} {r['t']*1e3:6.0f} "
              f"{r['Sh']:5.2f} {r['Sd']:5.3f} {r['span']*1e3:6.0f} {r['rise']*1e3:6.1f} {r['mass']:6.3f} "
              f"{r['n_bodies_free']:>5}/{r['n_bodies_glued']:<5}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("specimens", help="table of the specimen catalogue")
    add_options(p, "specimens")
    p.set_defaults(func=_specimens)
