"""``archdem calibrate``: fit the imperfect-fit model (edge loss of the joints) to laboratory tilt tests."""
from __future__ import annotations

import argparse

from analytic.limit.calibration import CALIBRATION_FILE, LAB_TILT_TESTS, calibrate, calibration_target, read_experiments
from dem.common.options import add_options, answer
from dem.experiments.tilt.run import calibration_lines


def _run(args: argparse.Namespace) -> int:
    out = calibration_target(args.out, args.replace)
    tests = read_experiments(args.experiments or LAB_TILT_TESTS)
    cal = calibrate(tests, scatter=not args.no_scatter, source=args.experiments or f"archdem's {LAB_TILT_TESTS.name}")
    cal.save(out, args.replace)
    answer(args.json, cal.to_json() | {"file": str(out)}, calibration_lines(cal, len(tests), out))
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
