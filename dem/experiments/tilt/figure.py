"""Figures of a tilt result: the arch at collapse (magnified displacements, joints coloured by
state, the joints that moved named, the load's direction) and the lambda bracket history.
Plotting only; no physics here."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from dem.common.figures import save_figure

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
        if st and st.state != "closed":
            # named as the report's text and `archdem tilt` name them, beyond the joint's outer end
            _label_joint(ax, j, c, 0.6 * m.size)
    for s, c in STATE_COLOURS.items():
        ax.plot([], [], color=c, lw=3, label=s)
    _load_arrow(ax, m)
    ax.set_aspect("equal")
    ax.autoscale_view()
    # beside the axes: inside, it would cover a block or a joint's name on some arch
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, title="joint state", title_fontsize=8)
    ax.set_title(f"{result.label}: lambda = {result.lam:.4f} ({result.theta_deg:.2f} deg), {result.mode}, "
                 f"displacements magnified x{mag:.0f}", fontsize=9)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    return ax


def _label_joint(ax, joint, colour: str, offset: float) -> None:
    """The joint's name ``offset`` [m] beyond its outer end (``p_e``), along the joint from ``p_i``."""
    p_i, p_e = np.asarray(joint.p_i, float)[:2], np.asarray(joint.p_e, float)[:2]
    d = p_e - p_i
    n = float(np.hypot(*d))
    at = p_e + (offset * d / n if n > 0 else 0.0)
    ax.update_datalim([at])  # text does not widen the axes' limits: the label would fall outside them
    ax.text(at[0], at[1], joint.name, ha="center", va="center", fontsize=8, color=colour, fontweight="bold",
            gid=f"joint-label-{joint.name}", zorder=5,
            bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))


def _load_arrow(ax, model) -> None:
    """An arrow below the springings: the tilt's equivalent horizontal load, lambda x the weight, to +x
    (dem.experiments.tilt.run: gravity's horizontal part points to +x)."""
    xs = np.concatenate([b.outline[:, 0] for b in model.bodies])
    ys = np.concatenate([b.outline[:, 1] for b in model.bodies])
    width = float(xs.max() - xs.min())
    y = float(ys.min()) - 0.12 * width
    x0, x1 = float(xs.mean()) - 0.15 * width, float(xs.mean()) + 0.15 * width
    ax.annotate("", xy=(x1, y), xytext=(x0, y), gid="load-direction",
                arrowprops=dict(arrowstyle="-|>", lw=2, color="k", mutation_scale=15))
    ax.text((x0 + x1) / 2, y - 0.03 * width, "equivalent horizontal load: lambda x weight (tilt)", ha="center",
            va="top", fontsize=8)
    ax.update_datalim([(x0, y - 0.1 * width), (x1, y)])  # room for the arrow and its words inside the axes


#: The bracket panel's legend entries: a level that collapsed, one that stood, the final bracket.
BRACKET_LABELS = ("collapsed", "stood", "final bracket")


def plot_bracket(result, ax=None):
    """Levels tried in order: collapsing (red x) and stable (green o), and the final bracket; lambda [-]
    on the left axis, the tilt angle [deg] on the right."""
    if ax is None:
        ax = Figure(figsize=(5, 4)).subplots()
    for k, (lam, col) in enumerate(result.levels, start=1):
        ax.plot(k, lam, "x" if col else "o", color="tab:red" if col else "tab:green")
    ax.axhspan(*result.bracket, color="0.9")
    # one legend entry per kind, whichever levels this test simulated
    ax.plot([], [], "x", color="tab:red", label=BRACKET_LABELS[0])
    ax.plot([], [], "o", color="tab:green", label=BRACKET_LABELS[1])
    ax.fill_between([], [], color="0.9", label=BRACKET_LABELS[2])
    ax.legend(loc="best", fontsize=8)

    ax.xaxis.set_major_locator(MaxNLocator(integer=True))  # simulations are counted
    ax.set_xlabel("simulation (in the order run) [-]")
    ax.set_ylabel("lambda = tan(theta) [-]")
    sec = ax.secondary_yaxis("right", functions=(lambda v: np.degrees(np.arctan(v)), lambda d: np.tan(np.radians(d))))
    sec.set_ylabel("tilt angle theta [deg]")
    lo, hi = result.bracket
    ax.set_title(f"lambda bracket [{lo:.4f}, {hi:.4f}] = [{math.degrees(math.atan(lo)):.2f}, "
                 f"{math.degrees(math.atan(hi)):.2f}] deg", fontsize=9)
    return ax


def save_tilt_figure(result, path: str | Path) -> Path:
    """Both panels in one file (png/pdf/svg), written atomically."""

    fig = Figure(figsize=(12, 4.8))
    (a1, a2) = fig.subplots(1, 2, gridspec_kw={"width_ratios": [2, 1]})
    plot_collapse(result, a1)
    plot_bracket(result, a2)
    fig.tight_layout()
    return save_figure(fig, path, overwrite=True, tight=False)
