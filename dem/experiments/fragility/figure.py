"""Figures of fragility studies. Plotting only; no physics here."""
from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from dem.common.figures import save_figure


def fragility_figure(res):
    """P(collapse) per stripe with its binomial interval, the fitted lognormal with its median's
    interval, and the deterministic threshold, one colour per curve."""
    fig = Figure(figsize=(6.5, 4.2))
    ax = fig.subplots()
    for k, c in enumerate(res.curves):
        col = f"C{k}"
        if not c.stripes:
            continue
        x = np.array([s.intensity for s in c.stripes])
        p = np.array([s.p for s in c.stripes])
        lo = np.array([s.ci[0] for s in c.stripes])
        hi = np.array([s.ci[1] for s in c.stripes])
        ax.errorbar(x, p, yerr=[p - lo, hi - p], fmt="o", color=col, capsize=3, label=f"{c.group} (stripes, 95 %)")
        if c.fit is not None:
            xs = np.linspace(0.8 * x.min(), 1.2 * x.max(), 300)
            ax.plot(xs, c.fit.probability(xs), color=col,
                    label=f"lognormal: median {c.fit.median:.3g}, beta {c.fit.beta:.2g}")
            ax.axvspan(*c.fit.median_ci, color=col, alpha=0.12)
        if c.deterministic is not None:
            ax.axvline(c.deterministic, color=col, ls="--", lw=1, label=f"deterministic {c.deterministic:.3g}")
    unit = res.curves[0].unit if res.curves else ""
    ax.set(xlabel=f"intensity [{unit}]", ylabel="P(collapse)", ylim=(-0.03, 1.03), title=f"fragility — {res.label}")
    ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def save_fragility_figure(res, path) -> None:
    save_figure(fragility_figure(res), path)
