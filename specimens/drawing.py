"""Engineering drawings of arches (matplotlib): blocks, numbered joints, dimensions."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Polygon

from specimens.blocks import Assembly
from foundation.io import atomic_path

#: ``gid`` of the joint labels and of the box of the drawing's data, so a test can find them.
JOINT_LABEL_GID = "joint-label"
INFO_BOX_GID = "drawing-info"


def draw_assembly(assembly: Assembly, ax=None, title: str | None = None, dimensions: bool = True,
                  face_colors: list | None = None, joint_colors: dict[str, str] | None = None):
    """Draw the bodies (grey), the joints (numbered) and the main dimensions [mm] on ``ax``."""
    arch = assembly.arch
    if ax is None:
        ax = Figure(figsize=(7, 5.5)).subplots()
    if arch is None:
        return _draw_drawn(assembly, ax, title, face_colors, joint_colors)
    for k, body in enumerate(assembly.bodies):
        fc = face_colors[k] if face_colors is not None else ("#d9c7a5" if body.name != "C" else "#c4a97a")
        if assembly.contact == 1.0:
            ax.add_patch(Polygon(body.outline * 1000, closed=True, fc=fc, ec="k", lw=0.8))
        else:  # the relieved pieces, so the reduced joints show
            for piece in body.pieces:
                ax.add_patch(Polygon(piece * 1000, closed=True, fc=fc, ec=fc, lw=0.3))
            ax.add_patch(Polygon(body.outline * 1000, closed=True, fc="none", ec="0.6", lw=0.4, ls=":"))
    for j in assembly.joints:
        p = np.array(j.contact_points) * 1000
        col = (joint_colors or {}).get(j.name, "tab:blue")
        ax.plot(p[:, 0], p[:, 1], color=col, lw=1.6)
        # label outside the extrados along the joint direction
        lab = (j.p_e + 0.35 * arch.t * j.tangent) * 1000
        if j.is_base:
            lab = (j.p_i + j.p_e) / 2 * 1000 + np.array([0.0, -0.25 * arch.t * 1000])
        ax.text(lab[0], lab[1], j.name, ha="center", va="center", fontsize=7, color=col, gid=JOINT_LABEL_GID)
    piers = assembly.piers
    ground = -piers.height * 1000 if piers is not None else 0.0
    base_x = max((arch.Rc + arch.t), piers.inner_x(arch) + piers.width if piers else 0.0) * 1000 * 1.15
    ax.fill_between([-base_x, base_x], [ground - 0.06 * arch.Rc * 1000] * 2, [ground] * 2, color="0.8", hatch="//", lw=0)
    if dimensions and piers is not None:
        x = (piers.inner_x(arch) + piers.width + 1.3 * arch.t) * 1000  # clear of the joint labels
        ax.annotate("", xy=(x, ground), xytext=(x, 0), arrowprops=dict(arrowstyle="<->", lw=0.8))
        ax.text(x + 0.2 * arch.t * 1000, ground / 2, f"pier {piers.height * 1000:.0f} mm\n{piers.courses} course(s)", ha="left",
                va="center", fontsize=8)
    if dimensions:
        span = arch.span * 1000
        y = ground - 0.12 * arch.Rc * 1000
        xi = (arch.Rc - arch.t / 2) * 1000
        ax.annotate("", xy=(-xi, y), xytext=(xi, y), arrowprops=dict(arrowstyle="<->", lw=0.8))
        ax.text(0, y + 0.35 * (y - ground), f"clear span {span:.0f} mm", ha="center", va="top", fontsize=8)
        rise = arch.rise * 1000
        xr = -xi * 0.15
        ax.annotate("", xy=(xr, 0), xytext=(xr, rise), arrowprops=dict(arrowstyle="<->", lw=0.8))
        ax.text(xr - 5, rise / 2, f"rise {rise:.0f} mm", ha="right", va="center", fontsize=8, rotation=90)
        _info_box(ax, f"Ri = {arch.Ri*1000:.0f} mm, Re = {arch.Re*1000:.0f} mm, "
                  f"e = {arch.e*1000:.0f} mm, t = {arch.t*1000:.0f} mm\n"
                  + (f"piers {piers.width*1000:.0f} x {piers.height*1000:.0f} x {piers.depth_for(arch)*1000:.0f} mm"
                     + (f", {piers.load / 1e3:g} kN on each" if piers.load else "") + "\n"
                     if piers is not None else "") +
                  f"{assembly.config}, {assembly.n_bodies} bodies, {assembly.total_mass:.3f} kg")
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(title or f"Sh = {arch.Sh:.2f}, Sd = {arch.Sd:.2f}")
    ax.autoscale_view()
    return ax


def _draw_drawn(assembly, ax, title, face_colors, joint_colors):
    """A drawn assembly (no arch): bodies named at their centroids, joints numbered, the supports hatched."""
    size = assembly.size * 1000
    for k, body in enumerate(assembly.bodies):
        fc = face_colors[k] if face_colors is not None else ("#d9c7a5" if k != assembly.crown_index else "#c4a97a")
        for piece in body.pieces:
            ax.add_patch(Polygon(piece * 1000, closed=True, fc=fc, ec=fc, lw=0.3))
        ax.add_patch(Polygon(body.outline * 1000, closed=True, fc="none", ec="k", lw=0.8))
        c = body.centroid * 1000
        ax.text(c[0], c[1], body.name, ha="center", va="center", fontsize=6, color="0.3")
    for j in assembly.joints:
        p = np.array(j.contact_points) * 1000
        col = (joint_colors or {}).get(j.name, "tab:red" if j.is_base else "tab:blue")
        ax.plot(p[:, 0], p[:, 1], color=col, lw=1.6)
        # beyond the joint's outer (p_e) end, as on an arch; a support's below its joint
        lab = j.p_e * 1000 + 0.5 * size * j.tangent
        if j.is_base:
            lab = p.mean(axis=0) - 0.4 * size * np.asarray(j.normal) * (1.0 if j.a < 0 else -1.0)
        ax.text(lab[0], lab[1], f"{j.index}" + ("" if j.name == f"J{j.index}" else f" {j.name}"), ha="center",
                va="center", fontsize=6, color=col, gid=JOINT_LABEL_GID)
    src = assembly.source
    _info_box(ax, f"{src.get('file', '')} (drawn in {src.get('units', 'm')}), {assembly.n_bodies} bodies, "
              f"{len(assembly.joints)} joints ({sum(j.is_base for j in assembly.joints)} on supports), "
              f"{assembly.total_mass:.4g} kg\n" + ("one chain: four-hinge enumeration applies" if assembly.is_chain
                                                   else "not one chain: LP and DEM only"))
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(title or src.get("file", "drawing"))
    ax.margins(0.1)
    ax.autoscale_view()
    return ax


def _info_box(ax, text: str) -> None:
    """The drawing's data below the x axis's label, clear of the blocks and their joint labels (which
    fill different corners of the axes from one arch to the next)."""
    # x in axes fractions, y in fractions of the x label's box: the box follows the label wherever
    # the layout puts it
    ax.annotate(text, xy=(0.0, 0.0), xycoords=("axes fraction", ax.xaxis.label), xytext=(0, -4),
                textcoords="offset points", ha="left", va="top", fontsize=8, family="monospace", gid=INFO_BOX_GID,
                annotation_clip=False, bbox=dict(boxstyle="square,pad=0.3", fc="white", ec="0.5", lw=0.6))


def drawing_figure(assembly: Assembly, title: str | None = None) -> Figure:
    """The figure ``save_drawing`` writes (7 x 6 in), laid out."""
    fig = Figure(figsize=(7, 6))
    ax = fig.subplots()
    draw_assembly(assembly, ax, title=title)
    fig.tight_layout()
    return fig


def drawing_title(label: str, assembly: Assembly, plane_depth: float | None = None) -> str:
    """The title ``archdem draw`` gives: an arch's label and ratios Sh, Sd; a drawing's label and density,
    and, where its blocks without a depth were drawn ``plane_depth`` [m] deep, that its masses are per metre."""
    a = assembly.arch
    if a is not None:
        return f"{label}   Sh = {a.Sh:.2f}, Sd = {a.Sd:.2f}"
    return f"{label}\ndensity {assembly.density:g} kg/m^3" + (
        f", blocks without a depth {plane_depth:g} m deep (masses per metre)" if plane_depth is not None else "")


def save_drawing(assembly: Assembly, path: str | Path, title: str | None = None) -> Path:
    """Draw ``assembly`` and save it atomically to ``path`` (format from the suffix)."""

    path = Path(path)
    fig = drawing_figure(assembly, title)
    with atomic_path(path, overwrite=True) as tmp:
        fig.savefig(tmp, format=path.suffix.lstrip(".") or "png", dpi=130)
    return path
