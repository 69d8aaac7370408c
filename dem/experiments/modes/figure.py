"""Mode shapes drawn on the structure. Plotting only; no physics here."""
from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from dem.common.figures import save_figure


def mode_shapes_figure(structure, res, n: int = 6, title: str = ""):
    """The first ``n`` modes: each body's outline moved by the mode, scaled to a tenth of the structure."""
    n = min(n, len(res.frequencies_hz))
    cols = min(3, n)
    rows = -(-n // cols)
    fig = Figure(figsize=(3.2 * cols, 2.8 * rows))
    axes = np.atleast_1d(fig.subplots(rows, cols)).ravel()
    pts = np.vstack([b.outline for b in structure.bodies])
    size = float(np.ptp(pts, axis=0).max())
    for k, ax in enumerate(axes):
        ax.set_axis_off()
        if k >= n:
            continue
        phi = res.shapes[:, k]
        disp = max(np.abs(phi[0::3]).max(), np.abs(phi[1::3]).max(), np.abs(phi[2::3]).max() * size, 1e-300)
        s = 0.1 * size / disp
        for i, b in enumerate(structure.bodies):
            c = np.asarray(b.centroid, float)
            ux, uy, th = s * phi[3 * i:3 * i + 3]
            r = b.outline - c
            rot = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
            moved = c + np.array([ux, uy]) + r @ rot.T
            ax.fill(*b.outline.T, color="0.85", lw=0)
            ax.plot(*np.vstack([moved, moved[:1]]).T, color="C3", lw=0.8)
        ax.set_aspect("equal")
        ax.set_title(f"mode {k + 1}: {res.frequencies_hz[k]:.4g} Hz", fontsize=8)
    if title:
        fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    return fig


def save_mode_shapes(structure, res, path, title: str = "") -> None:
    save_figure(mode_shapes_figure(structure, res, title=title), path)
