"""``archdem record FILE``: read an accelerogram and print what it holds.

The library call is :func:`dem.experiments.record.run.run` with a :class:`~dem.experiments.record.run.RecordSpec`.
"""
from __future__ import annotations

import argparse

from analytic.motions.records import FORMATS, MAX_RECORD_BYTES, MAX_RECORD_S, MAX_RECORD_SAMPLES
from dem.common.options import add_options, answer, default_of
from dem.experiments.record.run import RecordSpec, run


def _run(args: argparse.Namespace) -> int:
    res = run(RecordSpec(args.file, args.format, args.units))
    answer(args.json, res.to_json()[0], res.lines())
    return 0


def register(sub) -> None:
    p = sub.add_parser("record", help="read an accelerogram (AT2, SMC, ESM, CSV) and print its summary",
                       description="Read a recorded accelerogram and print name, npts, dt, duration, PGA and units.")
    p.add_argument("file", help=f"record file, up to {MAX_RECORD_BYTES // 2**20} MB, {MAX_RECORD_SAMPLES} samples "
                                f"and {MAX_RECORD_S:g} s (a real record is far below; cut a longer one)")
    p.add_argument("--format", default=default_of(RecordSpec, "format"), choices=("auto",) + FORMATS,
                   help="file format (default: detect)")
    add_options(p, "record")
    p.set_defaults(func=_run)
