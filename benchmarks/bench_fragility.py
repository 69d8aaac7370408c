"""Benchmark: one fragility curve and what its runs cost (docs/physics/fragility.md#speed).

* one curve of one specimen at one frequency, ``stripes`` x ``n`` realisations (the issue's
  measure: 10 x 20 = 200 runs within 5 minutes on 2 cores), as ``archdem fragility ID --sine F
  --amplitudes GRID --realizations N --no-deterministic`` runs it;
* throughput: simulations per core-second;
* the share of a run's wall time inside the engine's step (cProfile of one run in this process),
  and what the rest is;
* parallel efficiency: the same study on 1 and on 2 local workers, and on a local Dask cluster of
  2 workers (``--dask``), efficiency = t(1) / (workers x t(workers)).

    python benchmarks/bench_fragility.py [--id Sh06-Sd015] [--freq 2] [--amplitudes 0.30:0.39:0.01] [--n 20]
                                         [--efficiency-n 4] [--dask]
"""
from __future__ import annotations

import argparse
import cProfile
import os
import pstats
import tempfile
import time
from pathlib import Path

from _common import report


def _study(a, n: int, path: Path, workers: int | None = None, scheduler: str | None = None):
    from dem.experiments.fragility.run import DEFAULT_EDGE_LOSS_SD, Perturbation, arch_structure, fragility, sine_spec
    from specimens.catalogue import get_specimen
    from foundation.io import parse_grid

    amps = parse_grid(a.amplitudes)
    groups = [(f"{a.freq:g} Hz", "g", [(x, sine_spec(a.freq, x)) for x in amps])]
    t0 = time.perf_counter()
    res = fragility(a.id, arch_structure(get_specimen(a.id).arch), {"engine": a.engine},
                    Perturbation(edge_loss_sd=DEFAULT_EDGE_LOSS_SD, friction_cov=0.1), groups, n, 1, path,
                    workers=workers, scheduler=scheduler, progress=False)
    return res, time.perf_counter() - t0


def _engine_share(a) -> dict:
    """cProfile of one run (the middle amplitude): time inside the engine's step over the run's."""
    from dem.experiments.fragility.run import Perturbation, arch_structure, shake_case, sine_spec
    from specimens.catalogue import get_specimen
    from foundation.io import parse_grid

    amps = parse_grid(a.amplitudes)
    case = {"label": a.id, "structure": arch_structure(get_specimen(a.id).arch), "settings": {"engine": a.engine},
            "perturbation": Perturbation().describe(), "seed": 1, "realisation": 0, "group": "g",
            "intensity": amps[len(amps) // 2], "motion": sine_spec(a.freq, amps[len(amps) // 2])}
    shake_case(case)  # warm: imports and first connection
    prof = cProfile.Profile()
    t0 = time.perf_counter()
    prof.runcall(shake_case, case)
    total = time.perf_counter() - t0
    st = pstats.Stats(prof)
    step = sum(v[3] for k, v in st.stats.items() if k[2] == "step" and "engines" in k[0])
    build = sum(v[3] for k, v in st.stats.items() if k[2] == "build" and "engines" in k[0])
    return {"one_run_s": total, "engine_step_s": step, "engine_step_share": step / total,
            "engine_build_s": build, "rest_s": total - step - build}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--id", default="Sh06-Sd015")
    ap.add_argument("--freq", type=float, default=2.0)
    ap.add_argument("--amplitudes", default="0.30:0.39:0.01")
    ap.add_argument("--n", type=int, default=20)
    ap.add_argument("--efficiency-n", type=int, default=4)
    ap.add_argument("--engine", default="pybullet")
    ap.add_argument("--dask", action="store_true", help="also time a local Dask cluster of 2 workers")
    a = ap.parse_args()
    out: dict = {"specimen": a.id, "freq_hz": a.freq, "amplitudes": a.amplitudes, "engine": a.engine}
    with tempfile.TemporaryDirectory() as tmp:
        res, wall = _study(a, a.n, Path(tmp) / "curve.h5", workers=2)
        c = res.curves[0]
        out.update({"runs": res.n_runs, "wall_s": wall, "within_5_min": wall <= 300.0,
                    "sims_per_core_s": res.n_runs / (2 * wall),
                    "median_g": c.fit.median if c.fit else None, "beta": c.fit.beta if c.fit else None})
        t1 = _study(a, a.efficiency_n, Path(tmp) / "w1.h5", workers=1)[1]
        t2 = _study(a, a.efficiency_n, Path(tmp) / "w2.h5", workers=2)[1]
        out.update({"efficiency_runs": res.n_runs // a.n * a.efficiency_n, "t_1_worker_s": t1, "t_2_workers_s": t2,
                    "efficiency_local_2": t1 / (2 * t2)})
        if a.dask:
            import distributed

            with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                          dashboard_address=None) as cl:
                td = _study(a, a.efficiency_n, Path(tmp) / "dask.h5", scheduler=cl.scheduler_address)[1]
            out.update({"t_dask_2_workers_s": td, "efficiency_dask_2": t1 / (2 * td)})
    out.update(_engine_share(a))
    out["load_average"] = os.getloadavg()[0]
    report("fragility", out)


if __name__ == "__main__":
    main()
