"""Arches on piers and the rocking frame against limit analysis and the closed forms
(docs/validation.md#15-arches-on-piers).

1. Tilt, no sliding, both engines: Sh06-Sd015 on piers 3 t wide in 4 courses, heights 0 to 2.5
   rises (the campaign's full plan), DEM lambda against the LP, hinges, wall time of each test.
2. The rocking frame (piers 0.1 x 0.4 m, lintel 0.5 x 0.05 m, planar, no sliding): DEM outcome of a
   plain one-cycle sine at ratios 0.5-1.1 of the closed-form overturning amplitude, 2, 3, 5 Hz,
   light (gamma 0.03) and heavy (gamma 0.63) lintel, both engines.

Writes benchmarks/results/validate_piers[-N].json.

    python benchmarks/validate_piers.py [--engines pybullet,mujoco] [--workers 2]
"""
from __future__ import annotations

import argparse
import math
import time
from concurrent.futures import ProcessPoolExecutor

from _common import report

RATIOS = (0.5, 0.7, 0.85, 0.9, 0.95, 1.02, 1.05, 1.1)
B, H = 0.05, 0.2


def tilt_job(job: tuple[str, float]) -> dict:
    engine, k = job
    from analytic.limit.limit_discrete import solve_lp
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.tilt.run import tilt
    from specimens import Piers, discretise, get_specimen
    from specimens.constants import NO_SLIDING_MU

    a = get_specimen("Sh06-Sd015").arch
    asm = discretise(a, piers=Piers(k * a.rise, 3 * a.t, courses=4) if k else None)
    lp = solve_lp(asm, math.inf, math.inf)
    t0 = time.perf_counter()
    r = tilt(from_assembly(asm), Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, engine=engine))
    return {"engine": engine, "height_over_rise": k, "lambda_lp": lp.lam, "lambda_dem": r.lam,
            "err_pct": 100 * (r.lam / lp.lam - 1), "hinges_lp": [j for j, _ in lp.hinges],
            "hinges_dem": [j.joint for j in r.joints if j.state == "hinge"], "mode": r.mode,
            "n_sims": r.n_sims, "wall_s": time.perf_counter() - t0}


def frame_job(job: tuple[str, float, float]) -> dict:
    engine, beam_density, freq = job
    from analytic.motions.inputs import SinePulse
    from analytic.rocking.domain import domain_column
    from analytic.rocking.rocking_block import rocking_frame_equivalent
    from dem.core.model import frame_model
    from dem.core.settings import Settings
    from dem.experiments.shake.run import ShakeProtocol, shake
    from specimens.constants import NO_SLIDING_MU, G
    from specimens.frame import rocking_frame

    f = rocking_frame(B, H, 0.3, 0.05, beam_density=beam_density)
    blk, r = rocking_frame_equivalent(B, H, f.gamma)
    a = domain_column(blk, "sine0", freq, 0.2 * G, 2 * G, n_scan=12, restitution=r).thresholds[0][0]
    m = frame_model(f)
    s = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, planar=True, engine=engine)
    out = {ratio: shake(m, SinePulse(ratio * a, freq), s, ShakeProtocol(tail=2.0)).collapsed for ratio in RATIOS}
    return {"engine": engine, "gamma": f.gamma, "freq": freq, "closed_form_g": a / G,
            "collapsed": {f"{k:g}": v for k, v in out.items()},
            "collapse_from": min((x for x in RATIOS if all(out[y] for y in RATIOS if y >= x)), default=None)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--engines", default="pybullet,mujoco")
    ap.add_argument("--workers", type=int, default=2)
    a = ap.parse_args()
    from dem.experiments.tilt.step_piers import PIER_HEIGHTS_FULL
    from foundation.processes import die_with_parent

    engines = a.engines.split(",")
    with ProcessPoolExecutor(a.workers, initializer=die_with_parent) as ex:
        tilts = list(ex.map(tilt_job, [(e, k) for e in engines for k in PIER_HEIGHTS_FULL]))
        frames = list(ex.map(frame_job, [(e, bd, f) for e in engines for bd in (50.0, 1000.0) for f in (2.0, 3.0, 5.0)]))
    for t in tilts:
        print(f"{t['engine']:9s} H/rise {t['height_over_rise']:4.2f}  LP {t['lambda_lp']:.4f}  DEM {t['lambda_dem']:.4f} "
              f"({t['err_pct']:+.2f} %)  {t['mode']:8s} LP {' '.join(t['hinges_lp'])} | DEM {' '.join(t['hinges_dem'])}  "
              f"{t['wall_s']:.1f} s")
    for f in frames:
        print(f"{f['engine']:9s} gamma {f['gamma']:.3f} {f['freq']:g} Hz closed form {f['closed_form_g']:.4f} g  "
              f"collapse from {f['collapse_from']}  {f['collapsed']}")
    report("validate_piers", {"tilts": tilts, "frames": frames})


if __name__ == "__main__":
    main()
