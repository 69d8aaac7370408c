"""Figures of shake runs and DEM failure domains. Plotting only; no physics here."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from dem.common.figures import save_figure
from dem.experiments.shake.run import motion_trace
from specimens.constants import G


def plot_shake_history(t_in: np.ndarray, a_in: np.ndarray, t: np.ndarray, crown_u: np.ndarray, dmax: np.ndarray,
                       size: float, collapse_fraction: float, t_collapse: float | None = None,
                       t_rebound: float | None = None, title: str = ""):
    """Three panels over time: input ``a_g / g``; crown horizontal displacement [mm]; largest
    point displacement / size with the collapse level. Returns the figure."""
    fig = Figure(figsize=(7, 6.5))
    ax = fig.subplots(3, 1, sharex=True)
    ax[0].plot(t_in, np.asarray(a_in) / G, "k", lw=1)
    ax[0].set_ylabel("a_g / g")
    ax[1].plot(t, np.asarray(crown_u) * 1e3, "tab:blue", lw=1)
    ax[1].set_ylabel("crown u_x [mm]")
    ax[2].semilogy(t, np.maximum(np.asarray(dmax) / size, 1e-6), "tab:red", lw=1)
    ax[2].axhline(collapse_fraction, color="0.4", ls="--", lw=0.8, label="collapse level")
    ax[2].set_ylabel("max displacement / size")
    ax[2].set_xlabel("t [s]")
    for a in ax:
        if t_collapse is not None:
            a.axvline(t_collapse, color="tab:red", ls=":", lw=1)
        if t_rebound is not None:
            a.axvline(t_rebound, color="tab:green", ls=":", lw=1)
        a.grid(alpha=0.3)
    ax[2].legend(loc="lower right", fontsize=8)
    if title:
        ax[0].set_title(title)
    fig.tight_layout()
    return fig


def save_shake_figure(result, path: str | Path) -> Path:
    """Time-history figure of a :class:`dem.experiments.shake.run.ShakeResult`."""
    t_in, a_in = motion_trace(result.motion, result.sim.duration, result.settings.dt)
    h = result.sim.history
    fig = plot_shake_history(t_in, a_in, h.t, result.crown_u, h.dmax, result.model.size,
                             result.settings.collapse_fraction, result.t_collapse, result.t_rebound,
                             title=f"{result.label}: {'collapse' if result.collapsed else 'survival'}"
                                   f" ({result.mode}), PGA {result.motion.pga / G:.3f} g")
    return save_figure(fig, path)


def plot_domain_over_analytic(dem: dict, analytic: dict, path: str | Path, title: str = "") -> Path:
    """DEM failure domain (collapse bands shaded, thresholds as markers) over the analytic
    four-bar / two-bar thresholds (lines). ``dem``: dict of :func:`dem.experiments.shake.thresholds.failure_domain`;
    ``analytic``: name -> :class:`analytic.rocking.domain.FailureDomain`."""
    fig = Figure(figsize=(7, 5))
    ax = fig.subplots()
    xs = sorted({b["x"] for b in dem["bands"]})
    dx = 0.3 * (min(np.diff(xs)) if len(xs) > 1 else 1.0)
    for b in dem["bands"]:
        if b["collapse"]:
            ax.fill_between([b["x"] - dx, b["x"] + dx], b["from_g"], b["to_g"], color="tab:red", alpha=0.25, lw=0)
    first = [(p["x"], p["amplitude_g"]) for p in dem["points"] if p["mode"] != "collapse"]
    if first:
        ax.plot(*zip(*sorted(first)), "o-", color="tab:red", label="DEM least collapsing amplitude")
    styles = {"four-bar": ("k", "-"), "two-bar": ("tab:blue", "--")}
    for name, dom in analytic.items():
        c, ls = styles.get(name, ("0.5", ":"))
        pts = [(col.x, col.thresholds[0][0] / G) for col in dom.columns if col.thresholds]
        if pts:
            ax.plot(*zip(*pts), color=c, ls=ls, marker="s", ms=4, label=f"{name} (analytic, lowest threshold)")
        for col in dom.columns:
            for a, _ in col.thresholds[1:]:
                ax.plot([col.x], [a / G], marker="x", color=c, ms=5)
    if "lambda" in dem:
        ax.axhline(dem["lambda"], color="0.5", lw=0.8, ls=":", label="static onset lambda")
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("amplitude [g]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(title or "failure domain, one-cycle sine")
    fig.tight_layout()
    return save_figure(fig, path)
