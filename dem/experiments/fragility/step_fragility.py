"""The fragility step: collapse probability under one-cycle sine pulses from ensembles of perturbed
realisations, beside the deterministic DEM threshold and the four-bar (docs/physics/fragility.md)."""
from __future__ import annotations

import functools
import math
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from analytic.rocking.domain import failure_domain as linkage_domain
from analytic.rocking.linkage import minimised_four_bar
from dem.common.campaign import CampaignContext, studies_dir, write_csv
from dem.core.model import as_model
from dem.core.progress import terminal
from dem.experiments.contract import Column, Schema
from dem.experiments.fragility.figure import fragility_figure
from dem.experiments.fragility.file import write_tables
from dem.experiments.fragility.run import (
    DEFAULT_EDGE_LOSS_SD,
    DEFAULT_FRICTION_COV,
    Perturbation,
    arch_structure,
    fragility,
    sine_spec,
)
from dem.experiments.shake import ShakeProtocol, static_onset, threshold
from specimens.constants import G

#: Frequencies [Hz] and amplitude grids (multiples of the static onset lambda) of the study: around the
#: threshold at 2 Hz (~1.2 lambda), wider where thresholds scatter (4, 6 Hz).
GRIDS = {2.0: (1.0, 1.4, 0.05), 4.0: (1.2, 2.6, 0.2), 6.0: (1.6, 4.4, 0.4)}
#: Realisations per stripe, quick and full.
N_QUICK, N_FULL = 5, 20
#: The step's table: per specimen and frequency the fit, the nominal threshold and the four-bar's.
MEDIANS_SCHEMA = Schema((
    Column("id", "str"), Column("freq_hz", "float", "Hz"), Column("lambda_static", "float"),
    Column("realisations", "int"), Column("runs", "int"), Column("median_g", "float", "g"), Column("beta", "float"),
    Column("median_ci_low", "float", "g"), Column("median_ci_high", "float", "g"),
    Column("deterministic_g", "float", "g"), Column("four_bar_g", "float", "g"), Column("note", "str"),
))


def fragility_plan(ctx: CampaignContext) -> tuple[list, list[float], int]:
    """(specimens, frequencies, realisations): one specimen at 2 Hz when quick, the Sd 0.15 / 0.20
    specimens at 2, 4, 6 Hz in full."""
    if ctx.quick:
        specs = [s for s in ctx.specimens if s.id == "Sh06-Sd015"] or ctx.specimens[:1]
        return specs, [2.0], N_QUICK
    specs = [s for s in ctx.specimens if s.id.endswith(("Sd015", "Sd020"))] or ctx.specimens[:1]
    return specs, sorted(GRIDS), N_FULL


def step_fragility(ctx: CampaignContext, d: Path) -> dict:
    """Per specimen and frequency: the fitted median and beta, the nominal structure's threshold and
    the four-bar's overturning amplitude."""

    specs, freqs, n = fragility_plan(ctx)
    pert = Perturbation(edge_loss_sd=DEFAULT_EDGE_LOSS_SD, friction_cov=DEFAULT_FRICTION_COV)
    rows, figures = [], []
    for s in specs:
        dyn = ctx.dynamics_of(s)
        settings = {"engine": dyn.engine, "dt": dyn.dt, **ctx.law_of(s)}  # written into the study
        model = as_model(s, config=ctx.config)
        lam = static_onset(model, dyn)
        groups, det = [], {}

        def nominal(f: float, a_max_g: float, s=s, model=model, dyn=dyn, lam=lam) -> float:
            with terminal(f"[fragility] {s.id} {f:g} Hz threshold", unit="runs") as line:
                return threshold(model, f, dyn, ShakeProtocol(), a_min_g=lam, a_max_g=a_max_g,
                                 workers=ctx.workers, scheduler=ctx.scheduler, progress=line).amplitude_g

        for f in freqs:
            lo, hi, increment = GRIDS[f]
            amps = [round(k * lam, 4) for k in np.arange(lo, hi + 1e-9, increment)]
            groups.append((f"{f:g} Hz", "g", [(a, sine_spec(f, a)) for a in amps]))
            det[f"{f:g} Hz"] = functools.partial(nominal, f, 2 * amps[-1])  # run once the study file exists
        res = fragility(s.id, arch_structure(s.arch, ctx.config), settings, pert, groups, n, 1,
                        studies_dir(ctx) / f"fragility-{s.id}.h5", workers=ctx.workers, scheduler=ctx.scheduler,
                        resume=True, progress=True, deterministic=det)
        write_tables(res, d / f"fragility-{s.id}.h5")
        fig = fragility_figure(res)
        fig.savefig(d / f"fragility-{s.id}.png", dpi=120)
        figures.append({"path": f"fragility/fragility-{s.id}.png", "caption": f"{s.id}: fragility curves"})
        fb = linkage_domain(minimised_four_bar(s.arch), "sine0", freqs, workers=1)
        for c, f, col in zip(res.curves, freqs, fb.columns):
            four_bar = col.thresholds[0][0] / G if col.thresholds else math.nan
            rows.append({"id": s.id, "freq_hz": f, "lambda_static": lam, "realisations": n,
                         "runs": sum(p.n for p in c.stripes),
                         "median_g": c.fit.median if c.fit else math.nan, "beta": c.fit.beta if c.fit else math.nan,
                         "median_ci_low": c.fit.median_ci[0] if c.fit else math.nan,
                         "median_ci_high": c.fit.median_ci[1] if c.fit else math.nan,
                         "deterministic_g": c.deterministic if c.deterministic is not None else math.nan,
                         "four_bar_g": four_bar, "note": c.fit_note})
    write_csv(d / "fragility.csv", rows, MEDIANS_SCHEMA)
    if len(freqs) > 1:
        fig = Figure(figsize=(6.4, 4.2))
        ax = fig.subplots()
        for k, s in enumerate(specs):
            r = [x for x in rows if x["id"] == s.id]
            f = [x["freq_hz"] for x in r]
            ax.errorbar(f, [x["median_g"] for x in r], yerr=[[x["median_g"] - x["median_ci_low"] for x in r],
                        [x["median_ci_high"] - x["median_g"] for x in r]], fmt="o-", color=f"C{k}", capsize=3,
                        label=f"{s.id} median")
            ax.plot(f, [x["deterministic_g"] for x in r], "x", color=f"C{k}")
            ax.plot(f, [x["four_bar_g"] for x in r], ":", color=f"C{k}")
        ax.set(xlabel="frequency [Hz]", ylabel="amplitude [g]",
               title="fragility median (o), deterministic DEM (x), four-bar (dotted)")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(d / "fragility-medians.png", dpi=120)
        figures.append({"path": "fragility/fragility-medians.png", "caption": "median vs frequency"})
    findings = [f"{r['id']} at {r['freq_hz']:g} Hz: median {r['median_g']:.3f} g (95 % {r['median_ci_low']:.3f}-"
                f"{r['median_ci_high']:.3f}), beta {r['beta']:.3f}; deterministic DEM {r['deterministic_g']:.3f} g, "
                f"four-bar {r['four_bar_g']:.3f} g." for r in rows]
    return {
        "summary": ctx.joints_text() + " " + f"{n} realisations per stripe (joint edge-loss scatter {DEFAULT_EDGE_LOSS_SD * 1e3:g} mm, friction "
                   f"CoV {DEFAULT_FRICTION_COV:g}), one-cycle sine pulses at {', '.join(f'{f:g}' for f in freqs)} Hz, "
                   "stripes in multiples of the static onset; lognormal fits by maximum likelihood with bootstrap "
                   "intervals.",
        "tables": [{"name": "fragility", "title": "Fragility medians", "csv": "fragility/fragility.csv"}],
        "figures": figures,
        "findings": findings,
    }
