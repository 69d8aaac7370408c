"""``archdem specimens``: the table of the specimen catalogue."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, answer
from specimens.catalogue import JSON_KEYS, catalogue_rows, catalogue_table


def _specimens(args: argparse.Namespace) -> int:
    rows = catalogue_rows()
    answer(args.json, [{k: r[k] for k in JSON_KEYS} for r in rows], catalogue_table(rows))
    return 0


def register(sub) -> None:
    p = sub.add_parser("specimens", help="table of the specimen catalogue")
    add_options(p, "specimens")
    p.set_defaults(func=_specimens)
