"""Figures of the limit analysis (matplotlib only; no physics here).

:func:`catalogue_figures` writes, to ``out_dir``: lambda vs Sd per Sh (continuous, discrete,
80 % effective thickness, two-bar) for the catalogue and for the full-scale set, hinge
positions vs Sd, and one drawing of each catalogue specimen's discrete mechanism.
Existing files are not overwritten (a numbered name is used instead).
"""
from __future__ import annotations

import os
from pathlib import Path

import matplotlib
import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Polygon

from analytic.limit.limit_discrete import enumerate_mechanisms
from analytic.limit.summary import multiplier_series
from specimens.blocks import discretise
from specimens.catalogue import CATALOGUE, full_scale_set
from foundation.io import atomic_path, unique_run_path


def _save(fig, out_dir: Path, stem: str) -> Path:
    target = unique_run_path(out_dir, stem, ".png")
    with atomic_path(target) as tmp:
        fig.savefig(tmp, dpi=120, format="png")

    return target


def _lambda_plot(rows, title: str, with_discrete: bool):
    fig = Figure(figsize=(7, 5))
    ax = fig.subplots()
    shs = sorted({r["Sh"] for r in rows})
    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, sh in enumerate(shs):
        rr = sorted([r for r in rows if r["Sh"] == sh], key=lambda r: r["Sd"])
        sd = [r["Sd"] for r in rr]
        col = colors[i % len(colors)]
        ax.plot(sd, [r["cont"] for r in rr], "-o", color=col, label=f"Sh={sh:g} continuous")
        if with_discrete:
            ax.plot(sd, [r["disc"] for r in rr], "--s", color=col, label=f"Sh={sh:g} discrete (glued)")
        ax.plot(sd, [r["cont08"] for r in rr], ":^", color=col, label=f"Sh={sh:g} 80 % thickness")
        ax.plot(sd, [r["two_bar"] for r in rr], "-.x", color=col, label=f"Sh={sh:g} two-bar")
    ax.set_xlabel("Sd = t / Rp")
    ax.set_ylabel("collapse multiplier lambda")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=6, ncol=2)
    return fig


def _hinge_plot(rows, title: str):
    fig = Figure(figsize=(12, 3.5))
    axs = fig.subplots(1, 4, sharex=True)
    shs = sorted({r["Sh"] for r in rows})
    for k in range(4):
        for sh in shs:
            rr = sorted([r for r in rows if r["Sh"] == sh], key=lambda r: r["Sd"])
            axs[k].plot([r["Sd"] for r in rr], [np.pi - r["polar"][k] for r in rr], "-o", label=f"Sh={sh:g}")
        axs[k].set_title(f"H{k + 1}")
        axs[k].set_xlabel("Sd")
        axs[k].grid(True, alpha=0.3)
    axs[0].set_ylabel("hinge angle from the left springing [rad]")
    axs[0].legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    return fig


def mechanism_figure(spec_id: str, arch, config: str = "glued"):
    """Drawing of a specimen's discrete mechanism: blocks shaded by macro-block, hinges marked."""

    asm = discretise(arch, config=config)
    kin = enumerate_mechanisms(asm)
    j = [asm.joint(n) for n, _ in kin.hinges]
    shade = {}
    for k in range(3):
        for bi in range(j[k].b, j[k + 1].a + 1):
            shade[bi] = k
    colors = ("#e69f00", "#56b4e9", "#009e73")
    fig = Figure(figsize=(5, 4))
    ax = fig.subplots()
    for b in asm.bodies:
        ax.add_patch(Polygon(b.outline, closed=True, fc=colors[shade[b.index]] if b.index in shade else "#dddddd",
                             ec="k", lw=0.6))
    pts = kin.hinge_points
    ax.plot(pts[:, 0], pts[:, 1], "o", ms=8, mfc="r", mec="k", zorder=5)
    for i, p in enumerate(pts):
        ax.annotate(f"H{i + 1}", p, textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.axhline(0, color="k", lw=1)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_title(f"{spec_id} ({config}): lambda = {kin.lam:.3f}", fontsize=9)
    ax.axis("off")
    return fig


def catalogue_figures(out_dir: str | os.PathLike, full_scale: bool = True, rows: list[dict] | None = None) -> list[Path]:
    """Write all limit-analysis figures to ``out_dir``; return the files written. ``rows``: the
    catalogue's :func:`analytic.limit.summary.multiplier_series`, if the caller has computed it."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    files: list[Path] = []
    if rows is None:
        rows = multiplier_series(CATALOGUE)
    files.append(_save(_lambda_plot(rows, "Catalogue (Rc = 0.2 m): collapse multiplier", True), out,
                       "limit_lambda_vs_Sd_catalogue"))
    files.append(_save(_hinge_plot(rows, "Catalogue: continuous hinge positions"), out, "limit_hinges_vs_Sd_catalogue"))
    if full_scale:
        fs = [s for s in full_scale_set() if abs(s.arch.Rc - 5.0) < 1e-9]  # multipliers are scale-free
        rows_fs = multiplier_series(fs)
        files.append(_save(_lambda_plot(rows_fs, "Full-scale set (span 10 m; lambda is scale-free)", True), out,
                           "limit_lambda_vs_Sd_full_scale"))
        files.append(_save(_hinge_plot(rows_fs, "Full-scale set: continuous hinge positions"), out,
                           "limit_hinges_vs_Sd_full_scale"))
    for s in CATALOGUE:
        files.append(_save(mechanism_figure(s.id, s.arch), out, f"mechanism_{s.id}"))
    return files
