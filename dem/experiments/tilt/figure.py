"""Figures of a tilt result: the arch at collapse (magnified displacements, joints coloured by
state) and the lambda bracket history. Plotting only; no physics here."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from specimens.io import atomic_path

STATE_COLOURS = {"closed": "0.6", "hinge": "tab:red", "slide": "tab:blue", "hinge+slide": "tab:purple", "open": "tab:orange"}


def _frame_at_collapse(result):
    sim = result.collapse
    h = sim.history
    lo, hi = (f * result.model.size for f in result.settings.mode_window)
    k = int(np.argmax(h.dmax >= hi)) if np.any(h.dmax >= hi) else len(h.t) - 1
    return h.pos[k], h.rotations()[k], float(h.dmax[k])


def plot_collapse(result, ax=None, magnify: float | None = None):
    """Draw the initial outline (grey) and the deformed outline at the end of the mode window,
    displacements magnified so the largest is ~ one ring thickness; joints coloured by state."""
    if ax is None:
        ax = Figure(figsize=(7, 5)).subplots()
    m = result.model
    pos, R, dmax = _frame_at_collapse(result)
    mag = magnify if magnify is not None else (m.size / dmax if dmax > 0 else 1.0)
    for i, b in enumerate(m.bodies):
        o = np.c_[b.outline, np.zeros(len(b.outline))]
        ax.fill(*np.vstack([b.outline, b.outline[:1]]).T, fc="none", ec="0.8", lw=0.8)
        x = pos[i] + (o - b.centroid) @ R[i].T
        x = b.outline + mag * (x[:, :2] - b.outline)
        ax.fill(*np.vstack([x, x[:1]]).T, fc="wheat", ec="k", lw=0.8, alpha=0.9)
    states = {j.joint: j for j in result.joints}
    for j in m.joints:
        st = states.get(j.name)
        c = STATE_COLOURS.get(st.state if st else "closed", "0.6")
        ax.plot([j.p_i[0], j.p_e[0]], [j.p_i[1], j.p_e[1]], color=c, lw=3 if st and st.state != "closed" else 1)
        if st and st.face:
            p = j.p_i if st.face == "intrados" else j.p_e
            ax.plot(*p, "o", color=c, ms=6)
    for s, c in STATE_COLOURS.items():
        ax.plot([], [], color=c, lw=3, label=s)
    ax.set_aspect("equal")
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title(f"{result.label}: lambda = {result.lam:.4f} ({result.theta_deg:.2f} deg), {result.mode}, "
                 f"displacements x{mag:.0f}", fontsize=9)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    return ax


def plot_bracket(result, ax=None):
    """Levels tried in order: collapsing (red x) and stable (green o), and the final bracket."""
    if ax is None:
        ax = Figure(figsize=(5, 4)).subplots()
    for k, (lam, col) in enumerate(result.levels, start=1):
        ax.plot(k, lam, "x" if col else "o", color="tab:red" if col else "tab:green")
    ax.axhspan(*result.bracket, color="0.9")

    ax.xaxis.set_major_locator(MaxNLocator(integer=True))  # simulations are counted
    ax.set_xlabel("simulation")
    ax.set_ylabel("lambda")
    ax.set_title(f"bracket [{result.bracket[0]:.4f}, {result.bracket[1]:.4f}]", fontsize=9)
    return ax


def save_tilt_figure(result, path: str | Path) -> Path:
    """Both panels in one file (png/pdf/svg), written atomically."""

    path = Path(path)
    fig = Figure(figsize=(12, 4.8))
    (a1, a2) = fig.subplots(1, 2, gridspec_kw={"width_ratios": [2, 1]})
    plot_collapse(result, a1)
    plot_bracket(result, a2)
    fig.tight_layout()
    with atomic_path(path, overwrite=True) as tmp:
        fig.savefig(tmp, format=path.suffix.lstrip(".") or "png", dpi=120)
    return path
