"""``archdem calibrate``: fit the imperfect-fit model (edge loss of the joints) to laboratory tilt tests."""
from __future__ import annotations

import argparse

from analytic.limit.calibration import CALIBRATION_FILE, LAB_TILT_TESTS, calibrate, read_experiments
from dem.common.options import add_options, print_json, writable_file
from dem.experiments.tilt.run import calibration_lines
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path, to_json


def _run(args: argparse.Namespace) -> int:
    src = args.experiments or LAB_TILT_TESTS
    out = writable_file(args.out)  # checked, not made: a bad table leaves nothing behind, not even a folder
    if out.exists() and not args.replace:
        raise ArchdemInputError(f"{out} holds a calibration already; it is kept unless you give --replace")
    tests = read_experiments(src)
    cal = calibrate(tests, scatter=not args.no_scatter, source=args.experiments or f"archdem's {LAB_TILT_TESTS.name}")
    with atomic_path(out, overwrite=args.replace) as tmp:
        tmp.write_text(to_json(cal.to_json(), indent=2))
    if args.json:
        print_json(cal.to_json() | {"file": str(out)})
    else:
        print("\n".join(calibration_lines(cal, len(tests), out)))
    return 0


def register(sub) -> None:
    p = sub.add_parser("calibrate", help="fit the effective contact (edge loss of the joints) to laboratory tilt tests",
                       description=__doc__.splitlines()[0])
    p.add_argument("--experiments", default=None, metavar="FILE",
                   help="CSV of tilt tests: id, lambda_mean, lambda_sd, observed_mode [, n_tests, Ri_mm, Re_mm, e_mm] "
                        "(default: the six specimens of the reference study shipped with archdem)")
    add_options(p, "calibrate", out=str(CALIBRATION_FILE))
    p.add_argument("--replace", action="store_true", help="replace an existing calibration file")
    p.add_argument("--no-scatter", dest="no_scatter", action="store_true",
                   help="fit the edge loss only, not its scatter (seconds instead of about a minute)")
    p.set_defaults(func=_run)
