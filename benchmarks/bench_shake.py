"""Speed of the shake table: one 1.5 s shake simulation of a glued specimen (median of repeats;
target <= 1 s wall) and one threshold search (scan + bisection to 1 %) on 2 cores (target
<= 20 s). Writes benchmarks/results/shake.json.

    python benchmarks/bench_shake.py [--repeats 3] [--id Sh02-Sd020] [--freq 4]
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import time
from pathlib import Path

from _common import timed_threshold

OUT = Path(__file__).resolve().parent / "results"


def main() -> None:
    from analytic.motions.inputs import SinePulse
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.shake.run import ShakeProtocol, shake
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen
    from specimens.constants import G

    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--id", default="Sh02-Sd020")
    ap.add_argument("--freq", type=float, default=4.0)
    a = ap.parse_args()
    arch = get_specimen(a.id).arch
    model = from_assembly(discretise(arch, config="glued"), name=a.id)
    st = Settings()
    res: dict = {"id": a.id, "config": "glued", "mu": "0.577/1.0", "cpu_count": os.cpu_count(),
                 "load_average_at_start": list(os.getloadavg())}
    # one 1.5 s simulation: a 4 Hz sine below the threshold (the arch survives; all 3000 steps run:
    # no end at rest, which would stop this run at about 0.4 s)
    runs = []
    for _ in range(a.repeats):
        t0 = time.perf_counter()
        r = shake(model, SinePulse(0.3 * G, a.freq), st, ShakeProtocol(duration=1.5, rest_after=None))
        runs.append({"wall_s": time.perf_counter() - t0, "sim_wall_s": r.sim.wall_s, "steps": r.sim.steps,
                     "collapsed": r.collapsed})
    res["one_shake_1.5s"] = {"input": f"sine {a.freq:g} Hz 0.3 g", "median_wall_s": statistics.median(x["wall_s"] for x in runs),
                             "target_s": 1.0, "runs": runs}
    th, lam, wall = timed_threshold(a.id, a.freq, workers=2)
    res["one_threshold_2_cores"] = {"freq": a.freq, "wall_s": wall, "target_s": 20.0,
                                    "amplitude_g": th.amplitude_g, "bracket_g": th.bracket_g, "n_sims": th.n_sims,
                                    "survival_bands_above": th.survival_bands_above, "static_lambda": lam}
    res["load_average_at_end"] = list(os.getloadavg())
    OUT.mkdir(exist_ok=True)
    (OUT / "shake.json").write_text(json.dumps(res, indent=2))
    print(json.dumps(res, indent=2))


if __name__ == "__main__":
    main()
