"""The record step: the least collapsing PGA of a recorded ground motion."""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from analytic.motions.inputs import SampledMotion
from analytic.motions.records import baseline_correct, read_record, with_zero_tail
from dem.common.campaign import CampaignContext, write_csv
from dem.core.model import as_model
from dem.core.progress import terminal
from dem.core.settings import Settings
from dem.experiments.record.run import RecordThreshold
from dem.experiments.shake import ShakeProtocol, static_onset, threshold
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT

RECORD_FILE = "RSN6_IMPVALL.I_I-ELC180.AT2"  # El Centro 1940, the shared record set


def record_plan(ctx: CampaignContext) -> list:
    ids = ["Sh02-Sd020"] if ctx.quick else ["Sh02-Sd020", "Sh06-Sd015", "Sh1-Sd020"]
    return [s for s in ctx.specimens if s.id in ids] or ctx.specimens[:1]


# ---------------------------------------------------------------------------- recorded motion
@dataclass(frozen=True)
class RecordAtPGA:
    """A picklable motion factory for :func:`dem.experiments.shake.thresholds.threshold`: the record scaled to a PGA.

    Called as ``(amplitude [m/s^2], freq)``; ``freq`` is ignored.
    """

    path: str
    t_start: float
    t_end: float

    def __call__(self, amplitude: float, freq: float):
        return record_window(self.path, self.t_start, self.t_end).to_pga(amplitude)


def record_window(path: str, t_start: float, t_end: float):
    """The part ``[t_start, t_end]`` [s] of a record file, baseline-corrected, with a 1 s zero tail."""
    m = read_record(path)
    i0, i1 = int(round(t_start / m.dt)), int(round(t_end / m.dt)) + 1
    w = SampledMotion(m.values[i0:i1], m.dt, name=f"{m.name} [{t_start:g}, {t_end:g}] s", source=m.source)
    return with_zero_tail(baseline_correct(w), 1.0)


def _record_path() -> Path:
    """The shared El Centro record, shipped with the project's test data (repository root: two folders up)."""
    return Path(__file__).resolve().parents[3] / "tests" / "data" / "ground_motions" / RECORD_FILE


def step_record(ctx: CampaignContext, d: Path) -> dict:
    """One recorded accelerogram scaled until collapse, for three specimens (one when quick)."""
    path = _record_path()
    full = read_record(path)
    t_pga = float(np.argmax(np.abs(full.values)) * full.dt)
    # strong-motion window around the peak: short enough to scan many amplitudes
    t0, t1 = max(0.0, t_pga - 1.0), t_pga + (2.0 if ctx.quick else 6.0)
    specs = record_plan(ctx)
    rows = []
    for s in specs:
        model = as_model(s, config=ctx.config, contact=ctx.contact_of(s))
        lam = static_onset(model, Settings(mu_joint=REFERENCE_MU_JOINT, mu_base=REFERENCE_MU_BASE))
        with terminal(f"[record] {s.id}", unit="runs") as line:
            r = threshold(model, 1.0, ctx.dynamics_of(s), ShakeProtocol(), a_min_g=lam, a_max_g=4 * lam, scan_ratio=1.25,
                          tol=0.02 if ctx.quick else 0.01, workers=ctx.workers, scheduler=ctx.scheduler,
                          motion_fn=RecordAtPGA(str(path), t0, t1), progress=line)
        rows += RecordThreshold.of(s.id, RECORD_FILE, (t0, t1), full.pga, lam, r.amplitude_g, r.mode, r.n_sims).rows()
    write_csv(d / "record.csv", rows, RecordThreshold.SCHEMA)
    found = [r for r in rows if math.isfinite(r["collapse_pga_g"])]
    findings = [f"{r['id']}: the El Centro 1940 window collapses the arch at PGA {r['collapse_pga_g']:.3f} g "
                f"(x{r['scale_factor']:.2f} the record, {r['ratio_to_static']:.2f} x the static lambda)." for r in found]
    return {
        "summary": ctx.joints_text() + " " + f"{RECORD_FILE} (El Centro 1940, PEER NGA), window {t0:.2f}-{t1:.2f} s around the peak, baseline-"
                   "corrected, 1 s zero tail; scaled to increasing PGA until collapse (scan, then bisection).",
        "tables": [{"name": "record", "title": "Recorded accelerogram scaled to collapse", "csv": "record/record.csv"}],
        "findings": findings,
    }
