"""The shake step: one-cycle sine thresholds of the DEM against the four-bar and two-bar linkages."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from analytic.motions.inputs import SinePulse
from dem.common.campaign import CampaignContext, write_csv
from dem.core.model import from_assembly
from dem.core.progress import terminal
from dem.experiments.shake.domain import DomainThreshold, analytic_domains, dem_failure_domain
from dem.experiments.shake.run import shake
from specimens.blocks import discretise
from specimens.constants import G

SHAKE_FREQS = (2.0, 4.0, 6.0, 8.0, 10.0)  # Hz, the reference study's pulses


QUICK_SHAKE = (("Sh02-Sd020",), (2.0, 6.0))  # quick campaign: one specimen, two frequencies
#: Each threshold's search by quick: (top of the scan over the static lambda, bisection tolerance).
SHAKE_SEARCH = {True: (4.0, 0.02), False: (6.0, 0.01)}
#: Each threshold's check by quick: the quick campaign asks the half step only (LMGC90 costs minutes).
SHAKE_CHECK = {True: "half-step", False: True}


def shake_plan(ctx: CampaignContext) -> tuple[list, tuple[float, ...]]:
    """Specimens and pulse frequencies [Hz] of the shake step."""
    if ctx.quick:
        ids, freqs = QUICK_SHAKE
        return [s for s in ctx.specimens if s.id in ids] or ctx.specimens[:1], freqs
    return [s for s in ctx.specimens if round(s.arch.Sd, 3) in (0.15, 0.2)], SHAKE_FREQS


# --------------------------------------------------------------------------------- shake table
def _lowest_threshold(domain) -> dict[float, float]:
    """Least collapsing amplitude [g] per frequency of an analytic failure domain (or {})."""
    out: dict[float, float] = {}
    for p in (domain.points() if domain is not None else []):
        out[p["x"]] = min(out.get(p["x"], math.inf), p["amplitude_g"])
    return out


def step_shake(ctx: CampaignContext, d: Path) -> dict:
    """Shake-table thresholds (one-cycle sine) of the Sd = 0.15 and 0.20 specimens next to the four-bar."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.shake.figure import plot_domain_over_analytic

    specs, freqs = shake_plan(ctx)
    rows, figures = [], []
    for s in specs:
        c = ctx.contact_of(s)
        with terminal(f"[shake] {s.id}", unit="frequencies") as line:
            dem = dem_failure_domain(s.id, s.arch, freqs, ctx.config, workers=ctx.workers, scheduler=ctx.scheduler,
                                     settings=ctx.dynamics_of(s), disc_kw={"contact": c} if c != 1.0 else None,
                                     a_max_ratio=SHAKE_SEARCH[ctx.quick][0], tol=SHAKE_SEARCH[ctx.quick][1],
                                     progress=line, check=SHAKE_CHECK[ctx.quick])
        ana = analytic_domains(s.arch, freqs, workers=1, **({"contact": c} if c != 1.0 else {}))
        fb, tb = _lowest_threshold(ana.get("four-bar")), _lowest_threshold(ana.get("two-bar"))
        rows += [r for t in dem["thresholds"]
                 for r in DomainThreshold.of(s.id, dem["lambda"], t, fb.get(t["freq"]), tb.get(t["freq"])).rows()]
        figures += _threshold_histories(s, dem, ctx, d)
        png = d / f"domain_{s.id}.png"
        plot_domain_over_analytic(dem, ana, png, title=f"{s.id}: DEM vs rocking linkages, one-cycle sine")
        figures.append({"path": f"shake/{png.name}", "caption": f"{s.id}: DEM shake thresholds over the analytic domains"})
    write_csv(d / "shake.csv", rows, DomainThreshold.SCHEMA)
    ratios = np.array([r["ratio_dem_to_four_bar"] for r in rows], dtype=float)
    ok = np.isfinite(ratios)
    findings = []
    if ok.any():
        findings.append(f"DEM / four-bar collapse amplitude ratio: {np.nanmin(ratios):.2f}-{np.nanmax(ratios):.2f} over "
                        f"{int(ok.sum())} (specimen, frequency) pairs; the four-bar is conservative (ratio > 1) in "
                        f"{int(np.sum(ratios[ok] > 1))} of them.")
    windows = [f"{r['id']} {r['freq_Hz']:g} Hz ({r['survival_bands_above']} g)" for r in rows if r["survival_bands_above"]]
    findings.append("Survival windows above the first collapse amplitude: " + ("; ".join(windows) if windows else "none found")
                    + ".")
    findings.append(verdict_finding(rows))
    return {
        "summary": ctx.joints_text() + " " + "Plain one-cycle sine pulses; least collapsing amplitude by amplitude scan then bisection of the lowest "
                   "collapsing bracket; four-bar (minimised layout) and two-bar thresholds for the same input. "
                   f"Engine: {ctx.dynamics_engine}. Each threshold is settled (its bracket reads the same at half the "
                   "step and, at 4-10 Hz with joints free to slide, on LMGC90"
                   + (", which the quick campaign does not ask: unchecked there" if ctx.quick else "")
                   + ") or a range holding every reading "
                   "(docs/decisions/011-dynamics-engine.md#settled-or-a-range). Which features of these thresholds "
                   "belong to the arch and which to the engine (three engines, two time steps): "
                   "docs/validation.md#19-three-engine-shake-study.",
        "tables": [{"name": "shake", "title": "Shake-table thresholds [g]", "csv": "shake/shake.csv"}],
        "figures": figures, "findings": findings,
    }


def verdict_finding(rows: list[dict]) -> str:
    """One finding: how many thresholds are settled, a range or unchecked, and what the checks cost."""
    n = {k: sum(r["verdict"] == k for r in rows) for k in ("settled", "range", "unchecked")}
    ranges = [f"{r['id']} {r['freq_Hz']:g} Hz {r['verdict_text']}" for r in rows if r["verdict"] != "settled"]
    return (f"Thresholds settled: {n['settled']} of {len(rows)}; a range: {n['range']}; unchecked: {n['unchecked']}"
            + (f" ({'; '.join(ranges)})" if ranges else "")
            + f". The checks ran {sum(r['check_runs'] for r in rows)} runs in {sum(r['check_wall_s'] for r in rows):.0f} s.")


def _threshold_histories(spec, dem: dict, ctx: CampaignContext, d: Path) -> list[dict]:
    """Time histories just below and at the first DEM threshold (lowest frequency that has one)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.shake.figure import save_shake_figure

    t = next((t for t in dem["thresholds"] if t["amplitude_g"] is not None), None)
    if t is None:
        return []
    model = from_assembly(discretise(spec.arch, config=ctx.config, contact=ctx.contact_of(spec)), name=spec.id)
    out = []
    for what, a_g in (("survival", t["bracket_g"][0]), ("collapse", t["bracket_g"][1])):
        res = shake(model, SinePulse(a_g * G, t["freq"]), ctx.dynamics_of(spec), label=spec.id)
        png = save_shake_figure(res, d / f"history_{spec.id}_{t['freq']:g}Hz_{what}.png")
        out.append({"path": f"shake/{png.name}",
                    "caption": f"{spec.id}, {t['freq']:g} Hz sine at {a_g:.3f} g ({what} side of the threshold): "
                               "crown displacement and input"})
    return out
