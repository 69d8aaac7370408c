"""Simulator steps of the campaign: tilt tests, friction map, shake thresholds, a recorded motion.

Each step writes its tables / figures into the step folder and returns the outputs the report
reads (see :mod:`dem.report`); findings are sentences computed from the results. The
simulations run through the sweep engine (:mod:`dem.sweep`) into study files under
``OUT/studies/`` that live outside the step folders, so an interrupted campaign resumes
them without recomputing finished cases.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from dem.campaign import CampaignContext, _write_csv
from specimens.catalogue import REFERENCE_MU_BASE, REFERENCE_MU_JOINT

NO_SLIDING = 10.0  # "friction high enough to prevent sliding" (spec 03 §3.4), block-block and base
SHAKE_FREQS = (2.0, 4.0, 6.0, 8.0, 10.0)  # Hz, the reference study's pulses
QUICK_SHAKE = (("Sh02-Sd020",), (2.0, 6.0))  # quick campaign: one specimen, two frequencies
QUICK_MAP = ("Sh02-Sd015", "Sh1-Sd025")  # quick map: the thin/round-ish and the thick/sharp end
RECORD_FILE = "RSN6_IMPVALL.I_I-ELC180.AT2"  # El Centro 1940, the shared record set


# ------------------------------------------------------------------------ what each step runs
def _tilt_frictions(ctx: CampaignContext) -> dict[str, tuple[float, float]]:
    frictions = {"reference": (REFERENCE_MU_JOINT, REFERENCE_MU_BASE)}
    if not ctx.quick:  # the no-sliding validation doubles the cost: full campaign only
        frictions["no_sliding"] = (NO_SLIDING, NO_SLIDING)
    return frictions


def _map_plan(ctx: CampaignContext) -> tuple[list, str, int]:
    """Specimens, friction grid and bisection rounds of the map step."""
    if ctx.quick:
        return [s for s in ctx.specimens if s.id in QUICK_MAP] or ctx.specimens[:2], "0.3,0.6,0.9,1.2", 1
    return ctx.specimens, "0.3:1.5:0.1", 3


def _shake_plan(ctx: CampaignContext) -> tuple[list, tuple[float, ...]]:
    """Specimens and pulse frequencies [Hz] of the shake step."""
    if ctx.quick:
        ids, freqs = QUICK_SHAKE
        return [s for s in ctx.specimens if s.id in ids] or ctx.specimens[:1], freqs
    return [s for s in ctx.specimens if round(s.arch.Sd, 3) in (0.15, 0.2)], SHAKE_FREQS


def _record_plan(ctx: CampaignContext) -> list:
    ids = ["Sh02-Sd020"] if ctx.quick else ["Sh02-Sd020", "Sh06-Sd015", "Sh1-Sd020"]
    return [s for s in ctx.specimens if s.id in ids] or ctx.specimens[:1]


# Core-seconds of one unit of work of each simulator step, PyBullet, 15 bodies, defaults dt 0.5 ms /
# 100 iterations, tilt levels ramped 0.5 s and held 1 s (wall of the step x 2 cores / units), on the
# scale of REFERENCE_SPEED: each measurement x 1.9 / the machine_speed of its machine.
# Quick values: a quick campaign run from a fresh clone (204 s at machine_speed 1.65: tilt 64.8 s for
# 11 tests, map 52.5 s for 10 cases, shake 31.8 s for 2 thresholds, record 36.2 s for 1). Full
# values: the full campaign run end to end from a fresh clone (1914 s at 1.65: tilt 164.6 s for 22
# tests, map 868.6 s for 176 cases, shake 588.8 s for 30 thresholds, record 273.3 s for 3; the
# former values estimated it at 34 min). The machine_speed reading tracks stepping only: the quick
# shake and record steps (untouched by the code changes in between) cost 1.3 and 1.6 x less on the
# 1.65 machine than on a 1.76 one, both brought to this scale.
# Since the hold's rest rule (TiltProtocol.rest_after): the quick tilt and map values from a quick
# run at machine_speed 1.40 (tilt 45.7 s for 11 tests, map 36.8 s for 10 cases; 13.6 and 12.1
# before), the full ones scaled by what the rule saved on the same machine: x 0.80 the tilt (the
# 44 tilt tests of benchmarks/validate_dem.py, 206 s against 258 s) and x 0.79 the map
# (benchmarks/bench_map.py --specimens all, 524 s against 661 s).
# The tilt values since the tilt test simulates the ends of its first bracket only when the bisection
# ends on one (TiltProtocol.probe_ends) and the quick step runs the tilt test's protocol too: the tilt
# step alone (--steps tilt), quick 32.5 s for 11 tests at machine_speed 1.24, full 53.2 s for 22
# tests at 1.27 (the quick step's 11 tests on 2 workers leave one idle for the last one). The map
# values since the map does the same: quick, the map step alone, 25.2 s and 22.9 s for 10 cases at
# about 1.33; full, benchmarks/bench_map.py --specimens all, 345 s for 167 cases at about 1.28.
# The shake values since a shake run ends once at rest after the motion (ShakeProtocol.rest_after):
# the shake step alone, quick 20.4 s for 2 thresholds at machine_speed 1.28, full 339.3 s for 30 at
# 1.26 (458 s without the rule, same machine).
UNIT_CORE_S = {
    ("tilt", True): 9.1,  # one tilt test, bisected to 0.5 % from the LP bracket (3 simulations)
    ("tilt", False): 7.2,
    ("map", True): 6.9,  # one map case (tilt to 2 %, LP-started bracket, 2.5 simulations)
    ("map", False): 6.1,
    ("shake", True): 30.3,  # one threshold (scan + bisection) at one frequency, tol 2 %
    ("shake", False): 34.1,  # ... ceiling 6 x lambda and tol 1 %
    ("record", True): 83.4,  # one scaled-record threshold, 3 s window
    ("record", False): 209.8,  # ... 7 s window, tol 1 %
}
ENGINE_COST = {"pybullet": 1.0, "mujoco": 0.7}
# Wall seconds per simulated second that :func:`machine_speed` reads on the machine of UNIT_CORE_S
# (5 calls on an idle 2-core machine: PyBullet 1.80-2.09, median 1.93; MuJoCo 1.15-1.31, median 1.24;
# another machine read 1.64-1.65, e.g. at the start of the quick run above). The estimate scales
# the unit costs by this machine's own reading over these, so it holds on a faster machine too.
REFERENCE_SPEED = {"pybullet": 1.9, "mujoco": 1.25}
CALIBRATION_SPECIMEN = "Sh06-Sd015"


def machine_speed(engine: str = "pybullet", steps: int = 200, repeats: int = 3) -> float:
    """Wall seconds per simulated second of this machine for ``engine``: the glued
    CALIBRATION_SPECIMEN at rest with the default settings, the median of ``repeats`` runs of
    ``steps`` steps after the build (about 1.5 s of wall time with PyBullet on a 2-core machine)."""
    import statistics
    import time

    from dem.engines import get_engine
    from dem.model import from_assembly
    from dem.settings import Settings
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    settings = Settings(engine=engine)
    model = from_assembly(discretise(get_specimen(CALIBRATION_SPECIMEN).arch, config="glued"),
                          name=CALIBRATION_SPECIMEN)
    walls = []
    with get_engine(engine) as eng:
        eng.build(model, settings)
        eng.step(20)  # contacts found and warm-started before timing
        for _ in range(repeats):
            t0 = time.perf_counter()
            eng.step(steps)
            walls.append(time.perf_counter() - t0)
    return statistics.median(walls) / (steps * settings.dt)


def estimate(ctx: CampaignContext, steps: list[str], speed: float | None = None) -> dict[str, dict]:
    """Per simulator step in ``steps``: number of units (tilt tests, map cases, thresholds) and
    estimated wall time [s] on ``ctx.workers`` cores (all cores by default). ``speed``: this
    machine's :func:`machine_speed` for ``ctx.engine``; the unit costs are scaled by it over
    REFERENCE_SPEED (None: the reference machine's costs as they are)."""
    import os

    from dem.friction_map import parse_mu_grid

    cores = max(1, ctx.workers or os.cpu_count() or 1)
    map_specs, mus, refine = _map_plan(ctx)
    shake_specs, freqs = _shake_plan(ctx)
    units = {
        "tilt": (len(ctx.specimens) * len(_tilt_frictions(ctx)), "tilt tests"),
        "map": (len(map_specs) * (len(parse_mu_grid(mus)) + refine), "map tilt cases"),
        "shake": (len(shake_specs) * len(freqs), "sine-pulse thresholds"),
        "record": (len(_record_plan(ctx)), "record thresholds"),
    }
    ref = REFERENCE_SPEED.get(ctx.engine)
    scale = speed / ref if speed is not None and ref else 1.0
    out = {}
    for name in (s for s in steps if s in units):
        n, what = units[name]
        # units (or, for thresholds, the simulations inside one unit) run in parallel on the cores
        unit = UNIT_CORE_S[(name, ctx.quick)] * ENGINE_COST.get(ctx.engine, 1.0) * scale
        out[name] = {"units": n, "what": what, "wall_s": n * unit / cores}
    return out


def _studies(ctx: CampaignContext) -> Path:
    p = ctx.out / "studies"
    p.mkdir(exist_ok=True)
    return p


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


# ------------------------------------------------------------------------------------ tilt
def step_tilt(ctx: CampaignContext, d: Path) -> dict:
    """Tilt test of every specimen at the reference friction and with no sliding, beside the LP."""
    from analytic.limit_discrete import solve_lp
    from dem.friction_map import DEM_CASE, make_case
    from dem.sweep import case_key, run_study
    from specimens.blocks import discretise

    frictions = _tilt_frictions(ctx)
    eng = {"engine": ctx.engine} if ctx.engine != "pybullet" else None
    # the tilt test's protocol (LP-started bisection to 0.5 %, first-bracket ends simulated last), quick
    # or not: 3 simulations per test on 20 of the 22 tests of the full step, where the friction map's
    # protocol (2 %, both ends first; the quick step's until then) took 4
    proto = {"kind": "hold", "tol": 0.005, "start": "lp"}
    cases = {(s.id, k): make_case(s.id, s.arch, ctx.config, mj, mb, protocol=proto, settings=eng)
             for s in ctx.specimens for k, (mj, mb) in frictions.items()}
    res = run_study(list(cases.values()), DEM_CASE, _studies(ctx) / "tilt.h5", workers=ctx.workers, resume=True,
                    study_attrs={"study": "campaign-tilt", "config": ctx.config, "quick": ctx.quick})
    by_key = res.by_key
    rows = []
    for s in ctx.specimens:
        asm = discretise(s.arch, config=ctx.config)
        lp_ns = solve_lp(asm, math.inf, math.inf).lam
        lp_ref = solve_lp(asm, REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam
        out = {"id": s.id, "Sh": round(s.arch.Sh, 6), "Sd": round(s.arch.Sd, 6)}
        for k in frictions:
            rec = by_key.get(case_key(cases[(s.id, k)]))
            ok = rec is not None and rec.ok
            res_k = rec.results if ok else {}
            joints = zip(res_k.get("joint_names") or [], res_k.get("joint_states") or [])
            out[f"lambda_dem_{k}"] = float(res_k["lambda"]) if ok else float("nan")
            out[f"mode_{k}"] = str(res_k["mode"]) if ok else "failed"
            out[f"joints_{k}"] = " ".join(f"{n}:{st}" for n, st in joints if st != "closed")
            out[f"n_sims_{k}"] = int(res_k.get("n_sims", 0)) if ok else 0
        out["lambda_lp_reference"] = lp_ref
        out["err_reference_vs_lp_pct"] = 100 * (out["lambda_dem_reference"] - lp_ref) / lp_ref
        out["lambda_lp_no_sliding"] = lp_ns
        if "no_sliding" in frictions:
            out["err_no_sliding_pct"] = 100 * (out["lambda_dem_no_sliding"] - lp_ns) / lp_ns
            out["ratio_reference_to_no_sliding"] = out["lambda_dem_reference"] / out["lambda_dem_no_sliding"]
        rows.append(out)
    _write_csv(d / "tilt.csv", rows)

    plt = _plt()
    fig, ax = plt.subplots(figsize=(7, 4.8))
    colors = {0.2: "tab:blue", 0.6: "tab:orange", 1.0: "tab:green"}
    for sh in sorted({r["Sh"] for r in rows}):
        rs = sorted((r for r in rows if r["Sh"] == sh), key=lambda r: r["Sd"])
        c = colors.get(sh, None)
        sd = [r["Sd"] for r in rs]
        ax.plot(sd, [r["lambda_lp_no_sliding"] for r in rs], "-", color=c, lw=1, label=f"Sh {sh:g}: LP, no sliding")
        if "lambda_dem_no_sliding" in rs[0]:
            ax.plot(sd, [r["lambda_dem_no_sliding"] for r in rs], "o", mfc="none", color=c, label=f"Sh {sh:g}: DEM, no sliding")
        for r in rs:
            mk = {"rocking": "s", "sliding": "v", "mixed": "D"}.get(r["mode_reference"], "x")
            ax.plot(r["Sd"], r["lambda_dem_reference"], mk, color=c, ms=6)
    ax.plot([], [], "ks", label="DEM reference friction: rocking")
    ax.plot([], [], "kv", label="... sliding")
    ax.plot([], [], "kD", label="... mixed")
    ax.set_xlabel("Sd = t / Rp")
    ax.set_ylabel("lambda = tan(theta) at collapse")
    ax.set_title(f"Virtual tilt test ({ctx.config}) vs discrete limit analysis")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(d / "tilt_lambda_vs_Sd.png", dpi=120)
    plt.close(fig)

    figures = [{"path": "tilt/tilt_lambda_vs_Sd.png", "caption": "Tilt lambda vs Sd: DEM (markers) and LP (lines)"}]
    figures += _collapse_figures(rows, {s.id: by_key.get(case_key(cases[(s.id, "reference")])) for s in ctx.specimens},
                                 {s.id: cases[(s.id, "reference")] for s in ctx.specimens}, d)
    sliding = [r["id"] for r in rows if r["mode_reference"] in ("sliding", "mixed")]
    err_ref = np.array([r["err_reference_vs_lp_pct"] for r in rows])
    findings = [
        f"At the reference friction ({REFERENCE_MU_JOINT}/{REFERENCE_MU_BASE}) {len(sliding)} of {len(rows)} specimens "
        f"collapse with sliding joints{': ' + ', '.join(sliding) if sliding else ''}.",
        f"At the reference friction the DEM lambda is {np.nanmin(err_ref):+.1f} % to {np.nanmax(err_ref):+.1f} % from the "
        "associative LP (which is no bound for Coulomb friction).",
    ]
    if "no_sliding" in frictions:
        err = np.array([r["err_no_sliding_pct"] for r in rows])
        k = int(np.nanargmax(np.abs(err)))
        within = sum(1 for r in rows if r["lambda_dem_reference"] <= 1.01 * r["lambda_dem_no_sliding"])
        findings += [
            # the range, not "within max %", which read "within 3.0 % ... 10 of 11 within 3 %" at -3.005 %
            f"With no sliding the DEM tilt lambda is {np.nanmin(err):+.2f} % to {np.nanmax(err):+.2f} % from the "
            f"discrete LP (mean {np.nanmean(err):+.2f} %, largest deviation {err[k]:+.2f} % on {rows[k]['id']}); "
            f"{int(np.sum(np.abs(err) <= 3))} of {len(rows)} specimens within 3 %.",
            f"The reference-friction lambda stays at or below the no-sliding lambda (+1 %) for {within} of {len(rows)} specimens.",
        ]
    return {
        "summary": "Hold-and-bisect tilt test (lambda = tan theta, gravity rotated at constant magnitude) of every "
                   f"specimen, {ctx.engine}, at the reference friction"
                   + ("" if ctx.quick else f" and at mu = {NO_SLIDING:g} (no sliding)")
                   + ", next to the discrete static LP of the same linearised blocks"
                   + " (lambda bisected to 0.5 %).",
        "tables": [{"name": "tilt", "title": "Virtual tilt test vs limit analysis", "csv": "tilt/tilt.csv"}],
        "figures": figures,
        "findings": findings,
    }


def _collapse_figures(rows: list[dict], records: dict, cases: dict, d: Path) -> list[dict]:
    """The arch at collapse (joints coloured by state) and the lambda bracket history of the first
    specimen that rocks and the first that slides at the reference friction; the collapsing
    simulation is replayed from the study (:func:`dem.friction_map.replay_tilt`)."""
    from dem.figures import save_tilt_figure
    from dem.friction_map import replay_tilt

    picks = []
    for modes in (("rocking",), ("sliding", "mixed")):
        row = next((r for r in rows if r["mode_reference"] in modes), None)
        if row is not None:
            picks.append(row["id"])
    out = []
    for sid in picks:
        rec = records[sid]
        res = replay_tilt(cases[sid], rec.results)
        png = save_tilt_figure(res, d / f"collapse_{sid}.png")
        same = "" if res.mode == str(rec.results["mode"]) else f" (the replay reads {res.mode})"
        out.append({"path": f"tilt/{png.name}",
                    "caption": f"{sid} at the reference friction: the arch at collapse, displacements magnified, "
                               f"joints coloured by state ({rec.results['mode']}{same}); right: the levels "
                               "simulated by hold-and-bisect and the final bracket"})
    return out


# ------------------------------------------------------------------------------ friction map
def step_map(ctx: CampaignContext, d: Path) -> dict:
    """Rocking/sliding friction threshold of every specimen (coarse grid when quick)."""
    from dem.friction_map import catalogue_map

    specs, mus, refine = _map_plan(ctx)
    res = catalogue_map(specs, ctx.config, mus, REFERENCE_MU_BASE, _studies(ctx) / "map.h5",
                        workers=ctx.workers, resume=(_studies(ctx) / "map.h5").exists(), progress=True,
                        refine=refine,
                        settings={"engine": ctx.engine} if ctx.engine != "pybullet" else None)
    _write_csv(d / "map.csv", res.to_rows("summary"))
    _write_csv(d / "map_points.csv", res.to_rows("points"))
    figs = res.figures(d / "figures")
    rows = res.to_rows("summary")
    findings = []
    br = [r for r in rows if r["mu_star_dem"] is not None and r["mu_star_dem"] == r["mu_star_dem"]]
    if br:
        diffs = [(r["id"], r["mu_star_dem"] - r["mu_star_two_bar"]) for r in br if r["mu_star_two_bar"] is not None]
        values = ", ".join(f"{r['id']} {r['mu_star_dem']:.2f}" for r in br)
        findings.append(f"The DEM rocking/sliding threshold mu* is bracketed for {len(br)} of {len(rows)} specimens: {values}.")
        if diffs:
            above = sum(1 for _, x in diffs if x > 0)
            findings.append(f"The two-bar model's mu* is below the DEM mu* for {above} of {len(diffs)} bracketed specimens "
                            f"(mean difference DEM - two-bar {np.mean([x for _, x in diffs]):+.2f}).")
    for sh in sorted({r["Sh"] for r in br}):
        rs = sorted((r for r in br if r["Sh"] == sh), key=lambda r: r["Sd"])
        if len(rs) > 1:
            inc = all(b["mu_star_dem"] >= a["mu_star_dem"] for a, b in zip(rs, rs[1:]))
            values = ", ".join(f"{r['mu_star_dem']:.2f}" for r in rs)
            findings.append(f"Sh = {sh:g}: DEM mu* {'grows' if inc else 'does not grow monotonically'} with Sd ({values}).")
    for status, text in (("all_rocking", "Rocking already at the lowest friction of the grid"),
                         ("all_sliding", "Still sliding at the highest friction of the grid")):
        ids = [r["id"] for r in rows if r["dem_status"] == status]
        if ids:
            findings.append(f"{text}: {', '.join(ids)}.")
    return {
        "summary": f"Tilt test of {len(specs)} specimens swept over block-block friction ({mus}; base {REFERENCE_MU_BASE}), mu* refined by "
                   f"bisection ({res.rounds} round(s)); analytic LP and two-bar thresholds beside it. "
                   f"{res.n_cases} tilt tests, {res.n_failed} failed.",
        "tables": [{"name": "map", "title": "Friction thresholds mu* per specimen", "csv": "map/map.csv"},
                   {"name": "map_points", "title": "Tilt results of the friction sweep", "csv": "map/map_points.csv"}],
        "figures": [{"path": f"map/figures/{f.name}", "caption": f.stem.replace("_", " ")} for f in figs],
        "findings": findings,
    }


# --------------------------------------------------------------------------------- shake table
def _lowest_threshold(domain) -> dict[float, float]:
    """Least collapsing amplitude [g] per frequency of an analytic failure domain (or {})."""
    out: dict[float, float] = {}
    for p in (domain.points() if domain is not None else []):
        out[p["x"]] = min(out.get(p["x"], math.inf), p["amplitude_g"])
    return out


def step_shake(ctx: CampaignContext, d: Path) -> dict:
    """Shake-table thresholds (one-cycle sine) of the Sd = 0.15 and 0.20 specimens next to the four-bar."""
    from dem.figures_shake import plot_domain_over_analytic
    from dem.settings import Settings
    from dem.shake_domain import analytic_domains, dem_failure_domain

    specs, freqs = _shake_plan(ctx)
    rows, figures = [], []
    for s in specs:
        dem = dem_failure_domain(s.id, s.arch, freqs, ctx.config, workers=ctx.workers,
                                 settings=Settings(engine=ctx.engine),
                                 a_max_ratio=4.0 if ctx.quick else 6.0, tol=0.02 if ctx.quick else 0.01)
        ana = analytic_domains(s.arch, freqs, workers=1)
        fb, tb = _lowest_threshold(ana.get("four-bar")), _lowest_threshold(ana.get("two-bar"))
        for t in dem["thresholds"]:
            f = t["freq"]
            fb_f = fb.get(f)
            a = t["amplitude_g"]
            rows.append({
                "id": s.id, "freq_Hz": f, "lambda_static": dem["lambda"],
                "a_dem_g": a if a is not None else float("nan"), "dem_mode": t.get("mode") or "",
                "collapse_phase": t.get("collapse_phase") or "",
                "a_four_bar_g": fb_f if fb_f is not None else float("nan"),
                "a_two_bar_g": tb.get(f, float("nan")),
                "ratio_dem_to_four_bar": (a / fb_f) if (a is not None and fb_f) else float("nan"),
                "survival_bands_above": " ".join(f"{b['from_g']:.3f}-{b['to_g']:.3f}" for b in t.get("survival_bands_above", [])),
                "n_sims": t.get("n_sims", 0),
            })
        figures += _threshold_histories(s, dem, ctx, d)
        png = d / f"domain_{s.id}.png"
        plot_domain_over_analytic(dem, ana, png, title=f"{s.id}: DEM vs rocking linkages, one-cycle sine")
        figures.append({"path": f"shake/{png.name}", "caption": f"{s.id}: DEM shake thresholds over the analytic domains"})
    _write_csv(d / "shake.csv", rows)
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
    return {
        "summary": "Plain one-cycle sine pulses; least collapsing amplitude by amplitude scan then bisection of the lowest "
                   "collapsing bracket; four-bar (minimised layout) and two-bar thresholds for the same input. "
                   "Measured sensitivity to the engine's numerics (benchmarks/shake_convergence.py): within 2.5 % "
                   "at 2-4 Hz, 14 % to a factor 2.2 at 6 Hz (dem/thresholds.py), so ratios above 4 Hz are ranges.",
        "tables": [{"name": "shake", "title": "Shake-table thresholds [g]", "csv": "shake/shake.csv"}],
        "figures": figures, "findings": findings,
    }


def _threshold_histories(spec, dem: dict, ctx: CampaignContext, d: Path) -> list[dict]:
    """Time histories just below and at the first DEM threshold (lowest frequency that has one)."""
    from analytic.inputs import G, SinePulse
    from dem.figures_shake import save_shake_figure
    from dem.model import from_assembly
    from dem.settings import Settings
    from dem.shake import shake
    from specimens.blocks import discretise

    t = next((t for t in dem["thresholds"] if t["amplitude_g"] is not None), None)
    if t is None:
        return []
    model = from_assembly(discretise(spec.arch, config=ctx.config), name=spec.id)
    out = []
    for what, a_g in (("survival", t["bracket_g"][0]), ("collapse", t["bracket_g"][1])):
        res = shake(model, SinePulse(a_g * G, t["freq"]), Settings(engine=ctx.engine), label=spec.id)
        png = save_shake_figure(res, d / f"history_{spec.id}_{t['freq']:g}Hz_{what}.png")
        out.append({"path": f"shake/{png.name}",
                    "caption": f"{spec.id}, {t['freq']:g} Hz sine at {a_g:.3f} g ({what} side of the threshold): "
                               "crown displacement and input"})
    return out


# ---------------------------------------------------------------------------- recorded motion
@dataclass(frozen=True)
class RecordAtPGA:
    """A picklable motion factory for :func:`dem.thresholds.threshold`: the record scaled to a PGA.

    Called as ``(amplitude [m/s^2], freq)``; ``freq`` is ignored.
    """

    path: str
    t_start: float
    t_end: float

    def __call__(self, amplitude: float, freq: float):
        return record_window(self.path, self.t_start, self.t_end).to_pga(amplitude)


def record_window(path: str, t_start: float, t_end: float):
    """The part ``[t_start, t_end]`` [s] of a record file, baseline-corrected, with a 1 s zero tail."""
    from analytic.inputs import SampledMotion
    from analytic.records import baseline_correct, read_record, with_zero_tail

    m = read_record(path)
    i0, i1 = int(round(t_start / m.dt)), int(round(t_end / m.dt)) + 1
    w = SampledMotion(m.values[i0:i1], m.dt, name=f"{m.name} [{t_start:g}, {t_end:g}] s", source=m.source)
    return with_zero_tail(baseline_correct(w), 1.0)


def _record_path() -> Path:
    """The shared El Centro record, shipped with the project's test data."""
    return Path(__file__).resolve().parents[1] / "tests" / "data" / "ground_motions" / RECORD_FILE


def step_record(ctx: CampaignContext, d: Path) -> dict:
    """One recorded accelerogram scaled until collapse, for three specimens (one when quick)."""
    from analytic.inputs import G
    from analytic.records import read_record
    from dem.model import from_assembly
    from dem.settings import Settings
    from dem.shake import ShakeProtocol
    from dem.shake_domain import static_onset
    from dem.thresholds import threshold
    from specimens.blocks import discretise

    path = _record_path()
    full = read_record(path)
    t_pga = float(np.argmax(np.abs(full.values)) * full.dt)
    # strong-motion window around the peak: short enough to scan many amplitudes
    t0, t1 = max(0.0, t_pga - 1.0), t_pga + (2.0 if ctx.quick else 6.0)
    specs = _record_plan(ctx)
    rows = []
    for s in specs:
        lam = static_onset(s.arch, ctx.config, REFERENCE_MU_JOINT, REFERENCE_MU_BASE)
        model = from_assembly(discretise(s.arch, config=ctx.config), name=s.id)
        r = threshold(model, 1.0, Settings(engine=ctx.engine), ShakeProtocol(), a_min_g=lam, a_max_g=4 * lam, scan_ratio=1.25,
                      tol=0.02 if ctx.quick else 0.01, workers=ctx.workers, motion_fn=RecordAtPGA(str(path), t0, t1))
        a = r.amplitude_g
        rows.append({"id": s.id, "record": RECORD_FILE, "window_s": f"{t0:.2f}-{t1:.2f}", "pga_record_g": full.pga / G,
                     "lambda_static": lam, "collapse_pga_g": a if a is not None else float("nan"),
                     "scale_factor": (a * G / full.pga) if a is not None else float("nan"),
                     "ratio_to_static": (a / lam) if a is not None else float("nan"), "mode": r.mode or "",
                     "n_sims": r.n_sims})
    _write_csv(d / "record.csv", rows)
    found = [r for r in rows if math.isfinite(r["collapse_pga_g"])]
    findings = [f"{r['id']}: the El Centro 1940 window collapses the arch at PGA {r['collapse_pga_g']:.3f} g "
                f"(x{r['scale_factor']:.2f} the record, {r['ratio_to_static']:.2f} x the static lambda)." for r in found]
    return {
        "summary": f"{RECORD_FILE} (El Centro 1940, PEER NGA), window {t0:.2f}-{t1:.2f} s around the peak, baseline-"
                   "corrected, 1 s zero tail; scaled to increasing PGA until collapse (scan, then bisection).",
        "tables": [{"name": "record", "title": "Recorded accelerogram scaled to collapse", "csv": "record/record.csv"}],
        "findings": findings,
    }
