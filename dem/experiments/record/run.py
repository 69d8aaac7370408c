"""The virtual check of a code assessment: the structure shaken by records matched to the site
(docs/physics/assessment.md#6-records-matched-to-the-site).

Each matched record (:func:`analytic.motions.matching.match_record`) is run on the DEM model; the answer per
record is collapse or not and the peak displacement of the equivalent oscillator, ``d* = d_C / e*``
with ``d_C`` the horizontal displacement of the bodies' mass centroid (the control point of the
capacity curve). The verdict follows the codes' rule for non-linear dynamic analysis of a local
mechanism: no record reaches ``d0*`` (nor collapses) and the mean peak is at most ``d_u*``.

What a record file holds (``archdem record``) is :func:`run` of a :class:`RecordSpec`, a
:class:`RecordSummary`; the record step's row, a recorded motion scaled until collapse, is a
:class:`RecordThreshold`. Each declares its table once (:class:`dem.experiments.contract.Result`).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np

from analytic.motions.records import load_record
from dem.core.settings import Settings, dynamics_settings
from dem.experiments.contract import COLUMNS_ARE_FIELDS, Result, Schema
from dem.experiments.shake import ShakeProtocol, shake
from specimens.constants import G
from foundation.processes import worker_pool


def _row(result) -> dict:
    """A one-row result's row: its fields named as its schema's columns."""
    return {c.name: getattr(result, c.name) for c in result.SCHEMA.columns}


@dataclass(frozen=True)
class RecordSpec:
    """A record file to read: ``path``, its ``format`` (``auto``: detect) and ``units`` (None: from the file)."""

    path: str
    format: str = "auto"
    units: str | None = None


@dataclass(frozen=True)
class RecordSummary(Result):
    """What a record file holds: name, sampling [s], duration [s] and PGA (in g and m/s^2, at ``t_pga`` [s])."""

    SCHEMA: ClassVar[Schema] = COLUMNS_ARE_FIELDS

    file: str
    name: str
    format: str
    units: str
    units_from: str
    npts: int
    dt: float = field(metadata={"unit": "s"})
    duration: float = field(metadata={"unit": "s"})
    pga_g: float = field(metadata={"unit": "g"})
    pga_ms2: float = field(metadata={"unit": "m/s^2"})
    t_pga: float = field(metadata={"unit": "s"})

    def rows(self) -> list[dict]:
        return [_row(self)]

    def lines(self) -> list[str]:
        """The text of ``archdem record``."""
        return [f"file      {self.file}", f"name      {self.name}",
                f"format    {self.format}   units {self.units} ({self.units_from})",
                f"npts      {self.npts}   dt {self.dt:g} s   duration {self.duration:.3f} s",
                f"PGA       {self.pga_g:.4f} g = {self.pga_ms2:.4f} m/s^2 at t = {self.t_pga:.3f} s"]


def run(spec: RecordSpec) -> RecordSummary:
    """Read ``spec``'s record file (:func:`analytic.motions.records.load_record`) and say what it holds."""
    rec = load_record(spec.path, spec.format, spec.units)
    m = rec.motion
    k = int(np.argmax(np.abs(m.values)))
    return RecordSummary(str(spec.path), m.name, rec.format, rec.units, rec.units_from, len(m.values), m.dt,
                         m.duration, m.pga / G, m.pga, k * m.dt)


@dataclass(frozen=True)
class RecordThreshold(Result):
    """One row of the record step: the least collapsing PGA [g] of a record's window on one specimen
    (NaN when nothing up to the scan's top collapsed), against the record's own PGA and the static lambda."""

    SCHEMA: ClassVar[Schema] = COLUMNS_ARE_FIELDS

    id: str
    record: str
    window_s: str = field(metadata={"unit": "s"})  # "t0-t1" [s]
    pga_record_g: float = field(metadata={"unit": "g"})
    lambda_static: float
    collapse_pga_g: float = field(metadata={"unit": "g"})
    scale_factor: float  # the collapsing PGA / the record's
    ratio_to_static: float  # the collapsing PGA / lambda
    mode: str
    n_sims: int

    @classmethod
    def of(cls, sid: str, record: str, window: tuple[float, float], pga_record: float, lam: float,
           amplitude_g: float | None, mode: str, n_sims: int) -> "RecordThreshold":
        """The row of a threshold search's answer ``amplitude_g`` [g] (None: no collapse) on a record of PGA
        ``pga_record`` [m/s^2] cut to ``window`` [s]."""
        nan = float("nan")
        a = amplitude_g
        return cls(sid, record, f"{window[0]:.2f}-{window[1]:.2f}", pga_record / G, lam, nan if a is None else a,
                   nan if a is None else a * G / pga_record, nan if a is None else a / lam, mode or "", n_sims)

    def rows(self) -> list[dict]:
        return [_row(self)]


@dataclass(frozen=True)
class RecordRun(Result):
    """One matched record on the DEM: ``peak_d_star`` [m] (up to collapse), ``collapsed``, ``mode``."""

    SCHEMA: ClassVar[Schema] = COLUMNS_ARE_FIELDS

    record: str
    scale: float
    pga: float = field(metadata={"unit": "m/s^2"})
    collapsed: bool
    mode: str
    peak_d_star: float = field(metadata={"unit": "m"})
    wall_s: float = field(metadata={"unit": "s"})

    def rows(self) -> list[dict]:
        return [_row(self)]

    def describe(self) -> dict:
        return self.to_json()[0]


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

    with worker_pool(min(workers, len(jobs))) as ex:
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
