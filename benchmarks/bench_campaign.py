"""Time of the whole campaign (`archdem campaign`: catalogue, analytic, tilt, map, shake, record)
end to end on all cores, per step next to the estimate the command prints first. The full
campaign by default (about 18 min on a 2-core machine); ``--quick`` times the one of
``make demo``. The campaign is written to a temporary folder and removed afterwards.
Writes benchmarks/results/campaign.json (campaign_quick.json with --quick).

    python benchmarks/bench_campaign.py [--quick] [--engine pybullet|mujoco] [--workers N]
"""
from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from pathlib import Path

OUT = Path(__file__).resolve().parent / "results"


def main() -> None:
    from dem.campaign.estimate import REFERENCE_SPEED, estimate, machine_speed
    from dem.campaign.runner import all_steps, run_campaign
    from dem.common.campaign import CampaignContext
    from dem.core.provenance import provenance
    from specimens.catalogue import select_specimens
    from foundation.io import atomic_path

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="the quick campaign of make demo")
    ap.add_argument("--engine", default="pybullet", choices=("pybullet", "mujoco"))
    ap.add_argument("--workers", type=int, default=None, help="processes (default: all cores)")
    a = ap.parse_args()
    steps = list(all_steps())
    with tempfile.TemporaryDirectory(prefix="archdem-bench-campaign-") as d:
        ctx = CampaignContext(out=Path(d) / "campaign", specimens=select_specimens("all"), engine=a.engine,
                              quick=a.quick, workers=a.workers)
        speed = machine_speed(a.engine)
        est = estimate(ctx, steps, speed=speed)
        load0 = list(os.getloadavg())
        t0 = time.perf_counter()
        manifest = run_campaign(ctx)
        wall = time.perf_counter() - t0
    per_step = {name: {"wall_s": manifest["steps"][name]["wall_s"],
                       **({"estimate_s": est[name]["wall_s"], "units": est[name]["units"], "what": est[name]["what"]}
                          if name in est else {})}
                for name in steps}
    res = {"campaign": "quick" if a.quick else "full", "engine": a.engine, "specimens": len(ctx.specimens),
           "config": ctx.config, "workers": a.workers or os.cpu_count(), "cpu_count": os.cpu_count(),
           "machine_speed_s_per_sim_s": speed, "reference_speed": REFERENCE_SPEED[a.engine],
           "estimate_s": sum(e["wall_s"] for e in est.values()), "wall_s": wall, "steps": per_step,
           "load_avg_start": load0, "load_avg_end": list(os.getloadavg()), "provenance": provenance()}
    OUT.mkdir(exist_ok=True)
    out = OUT / ("campaign_quick.json" if a.quick else "campaign.json")
    with atomic_path(out, overwrite=True) as tmp:
        Path(tmp).write_text(json.dumps(res, indent=2, default=str))
    print(json.dumps({k: v for k, v in res.items() if k != "provenance"}, indent=1, default=str))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
