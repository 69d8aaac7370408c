"""``archdem record FILE``: read an accelerogram and print what it holds."""
from __future__ import annotations

import argparse

import numpy as np

from analytic.motions.records import FORMATS, MAX_RECORD_BYTES, MAX_RECORD_S, MAX_RECORD_SAMPLES, load_record
from dem.common.options import print_json
from specimens.constants import G


def record_summary(path: str, fmt: str = "auto", units: str | None = None) -> dict:
    """Name, sampling, duration and PGA of a record file (SI units, PGA also in g)."""
    rec = load_record(path, fmt, units)
    m = rec.motion
    k = int(np.argmax(np.abs(m.values)))
    return {
        "file": str(path), "name": m.name, "format": rec.format,
        "units": rec.units, "units_from": rec.units_from,
        "npts": len(m.values), "dt": m.dt, "duration": m.duration,
        "pga_g": m.pga / G, "pga_ms2": m.pga, "t_pga": k * m.dt,
    }


def _run(args: argparse.Namespace) -> int:
    s = record_summary(args.file, args.format, args.units)
    if args.json:
        print_json(s)
        return 0
    print(f"file      {s['file']}")
    print(f"name      {s['name']}")
    print(f"format    {s['format']}   units {s['units']} ({s['units_from']})")
    print(f"npts      {s['npts']}   dt {s['dt']:g} s   duration {s['duration']:.3f} s")
    print(f"PGA       {s['pga_g']:.4f} g = {s['pga_ms2']:.4f} m/s^2 at t = {s['t_pga']:.3f} s")
    return 0


def register(sub) -> None:
    p = sub.add_parser("record", help="read an accelerogram (AT2, SMC, ESM, CSV) and print its summary",
                       description="Read a recorded accelerogram and print name, npts, dt, duration, PGA and units.")
    p.add_argument("file", help=f"record file, up to {MAX_RECORD_BYTES // 2**20} MB, {MAX_RECORD_SAMPLES} samples "
                                f"and {MAX_RECORD_S:g} s (a real record is far below; cut a longer one)")
    p.add_argument("--format", default="auto", choices=("auto",) + FORMATS, help="file format (default: detect)")
    p.add_argument("--units", default=None, choices=("g", "m/s2", "cm/s2", "mm/s2"),
                   help="units of the numbers in the file (needed for CSV without units in its header)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(func=_run)
