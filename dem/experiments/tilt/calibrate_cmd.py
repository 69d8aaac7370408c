"""``archdem calibrate``: fit the imperfect-fit model (edge loss of the joints) to laboratory tilt tests."""
from __future__ import annotations

import argparse

from analytic.limit.calibration import CALIBRATION_FILE, LAB_TILT_TESTS, calibrate, read_experiments
from dem.common.options import print_json, writable_file
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
        return 0
    print(f"edge loss {cal.edge_loss * 1e3:.2f} mm (scatter {cal.edge_loss_sd * 1e3:.2f} mm per edge), fitted to "
          f"{len(tests)} specimens; leave-one-out RMS error {cal.loo_rms_pct:.1f} % "
          f"(one contact fraction for all, {cal.fraction:.3f}: {cal.fraction_loo_rms_pct:.1f} %)")
    print(f"{'id':<12} {'t mm':>5} {'lab':>6} {'sd':>6} {'ideal':>6} {'contact':>7} {'fit':>6} {'resid %':>8} "
          f"{'LOO':>6} {'LOO %':>7}  mode")
    for r in cal.rows:
        print(f"{r['id']:<12} {r['t_mm']:5.0f} {r['lambda_lab']:6.3f} {r['lambda_lab_sd']:6.3f} {r['lambda_ideal_lp']:6.3f} "
              f"{r['contact']:7.3f} {r['lambda_fit']:6.3f} {r['residual_pct']:+8.1f} {r['lambda_loo']:6.3f} "
              f"{r['loo_error_pct']:+7.1f}  {r['observed_mode']}")
    print(f"-> {out} (used by --contact calibrated)")
    return 0


def register(sub) -> None:
    p = sub.add_parser("calibrate", help="fit the effective contact (edge loss of the joints) to laboratory tilt tests",
                       description=__doc__.splitlines()[0])
    p.add_argument("--experiments", default=None, metavar="FILE",
                   help="CSV of tilt tests: id, lambda_mean, lambda_sd, observed_mode [, n_tests, Ri_mm, Re_mm, e_mm] "
                        "(default: the six specimens of the reference study shipped with archdem)")
    p.add_argument("--out", default=str(CALIBRATION_FILE),
                   help=f"where to store the calibration (default {CALIBRATION_FILE}, read by --contact calibrated)")
    p.add_argument("--replace", action="store_true", help="replace an existing calibration file")
    p.add_argument("--no-scatter", dest="no_scatter", action="store_true",
                   help="fit the edge loss only, not its scatter (seconds instead of about a minute)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=_run)
