"""The analytic step: limit analysis of every specimen, multipliers and hinge layouts."""
from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from analytic.limit.figures import catalogue_figures
from analytic.limit.limit_continuous import continuous_collapse
from analytic.limit.limit_discrete import enumerate_mechanisms
from analytic.limit.non_associative import solve_non_associative
from analytic.limit.summary import analyse, multiplier_series
from dem.common.campaign import CampaignContext, pct, write_csv
from specimens.blocks import discretise
from specimens.catalogue import CATALOGUE
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT


def step_analytic(ctx: CampaignContext, d: Path) -> dict:
    """Limit analysis of every specimen: continuous, 80 % thickness, discrete, LP (associative and
    not), two-bar."""

    # the figures' series of the whole catalogue also gives the 80 % thickness multipliers
    series = multiplier_series(CATALOGUE)
    lam80_of = {r["id"]: r["cont08"] for r in series}
    # each profile is solved once: the series' result is reused for a specimen with that very arch
    cont_of = {r["id"]: (c.arch, r["continuous"]) for c, r in zip(CATALOGUE, series)}
    rows = []
    na_cost: dict[str, tuple[bool, float]] = {}  # id -> (proven optimal, wall time [s]) of the extra solve
    for s in ctx.specimens:
        arch_c, cont = cont_of.get(s.id, (None, None))
        c = ctx.contact_of(s)
        a = analyse(s.arch, ctx.config, REFERENCE_MU_JOINT, REFERENCE_MU_BASE, disc_kw={"contact": c},
                    continuous=cont if arch_c == s.arch and c == 1.0 else None)
        other = "free" if ctx.config == "glued" else "glued"
        lam_other = enumerate_mechanisms(discretise(s.arch, config=other, contact=c)).lam
        lam80 = lam80_of[s.id] if s.id in lam80_of else continuous_collapse(s.arch, effective_thickness=0.8).lam
        sliding = [j for j, v in a["joints_lp"].items() if "sliding" in v["state"]]
        # the blocks of lambda_lp_reference_friction (analyse's), without dilatancy
        t0 = time.perf_counter()
        na = solve_non_associative(discretise(s.arch, config=ctx.config, contact=c), REFERENCE_MU_JOINT,
                                   REFERENCE_MU_BASE)
        na_cost[s.id] = (na.optimal, time.perf_counter() - t0)
        rows.append({
            "id": s.id, "Sh": round(s.arch.Sh, 6), "Sd": round(s.arch.Sd, 6),
            "lambda_continuous": a["lambda_continuous"], "lambda_continuous_80pct": lam80,
            f"lambda_discrete_{ctx.config}": a["lambda_discrete"], f"lambda_discrete_{other}": lam_other,
            "lambda_lp_reference_friction": a["lambda_lp"], "lambda_non_associative": na.lam,
            "non_associative_below_lp_pct": _below_pct(na.lam, a["lambda_lp"]), "lambda_two_bar": a["lambda_two_bar"],
            "mu_star_two_bar": a["mu_star"],
            "hinges_discrete": " ".join(f"{h['joint']}:{h['face'][0]}" for h in a["hinges_discrete"]),
            "hinges_continuous_rad": " ".join(f"{h['half'][0].upper()}{h['angle_rad']:.3f}{h['face'][0]}"
                                              for h in a["hinges_continuous"]),
            "lp_sliding_joints": " ".join(sliding),
        })
    write_csv(d / "analytic.csv", rows)
    figs = catalogue_figures(d / "figures", full_scale=True, rows=series)
    keep = [f for f in figs if "mechanism" not in f.name] + [f for f in figs if "mechanism" in f.name][:2]
    figures = [{"path": f"analytic/figures/{f.name}", "caption": f.stem.replace("_", " ")} for f in keep]
    # findings computed from the rows
    lc = np.array([r["lambda_continuous"] for r in rows])
    ld = np.array([r[f"lambda_discrete_{ctx.config}"] for r in rows])
    gap = 100 * (ld - lc) / ld
    k = int(np.argmax(gap))
    findings = [
        f"Continuous-profile lambda is below the discrete one for {int(np.sum(lc <= ld + 1e-12))} of {len(rows)} "
        f"specimens; the largest gap is {gap[k]:.1f} % ({rows[k]['id']}).",
    ]
    by_sh: dict[float, list] = {}
    for r in rows:
        by_sh.setdefault(r["Sh"], []).append(r)
    mono = [sh for sh, rs in by_sh.items() if len(rs) > 1 and
            all(b["lambda_continuous"] > a["lambda_continuous"] for a, b in zip(sorted(rs, key=lambda r: r["Sd"]), sorted(rs, key=lambda r: r["Sd"])[1:]))]
    if len(by_sh) > 0:
        findings.append(f"lambda grows with slenderness Sd at fixed sharpness for Sh = {', '.join(f'{x:g}' for x in sorted(mono)) or 'none'}"
                        f" (of {', '.join(f'{x:g}' for x in sorted(by_sh))}).")
    base = sum(1 for r in rows if any(h.split(':')[0] in ('L0', 'R0') for h in r["hinges_discrete"].split()))
    findings.append(f"The discrete mechanism has a hinge at a springing (base joint) in {base} of {len(rows)} specimens.")
    red = np.array([pct(r["lambda_continuous_80pct"], r["lambda_continuous"]) for r in rows])
    findings.append(f"An 80 % effective thickness lowers the continuous lambda by {-red.max():.0f}-{-red.min():.0f} %.")
    slid = [r["id"] for r in rows if r["lp_sliding_joints"]]
    findings.append(f"At the reference friction ({REFERENCE_MU_JOINT}/{REFERENCE_MU_BASE}) the associative LP has sliding joints in "
                    f"{len(slid)} specimens{': ' + ', '.join(slid) if slid else ''}.")
    findings.append(_non_associative_finding(rows, na_cost))
    return {
        "summary": "Limit analysis: four-hinge mechanism on the continuous profile (global search), discrete "
                   "enumeration of the actual voussoirs, static LP with Coulomb friction (associative, and its "
                   "non-associative collapse by a mixed-integer program), two-bar sliding model.",
        "tables": [{"name": "analytic", "title": "Limit analysis per specimen", "csv": "analytic/analytic.csv"}],
        "figures": figures, "findings": findings,
    }


def _below_pct(lam: float, lam_lp: float) -> float:
    """How far ``lam`` lies below the associative LP's ``lam_lp`` [%]; NaN where either is not a number."""
    return 100.0 * (1.0 - lam / lam_lp) if lam_lp and math.isfinite(lam_lp) and math.isfinite(lam) else math.nan


def _non_associative_finding(rows: list[dict], cost: dict[str, tuple[bool, float]]) -> str:
    """The sentence on the non-associative multipliers of ``rows``: their range below the LP, whether the
    mixed-integer program proved each, and its wall time [s] per specimen (``cost``: by id)."""
    below = {r["id"]: r["non_associative_below_lp_pct"] for r in rows}
    known = {k: v for k, v in below.items() if math.isfinite(v)}
    if known:
        worst = max(known, key=known.get)
        # + 0.0: a difference of -1e-12 reads 0.00, not -0.00
        lo, hi = round(min(known.values()), 2) + 0.0, round(known[worst], 2) + 0.0
        # all equal to the digits quoted: no largest worth naming
        spread = (f"equals the associative LP (to 0.005 %) for {len(known)} of {len(rows)} specimens" if lo == hi == 0
                  else f"is {lo:.2f}–{hi:.2f} % below the associative LP (largest: {worst})")
    else:
        spread = "has no value for any specimen"
    missing = [k for k in below if k not in known]
    unproven = [k for k, (opt, _) in cost.items() if not opt and k in known]
    secs = [t for _, t in cost.values()]
    return (f"Without dilatancy (Coulomb friction, non-associative) the collapse multiplier {spread}"
            + (f", none for {', '.join(missing)}" if missing and known else "")
            + f"; mixed-integer program proven optimal for {sum(opt for opt, _ in cost.values())} of {len(cost)} specimens"
            + (f" (not proven, their multiplier an upper bound: {', '.join(unproven)})" if unproven else "")
            + f", {np.mean(secs):.1f} s per specimen (at most {max(secs):.1f} s).")
