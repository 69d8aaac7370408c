"""Plots of the linkage dynamics: one time history, and a failure domain (matplotlib, files only)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from analytic.rocking.domain import FailureDomain
from analytic.rocking.dynamics import Response
from specimens.constants import G
from foundation.io import atomic_path


def _save(fig, path: str | Path, overwrite: bool = False) -> Path:
    path = Path(path)
    fmt = path.suffix.lstrip(".") or "png"
    with atomic_path(path, overwrite=overwrite) as tmp:
        fig.savefig(tmp, format=fmt, dpi=130, bbox_inches="tight")

    return path


def plot_response(resp: Response, path: str | Path, title: str = "", input_end: float | None = None,
                  overwrite: bool = False) -> Path:
    """Rotation / phi_cr against time, impacts marked, input end and collapse shown."""
    fig = Figure(figsize=(7, 3.6))
    ax = fig.subplots()
    ax.plot(resp.t, resp.ratio, lw=1.2, color="C0", label="phi / phi_cr")
    for k, imp in enumerate(resp.impacts):
        ax.axvline(imp.t, color="0.6", lw=0.6, ls=":", label="impact" if k == 0 else None)
    ax.axhline(1.0, color="C3", lw=0.7, ls="--")
    ax.axhline(-1.0, color="C3", lw=0.7, ls="--")
    if input_end is not None:
        ax.axvline(input_end, color="k", lw=0.8, ls="-.", label="input ends")
    if resp.collapsed and resp.t_collapse is not None:
        ax.plot([resp.t_collapse], [np.sign(resp.residual or 1.0)], "rx", ms=9, label=f"collapse ({resp.mode})")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("phi / phi_cr")
    ax.set_title(title or ("collapse" if resp.collapsed else "survival") + f" ({resp.rule})")
    ax.legend(loc="best", fontsize=8)
    ax.grid(alpha=0.3)
    return _save(fig, path, overwrite)


def plot_domain(dom: FailureDomain, path: str | Path, title: str = "", overwrite: bool = False) -> Path:
    """Failure domain: collapse bands (both modes) and survival, amplitude in g; normalised twin axis."""
    colours = {"survival": "#d9f0d3", "first-half-cycle": "#f4a582", "after-impact": "#ca0020"}
    xs = np.array([c.x for c in dom.columns])
    w = np.diff(xs).min() if len(xs) > 1 else 0.1 * xs[0]
    fig = Figure(figsize=(7, 4.2))
    ax = fig.subplots()
    seen = set()
    for c in dom.columns:
        for b in c.bands:
            lab = b.outcome if b.outcome not in seen else None
            seen.add(b.outcome)
            ax.bar(c.x, (b.hi - b.lo) / G, bottom=b.lo / G, width=w, color=colours[b.outcome], lw=0, label=lab)
    lin = [(c.x, c.linearised / G) for c in dom.columns if c.linearised is not None]
    if lin:
        ax.plot(*zip(*lin), "k--", lw=1, label="linearised estimate")
    ax.axhline(dom.lam, color="k", lw=0.6, label="onset lambda g")
    ax.set_xlabel("frequency [Hz]" if dom.axis == "frequency" else "pulse duration t_i [s]")
    ax.set_ylabel("amplitude [g]")
    ax.set_ylim(0, dom.a_range[1] / G)
    sec = ax.secondary_yaxis("right", functions=(lambda a: a / dom.lam, lambda r: r * dom.lam))
    sec.set_ylabel("a / (lambda g)")
    ax.set_title(title or f"failure domain ({dom.input_kind})")
    ax.legend(loc="upper left", fontsize=8)
    return _save(fig, path, overwrite)
