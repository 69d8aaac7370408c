"""Figure of the engine cross-check (:mod:`dem.experiments.compare_engines.run`)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from dem.common.figures import save_figure


def plot_engine_comparison(rows, axes=None):
    """Two panels (no sliding, reference friction): lambda per specimen from each engine and the LP."""
    cases = [f for f in ("none", "reference") if any(r.friction == f for r in rows)]
    if axes is None:
        axes = Figure(figsize=(6 * len(cases), 4.2)).subplots(1, len(cases), squeeze=False)
        axes = axes[0]
    titles = {"none": "no sliding (LP exact)", "reference": "friction 0.577 / 1.0 (associative LP: no bound)"}
    markers = {"pybullet": "s", "mujoco": "o"}
    for ax, f in zip(axes, cases):
        rs = [r for r in rows if r.friction == f]
        x = np.arange(len(rs))
        ax.plot(x, [r.lp_lam for r in rs], "_", ms=18, mew=2, color="k", label="LP")
        for k, e in enumerate(rs[0].engines if rs else []):
            ax.plot(x + 0.12 * (k - 0.5), [r.results[e].lam for r in rs], markers.get(e, "^"), mfc="none", label=e)
        ax.set_xticks(x, [f"{r.id}\n{r.config}" for r in rs], rotation=60, fontsize=7)
        ax.set_ylabel("lambda = tan theta")
        ax.set_title(titles[f], fontsize=9)
        ax.legend(fontsize=8)
    return axes


def save_engine_comparison(rows, path: str | Path) -> Path:
    """Write the figure (png/pdf/svg) atomically."""

    axes = plot_engine_comparison(rows)
    fig = axes[0].figure
    fig.tight_layout()
    return save_figure(fig, path, overwrite=True, tight=False)
