"""The tilt step: the virtual tilt test of every specimen against limit analysis."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
from matplotlib.figure import Figure

from dem.common.campaign import CampaignContext, studies_dir, write_csv
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.tilt.case import DEM_CASE, make_case, replay_tilt
from dem.experiments.tilt.check import LP_TOLERANCE, TiltCheck, check, lp_check_of, reference_lp
from dem.experiments.tilt.figure import save_tilt_figure
from dem.studies.sweep import case_key, run_study
from specimens.blocks import discretise
from specimens.constants import NO_SLIDING_MU, REFERENCE_MU_BASE, REFERENCE_MU_JOINT


# ------------------------------------------------------------------------ what each step runs
def tilt_frictions(ctx: CampaignContext) -> dict[str, tuple[float, float]]:
    frictions = {"reference": (REFERENCE_MU_JOINT, REFERENCE_MU_BASE)}
    if not ctx.quick:  # the no-sliding validation doubles the cost: full campaign only
        frictions["no_sliding"] = (NO_SLIDING_MU, NO_SLIDING_MU)
    return frictions


# ------------------------------------------------------------------------------------ tilt
def _by_friction(kind: str) -> tuple[Column, ...]:
    return (Column(f"lambda_dem_{kind}", "float"), Column(f"mode_{kind}", "str"), Column(f"joints_{kind}", "str"),
            Column(f"n_sims_{kind}", "int"))


@dataclass(frozen=True)
class SpecimenTilt(Result):
    """One specimen's row of the tilt table: its tilts by friction (``checks``, the reference first, with no
    sliding in the full campaign only) beside the LP of its blocks. ``SCHEMA`` holds every column; a quick
    campaign's table has those of the frictions it ran (:meth:`schema`)."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("id", "str"), Column("Sh", "float"), Column("Sd", "float"),
        *_by_friction("reference"), *_by_friction("no_sliding"),
        Column("lambda_lp_reference", "float"), Column("err_reference_vs_lp_pct", "float", "%"),
        Column("lambda_lp_no_sliding", "float"), Column("err_no_sliding_pct", "float", "%"),
        Column("ratio_reference_to_no_sliding", "float"),
    ))
    NO_SLIDING_ONLY: ClassVar[tuple[str, ...]] = (*(c.name for c in _by_friction("no_sliding")), "err_no_sliding_pct",
                                                  "ratio_reference_to_no_sliding")

    id: str
    Sh: float
    Sd: float
    checks: dict[str, TiltCheck]  # friction ("reference", "no_sliding") -> the tilt beside its LP
    joints: dict[str, str]  # friction -> the joints that moved, "NAME:STATE" apart by spaces
    lambda_lp_reference: float
    lambda_lp_no_sliding: float

    @classmethod
    def schema(cls, no_sliding: bool) -> Schema:
        """The table's columns: with the tilts with no sliding or without them."""
        return cls.SCHEMA if no_sliding else Schema(tuple(c for c in cls.SCHEMA.columns
                                                          if c.name not in cls.NO_SLIDING_ONLY))

    def rows(self) -> list[dict]:
        out = {"id": self.id, "Sh": self.Sh, "Sd": self.Sd}
        for k, row in self.checks.items():
            out |= {f"lambda_dem_{k}": row.lam, f"mode_{k}": row.mode, f"joints_{k}": self.joints[k],
                    f"n_sims_{k}": row.n_sims}
        out |= {"lambda_lp_reference": self.lambda_lp_reference, "err_reference_vs_lp_pct": self.checks["reference"].err_pct,
                "lambda_lp_no_sliding": self.lambda_lp_no_sliding}
        if "no_sliding" in self.checks:
            out |= {"err_no_sliding_pct": self.checks["no_sliding"].err_pct,
                    "ratio_reference_to_no_sliding": out["lambda_dem_reference"] / out["lambda_dem_no_sliding"]}
        return [out]


def step_tilt(ctx: CampaignContext, d: Path) -> dict:
    """Tilt test of every specimen at the reference friction and with no sliding, beside the LP."""
    frictions = tilt_frictions(ctx)
    eng = {"engine": ctx.engine} if ctx.engine != "pybullet" else None
    # the tilt test's own protocol (LP start, 0.5 %), quick or not: 3 simulations per test
    # (docs/timings.md#2-the-full-campaign)
    proto = {"kind": "hold", "tol": 0.005, "start": "lp"}
    cases = {(s.id, k): make_case(s.id, s.arch, ctx.config, mj, mb, protocol=proto,
                                  settings=((eng or {}) | ctx.law_of(s)) or None, contact=ctx.contact_of(s))
             for s in ctx.specimens for k, (mj, mb) in frictions.items()}
    res = run_study(list(cases.values()), DEM_CASE, studies_dir(ctx) / "tilt.h5", workers=ctx.workers,
                    scheduler=ctx.scheduler, resume=True,
                    study_attrs={"study": "campaign-tilt", "config": ctx.config, "quick": ctx.quick})
    by_key = res.by_key
    rows = []
    checks = []  # every tilt beside the LP of its own blocks (the same check as archdem tilt's)
    for s in ctx.specimens:
        asm = discretise(s.arch, config=ctx.config, contact=ctx.contact_of(s))
        lp = {k: reference_lp(asm, mj, mb) for k, (mj, mb) in
              (("reference", (REFERENCE_MU_JOINT, REFERENCE_MU_BASE)), ("no_sliding", (NO_SLIDING_MU, NO_SLIDING_MU)))}
        rows_k, joints = {}, {}
        for k, (mj, mb) in frictions.items():
            rec = by_key.get(case_key(cases[(s.id, k)]))
            ok = rec is not None and rec.ok
            res_k = rec.results if ok else {}
            states = list(zip(res_k.get("joint_names") or [], res_k.get("joint_states") or [],
                              res_k.get("joint_faces") or []))
            rows_k[k] = row = check(s.id, asm, ctx.engine, mj, mb, float(res_k["lambda"]) if ok else float("nan"),
                                    str(res_k["mode"]) if ok else "failed", states,
                                    int(res_k.get("n_sims", 0)) if ok else 0, lp=lp[k])
            joints[k] = " ".join(f"{n}:{st}" for n, st, _ in states if st != "closed")
            if ok:
                checks.append(lp_check_of(row, lp[k], ctx.law_of(s).get("contact_law", "rigid")))
        rows += SpecimenTilt(s.id, round(s.arch.Sh, 6), round(s.arch.Sd, 6), rows_k, joints, lp["reference"].lam,
                             lp["no_sliding"].lam).rows()
    write_csv(d / "tilt.csv", rows, SpecimenTilt.schema("no_sliding" in frictions))

    fig = Figure(figsize=(7, 4.8))
    ax = fig.subplots()
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
    off = [c.warning for c in checks if c.agrees is False]
    findings.append(f"Every tilt is within {100 * LP_TOLERANCE:g} % of the LP of its own blocks." if not off else
                    f"{len(off)} of {len(checks)} tilts depart from the LP of their own blocks by more than "
                    f"{100 * LP_TOLERANCE:g} %: " + " ".join(w + "." for w in off))
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
        "summary": ctx.joints_text() + " " + "Hold-and-bisect tilt test (lambda = tan theta, gravity rotated at constant magnitude) of every "
                   f"specimen, {ctx.engine}, at the reference friction"
                   + ("" if ctx.quick else f" and at mu = {NO_SLIDING_MU:g} (no sliding)")
                   + ", next to the discrete static LP of the same linearised blocks"
                   + " (lambda bisected to 0.5 %).",
        "tables": [{"name": "tilt", "title": "Virtual tilt test vs limit analysis", "csv": "tilt/tilt.csv"}],
        "figures": figures,
        "findings": findings,
    }


def _collapse_figures(rows: list[dict], records: dict, cases: dict, d: Path) -> list[dict]:
    """The arch at collapse (joints coloured by state) and the lambda bracket history of the first
    specimen that rocks and the first that slides at the reference friction; the collapsing
    simulation is replayed from the study (:func:`dem.experiments.tilt.case.replay_tilt`)."""
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
