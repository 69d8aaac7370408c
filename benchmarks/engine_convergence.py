"""Convergence in the time step of the frictional tilt threshold (docs/engines.md#8-convergence-in-the-numerical-settings), one specimen,
each engine: hold-protocol lambda at the reference friction (and optionally at no sliding)
for a sequence of dt. MuJoCo's internal step is settings.dt itself when dt <= 0.5 ms.
Writes benchmarks/results/engine_convergence_<id>.json (not part of ``make bench``: ~10-20 min).

    python benchmarks/engine_convergence.py [--id Sh1-Sd025] [--config glued]
        [--dts pybullet:1e-3,5e-4,2.5e-4 --dts mujoco:5e-4,2.5e-4,1.25e-4] [--friction reference]
"""
from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

OUT = Path(__file__).resolve().parent / "results"


def main() -> None:
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.compare_engines.run import FRICTIONS, engine_tilt
    from dem.experiments.tilt.check import reference_lp
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen
    from foundation.io import atomic_path

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--id", default="Sh1-Sd025")
    ap.add_argument("--config", default="glued")
    ap.add_argument("--friction", default="reference", choices=tuple(FRICTIONS))
    ap.add_argument("--dts", action="append", default=None, help="engine:dt1,dt2,... (repeatable)")
    ap.add_argument("--out", default=None, help="default benchmarks/results/engine_convergence_<id>.json")
    a = ap.parse_args()
    dts = a.dts or ["mujoco:5e-4,2.5e-4,1.25e-4", "pybullet:1e-3,5e-4,2.5e-4"]
    plan = [(e, float(x)) for spec in dts for e, xs in [spec.split(":")] for x in xs.split(",")]
    asm = discretise(get_specimen(a.id).arch, config=a.config)
    m = from_assembly(asm, name=a.id)
    mj, mb = FRICTIONS[a.friction]
    rows = []
    for e, dt in plan:
        t0 = time.perf_counter()
        r = engine_tilt(m, Settings(engine=e, dt=dt, mu_joint=mj, mu_base=mb))
        rows.append({"engine": e, "dt": dt, "lambda": r.lam, "mode": r.mode, "hinges": [list(h) for h in r.hinges],
                     "slides": list(r.slides), "n_sims": r.n_sims, "wall_s": time.perf_counter() - t0,
                     "load_avg_1min": os.getloadavg()[0]})
        print(json.dumps(rows[-1]), flush=True)
    lp = reference_lp(asm, mj, mb)
    res = {"id": a.id, "config": a.config, "friction": a.friction, "mu_joint": mj, "mu_base": mb,
           "lp_lambda": float(lp.lam), "lp_note": "associative LP (no bound with Coulomb friction)"
           if a.friction == "reference" else "exact at no sliding", "rows": rows}
    out = Path(a.out or OUT / f"engine_convergence_{a.id}.json")
    with atomic_path(out, overwrite=True) as tmp:
        Path(tmp).write_text(json.dumps(res, indent=2))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
