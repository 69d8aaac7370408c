"""Benchmark: one tilt ensemble of imperfect joints (docs/physics/dem.md#16-tilt-ensembles).

Ten realisations (the issue's measure: at most 60 s on 2 cores) of one specimen with the
calibrated edge loss and scatter, as ``archdem tilt ID --contact calibrated --ensemble 10 --seed 1``
runs them; the study file goes to a temporary folder.

    python benchmarks/bench_ensemble.py [--id Sh06-Sd020] [--n 10] [--workers 2] [--engine pybullet]
"""
from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

from _common import report


def main() -> None:
    from analytic.limit.calibration import load_calibration
    from dem.experiments.tilt.ensemble import tilt_ensemble
    from specimens.catalogue import get_specimen
    from specimens.imperfection import Imperfection

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--id", default="Sh06-Sd020")
    ap.add_argument("--n", type=int, default=10)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--engine", default="pybullet")
    a = ap.parse_args()
    cal = load_calibration()
    arch = get_specimen(a.id).arch
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        res = tilt_ensemble(a.id, arch, Imperfection(cal.edge_loss, cal.edge_loss_sd), a.n, 1,
                            Path(tmp) / "ensemble.h5", engine=a.engine, workers=a.workers, progress=False)
        wall = time.perf_counter() - t0
    report("ensemble", {
        "specimen": a.id, "engine": a.engine, "realisations": a.n, "workers": a.workers,
        "wall_s": wall, "wall_per_realisation_core_s": wall * a.workers / a.n, "within_60_s": wall <= 60.0,
        "lambda_mean": res.lambda_mean, "lambda_sd": res.lambda_sd, "modes": res.summary()["modes"],
        "failed": len(res.failed),
        "load_average": os.getloadavg()[0],
    })


if __name__ == "__main__":
    main()
