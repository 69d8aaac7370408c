"""Figures of a friction map (:class:`dem.experiments.friction_map.run.MapResult`). Plotting only; no physics here.

* ``threshold_map.png`` — mu* against Sd, one colour per Sh: DEM (solid, markers with the
  bisection bracket as error bar), LP (dotted), LP without dilatancy (dash-dot), two-bar (dashed);
  sliding below, rocking above.
* ``lambda_mu_<id>.png`` — lambda(mu) of one specimen: DEM points coloured by mode over the LP
  curve, the non-associative one (no dilatancy, on the map's grid), the two-bar lambda_slide(mu) and
  the no-sliding multiplier; mu* marks.
* ``mode_grid.png`` — Sh x Sd grid, each cell coloured by the DEM mode at the reference friction
  (grid value nearest to ``REFERENCE_MU_JOINT``), annotated with mu* (DEM / LP / no dilatancy / two-bar).
"""
from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

import matplotlib
import numpy as np
from matplotlib.figure import Figure

from specimens.constants import REFERENCE_MU_JOINT
from foundation.io import writable_dir

MODE_COLOURS = {"rocking": "tab:green", "sliding": "tab:blue", "mixed": "tab:purple", "none": "0.6",
                "failed": "tab:red"}


def _val(x):
    return np.nan if x is None else float(x)


def plot_threshold_map(result, ax=None):
    """mu* against Sd, one colour per Sh (DEM, LP, LP without dilatancy, two-bar)."""
    if ax is None:
        ax = Figure(figsize=(7, 5)).subplots()
    by_sh: dict = {}
    for s in result.specimens:
        by_sh.setdefault(round(s.arch.Sh, 3), []).append(s)
    colours = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    top = 0.0
    for k, (sh, ss) in enumerate(sorted(by_sh.items())):
        ss = sorted(ss, key=lambda s: s.arch.Sd)
        c = colours[k % len(colours)]
        sd = np.array([s.arch.Sd for s in ss])
        dem = np.array([_val(s.mu_star_dem) for s in ss])
        lo = np.array([_val(s.threshold.lo) for s in ss])
        hi = np.array([_val(s.threshold.hi) for s in ss])
        lp = np.array([_val(s.analytic.mu_star_lp) for s in ss])
        na = np.array([_val(s.analytic.mu_star_na) for s in ss])
        tb = np.array([_val(s.analytic.mu_star_two_bar) for s in ss])
        ax.errorbar(sd, dem, yerr=[dem - lo, hi - dem], color=c, marker="o", ls="-", capsize=3,
                    label=f"Sh = {sh:g}: DEM")
        ax.plot(sd, lp, color=c, ls=":", marker="s", mfc="none", label=f"Sh = {sh:g}: LP")
        if np.isfinite(na).any():
            ax.plot(sd, na, color=c, ls="-.", marker="x", label=f"Sh = {sh:g}: LP, no dilatancy")
        ax.plot(sd, tb, color=c, ls="--", marker="^", mfc="none", label=f"Sh = {sh:g}: two-bar")
        # open brackets: all rocking (mu* <= lowest mu) / all sliding (mu* > highest mu)
        for s in ss:
            if s.threshold.status == "all_rocking":
                ax.annotate("", (s.arch.Sd, s.threshold.hi - 0.08), (s.arch.Sd, s.threshold.hi),
                            arrowprops={"arrowstyle": "->", "color": c})
            elif s.threshold.status == "all_sliding":
                ax.annotate("", (s.arch.Sd, s.threshold.lo + 0.08), (s.arch.Sd, s.threshold.lo),
                            arrowprops={"arrowstyle": "->", "color": c})
        top = max([top] + [v for v in np.r_[dem, lp, na, tb, hi] if np.isfinite(v)])
    ax.set_xlabel("slenderness Sd = t / (2 Rc)")
    ax.set_ylabel("threshold friction mu*")
    ax.text(0.02, 0.03, "sliding below", transform=ax.transAxes, color="tab:blue")
    ax.text(0.02, 0.95, "rocking above", transform=ax.transAxes, color="tab:green", va="top")
    ax.set_ylim(0, max(1.0, 1.1 * top))
    ax.set_title(f"Rocking/sliding threshold ({result.config}, mu_base = {result.mu_base:g})")
    ax.legend(fontsize=7, ncol=3, loc="upper center")
    ax.grid(alpha=0.3)
    return ax


def plot_lambda_mu(smap, ax=None):
    """lambda(mu) of one specimen: DEM points by mode over the analytic curves."""
    if ax is None:
        ax = Figure(figsize=(7, 4.5)).subplots()
    a = smap.analytic
    ax.plot(a.mu, a.lam_lp, "k-", lw=1.2, label="LP (associative)")
    if len(a.lam_na):  # on the map's grid only: about 1 s a value
        ax.plot(a.mu_na, a.lam_na, "-.", color="tab:brown", marker=".", lw=1, label="LP, no dilatancy")
    ax.plot(a.mu, a.lam_two_bar, "k--", lw=1, label="two-bar lambda_slide")
    ax.axhline(a.lam_no_sliding, color="0.4", ls=":", label="no sliding (LP, mu_joint = inf)")
    for mode in MODE_COLOURS:
        pts = [p for p in smap.points if p.mode == mode]
        if not pts:
            continue
        y = [p.lam if np.isfinite(p.lam) else 0.0 for p in pts]
        ax.scatter([p.mu for p in pts], y, c=MODE_COLOURS[mode], marker="x" if mode == "failed" else "o",
                   s=[40 if p.kind == "grid" else 20 for p in pts], zorder=3, label=f"DEM {mode}")
    for v, ls, colour, lab in ((smap.mu_star_dem, "-", "tab:orange", "mu* DEM"),
                               (a.mu_star_lp, ":", "tab:orange", "mu* LP"),
                               (a.mu_star_na, "-.", "tab:brown", "mu* LP, no dilatancy"),
                               (a.mu_star_two_bar, "--", "tab:orange", "mu* two-bar")):
        if v is not None and a.mu[0] <= v <= a.mu[-1]:
            ax.axvline(v, color=colour, ls=ls, lw=1, label=lab)
    ax.set_xlabel("joint friction mu")
    ax.set_ylabel("collapse multiplier lambda")
    ax.set_ylim(0, 1.25 * max(a.lam_no_sliding, np.nanmax([p.lam for p in smap.points] + [0.1])))
    shape = smap.shape()
    ax.set_title(f"{smap.id} (drawing)" if smap.drawn else
                 f"{smap.id} (Sh = {shape['Sh']:.2f}, Sd = {shape['Sd']:.2f}, {smap.config})")
    ax.legend(fontsize=7, loc="lower right")
    ax.grid(alpha=0.3)
    return ax


def plot_mode_grid(result, mu_ref: float | None = None, ax=None):
    """Sh x Sd grid of DEM modes at ``mu_ref`` (nearest grid value; default the reference friction)."""
    if ax is None:
        ax = Figure(figsize=(7, 4.5)).subplots()
    grid = np.asarray(result.mus)
    mu = float(grid[np.argmin(np.abs(grid - (REFERENCE_MU_JOINT if mu_ref is None else mu_ref)))])
    shs = sorted({round(s.arch.Sh, 3) for s in result.specimens})
    sds = sorted({round(s.arch.Sd, 3) for s in result.specimens})
    for s in result.specimens:
        i, j = shs.index(round(s.arch.Sh, 3)), sds.index(round(s.arch.Sd, 3))
        p = min(s.points, key=lambda p: abs(p.mu - mu), default=None)
        mode = p.mode if p is not None and abs(p.mu - mu) < 1e-9 else "none"
        ax.add_patch(matplotlib.patches.Rectangle((j - 0.45, i - 0.45), 0.9, 0.9, fc=MODE_COLOURS.get(mode, "0.6"), alpha=0.6))

        def f(v):
            return "-" if v is None else f"{v:.2f}"

        ax.text(j, i, f"{mode}\nDEM {f(s.mu_star_dem)}\nLP {f(s.analytic.mu_star_lp)}\nNA {f(s.analytic.mu_star_na)}\n"
                f"2bar {f(s.analytic.mu_star_two_bar)}", ha="center", va="center", fontsize=7)
    ax.set_xticks(range(len(sds)), [f"{v:g}" for v in sds])
    ax.set_yticks(range(len(shs)), [f"{v:g}" for v in shs])
    ax.set_xlim(-0.5, len(sds) - 0.5)
    ax.set_ylim(-0.5, len(shs) - 0.5)
    ax.set_xlabel("Sd")
    ax.set_ylabel("Sh")
    ax.set_title(f"DEM mode at mu = {mu:g} (cells: mu* DEM / LP / no dilatancy / two-bar)")
    return ax


def save_map_figures(result, out_dir: str | os.PathLike) -> list[Path]:
    """Write the threshold map and the mode grid of the arches (over Sh and Sd: not of drawings) and one
    lambda(mu) figure per specimen (PNG)."""
    d = writable_dir(out_dir)
    paths = []
    arches = replace(result, specimens=[s for s in result.specimens if not s.drawn])
    for name, fn in (("threshold_map", plot_threshold_map), ("mode_grid", plot_mode_grid)):
        if not arches.specimens:
            break
        fig = Figure(figsize=(7, 5))
        ax = fig.subplots()
        fn(arches, ax=ax)
        fig.tight_layout()
        p = d / f"{name}.png"
        fig.savefig(p, dpi=120)
        paths.append(p)
    for s in result.specimens:
        fig = Figure(figsize=(7, 4.5))
        ax = fig.subplots()
        plot_lambda_mu(s, ax=ax)
        fig.tight_layout()
        p = d / f"lambda_mu_{s.id}.png"
        fig.savefig(p, dpi=120)
        paths.append(p)
    return paths
