"""Speed of the DEM: one tilt test (median of repeats), the 11-specimen campaign on 2 cores, and
wall time per simulated second for 15, 17, 68 and 272 bodies. Writes benchmarks/results/dem.json.

    python benchmarks/bench_dem.py [--repeats 3] [--skip-campaign]
"""
from __future__ import annotations

import argparse
import json
import statistics
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

OUT = Path(__file__).resolve().parent / "results"


def _tilt(sid: str) -> dict:
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.tilt.run import tilt
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    asm = discretise(get_specimen(sid).arch, config="glued")
    m = from_assembly(asm, name=sid)
    t0 = time.perf_counter()
    r = tilt(m, Settings(), assembly=asm)  # the default protocol: LP-started hold-and-bisect to 0.5 %
    return {"id": sid, "lambda": r.lam, "mode": r.mode, "n_sims": r.n_sims, "wall_s": time.perf_counter() - t0}


def per_simulated_second(model, seconds: float = 1.0) -> float:
    from dem.core.loads import Rest
    from dem.core.settings import Settings
    from dem.core.simulate import simulate

    r = simulate(model, Settings(), Rest(), seconds, record_every=0.1, stop_on_collapse=False, friction_work=False)
    return r.wall_s / seconds


def main() -> None:
    from dem.core.model import from_assembly, side_by_side
    from specimens.blocks import discretise
    from specimens.catalogue import SPECIMEN_IDS, get_specimen

    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--skip-campaign", action="store_true")
    a = ap.parse_args()
    res: dict = {}
    runs = [_tilt("Sh06-Sd015") for _ in range(a.repeats)]
    res["one_tilt"] = {"id": "Sh06-Sd015", "config": "glued", "mu": "0.577/1.0",
                       "median_wall_s": statistics.median(r["wall_s"] for r in runs), "runs": runs}
    if not a.skip_campaign:
        t0 = time.perf_counter()
        with ProcessPoolExecutor(2) as ex:
            rows = list(ex.map(_tilt, SPECIMEN_IDS))
        res["campaign_2_cores"] = {"wall_s": time.perf_counter() - t0, "rows": rows}
    arch = get_specimen("Sh06-Sd015").arch
    glued = from_assembly(discretise(arch, config="glued"))
    free = from_assembly(discretise(arch, config="free"))
    cases = {15: glued, 17: free, 68: side_by_side(free, 4), 272: side_by_side(free, 16)}
    res["wall_per_simulated_s"] = {str(n): per_simulated_second(m) for n, m in cases.items()}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "dem.json").write_text(json.dumps(res, indent=1))
    print(json.dumps({k: v for k, v in res.items() if k != "campaign_2_cores"}, indent=1))
    if "campaign_2_cores" in res:
        print("campaign wall", res["campaign_2_cores"]["wall_s"])


if __name__ == "__main__":
    main()
