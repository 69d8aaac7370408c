"""The virtual check of a code assessment: the structure shaken by records matched to the site
(docs/physics/assessment.md#6-records-matched-to-the-site).

Each matched record (:func:`analytic.motions.matching.match_record`) is run on the DEM model; the answer per
record is collapse or not and the peak displacement of the equivalent oscillator, ``d* = d_C / e*``
with ``d_C`` the horizontal displacement of the bodies' mass centroid (the control point of the
capacity curve). The verdict follows the codes' rule for non-linear dynamic analysis of a local
mechanism: no record reaches ``d0*`` (nor collapses) and the mean peak is at most ``d_u*``.
"""
from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass

import numpy as np

from dem.core.settings import Settings, dynamics_settings
from dem.experiments.shake.run import ShakeProtocol, shake
from foundation.processes import pool_worker_init


@dataclass(frozen=True)
class RecordRun:
    """One matched record on the DEM: ``peak_d_star`` [m] (up to collapse), ``collapsed``, ``mode``."""

    record: str
    scale: float
    pga: float
    collapsed: bool
    mode: str
    peak_d_star: float
    wall_s: float

    def describe(self) -> dict:
        return {"record": self.record, "scale": self.scale, "pga": self.pga, "collapsed": self.collapsed,
                "mode": self.mode, "peak_d_star": self.peak_d_star, "wall_s": self.wall_s}


def _one(job) -> RecordRun:
    target, motion, settings, protocol, e_star = job
    r = shake(target, motion, settings, protocol, friction_work=False)
    m = np.array([b.mass for b in r.model.bodies])
    x0 = np.array([b.centroid[0] for b in r.model.bodies])
    d_C = (r.sim.history.pos[:, :, 0] - x0) @ m / m.sum()
    return RecordRun(motion.name, float(motion.scale), float(motion.pga), r.collapsed, r.mode,
                     float(np.max(np.abs(d_C)) / e_star) if len(d_C) else 0.0, float(r.sim.wall_s))


def run_records(target, motions, e_star: float, settings: Settings | None = None,
                protocol: ShakeProtocol | None = None, workers: int = 1) -> list[RecordRun]:
    """Shake ``target`` (an assembly or model) with each of ``motions`` (matched, scaled records) in
    ``workers`` processes; results in input order."""
    jobs = [(target, m, settings or dynamics_settings(), protocol or ShakeProtocol(), e_star) for m in motions]
    if workers <= 1 or len(jobs) <= 1:
        return [_one(j) for j in jobs]

    with ProcessPoolExecutor(min(workers, len(jobs)), initializer=pool_worker_init) as ex:
        return list(ex.map(_one, jobs))


def dem_verdict(runs: list[RecordRun], d0_star: float, du_star: float) -> dict:
    """The codes' rule over the records: none collapses or reaches ``d0*``, and the mean peak
    ``d*`` is at most ``d_u*``."""
    peaks = [r.peak_d_star for r in runs]
    reach = [r.collapsed or r.peak_d_star >= d0_star for r in runs]
    mean = float(np.mean(peaks)) if peaks else float("nan")
    return {"n_records": len(runs), "n_collapsed": sum(r.collapsed for r in runs), "n_reach_d0": int(sum(reach)),
            "mean_peak_d_star": mean, "max_peak_d_star": float(max(peaks)) if peaks else float("nan"),
            "d0_star": d0_star, "du_star": du_star, "verified": bool(not any(reach) and mean <= du_star)}
