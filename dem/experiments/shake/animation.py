"""Animations of run files (tilt or shake): the blocks moving over time, the input underneath.

``animate(run_file, out)`` reads an HDF5 run file (format ``archdem-tilt-1`` of
:mod:`dem.experiments.tilt.file` — the collapsing simulation is shown — or ``archdem-shake-1`` of
:mod:`dem.experiments.shake.run`), draws every body's outline at each recorded instant (true scale, no
magnification) over the base, and below it the input trace (shake: ``a_g / g``; tilt: the
horizontal load multiplier ``lambda = -g_x / g_y``) with a moving cursor. GIF via matplotlib's
``PillowWriter``; MP4 via ``FFMpegWriter`` only when ffmpeg is installed (otherwise a clear error).
"""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np

from specimens.constants import G
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path, can_make_dir


def read_run(path: str | Path) -> dict:
    """``model``, ``history`` (:class:`dem.core.simulate.History`), ``input_t``, ``input`` (values),
    ``input_label``, ``title`` of a tilt or shake run file."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    import h5py

    path = Path(path)
    if not path.is_file():
        raise ArchdemInputError(f"{path}: no such run file")
    try:
        with h5py.File(path, "r") as f:
            fmt = str(f.attrs.get("format", ""))
    except OSError:
        raise ArchdemInputError(f"{path}: not an HDF5 run file") from None
    if fmt == "archdem-shake-1":
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.shake.file import load_shake

        d = load_shake(path)
        s = d["summary"]
        return {"model": d["model"], "history": d["sim"].history, "input_t": d["input_t"],
                "input": d["input_a"] / G, "input_label": "a_g / g",
                "title": f"{d['label']}: shake, PGA {s.get('pga_g', float('nan')):.3f} g, "
                         f"{'collapse' if s['collapsed'] else 'survival'}"}
    if fmt == "archdem-tilt-1":
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.tilt import load_result

        r = load_result(path)
        sim = r.collapse or r.stable
        if sim is None:
            raise ArchdemInputError(f"{path}: the tilt result holds no simulation history")
        h = sim.history
        lam = -h.gravity[:, 0] / h.gravity[:, 1]
        return {"model": r.model, "history": h, "input_t": h.t, "input": lam, "input_label": "lambda",
                "title": f"{r.label}: tilt, lambda = {r.lam:.4f} ({r.mode})"}
    raise ArchdemInputError(f"{path}: not an archdem tilt or shake run file (format {fmt or 'missing'!r})")


def _outlines(model, pos: np.ndarray, R: np.ndarray) -> list[np.ndarray]:
    out = []
    for i, b in enumerate(model.bodies):
        o = np.c_[b.outline, np.full(len(b.outline), b.centroid[2])]
        x = pos[i] + (o - b.centroid) @ R[i].T
        out.append(np.vstack([x[:, :2], x[:1, :2]]))
    return out


def animate(path: str | Path, out: str | Path, fps: int = 25, max_frames: int = 200, overwrite: bool = False) -> Path:
    """Write the animation of run file ``path`` to ``out`` (.gif or .mp4); returns ``out``."""

    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from matplotlib import animation
    from matplotlib.figure import Figure

    out = Path(out)
    ext = out.suffix.lower()
    if ext not in (".gif", ".mp4"):
        raise ArchdemInputError(f"--out must end in .gif or .mp4, got {out.name!r}")
    if ext == ".mp4" and shutil.which("ffmpeg") is None:
        raise ArchdemInputError("mp4 needs ffmpeg, which is not installed; write a .gif instead")
    if not (fps >= 1 and max_frames >= 2):
        raise ArchdemInputError("fps must be >= 1 and max_frames >= 2")
    if out.exists() and not overwrite:
        raise ArchdemInputError(f"{out} exists; not overwriting it (choose another --out)")
    can_make_dir(out.parent)  # before any drawing: a failure leaves nothing behind
    run = read_run(path)
    model, h = run["model"], run["history"]
    if len(h.t) < 2:
        raise ArchdemInputError(f"{path}: the run has fewer than 2 recorded instants")
    frames = np.unique(np.linspace(0, len(h.t) - 1, min(max_frames, len(h.t))).round().astype(int))
    Rs = h.rotations()

    fig = Figure(figsize=(6.4, 6.4))
    (ax, ax2) = fig.subplots(2, 1, gridspec_kw={"height_ratios": [3, 1]})
    allpts = np.vstack([np.vstack(_outlines(model, h.pos[k], Rs[k])) for k in (0, frames[-1])])
    for p in model.base.pieces:
        ax.fill(*np.vstack([p, p[:1]]).T, fc="0.85", ec="0.5", lw=0.6)
    x0, x1 = allpts[:, 0].min(), allpts[:, 0].max()
    y1 = allpts[:, 1].max()
    pad = 0.1 * max(x1 - x0, y1)
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(min(-0.1 * y1, allpts[:, 1].min()) - pad * 0.2, y1 + pad)
    ax.set_aspect("equal")
    ax.set_title(run["title"], fontsize=9)
    patches = [ax.fill(*o.T, fc="wheat", ec="k", lw=0.8)[0] for o in _outlines(model, h.pos[0], Rs[0])]
    label = ax.text(0.02, 0.95, "", transform=ax.transAxes, va="top", fontsize=8)
    ax2.plot(run["input_t"], run["input"], "k", lw=1)
    ax2.set_xlim(0, max(float(h.t[-1]), float(run["input_t"][-1])))
    ax2.set_xlabel("t [s]")
    ax2.set_ylabel(run["input_label"])
    ax2.grid(alpha=0.3)
    cursor = ax2.axvline(0.0, color="tab:red", lw=1)
    fig.tight_layout()

    def update(k):
        for p, o in zip(patches, _outlines(model, h.pos[k], Rs[k])):
            p.set_xy(o)
        cursor.set_xdata([h.t[k], h.t[k]])
        label.set_text(f"t = {h.t[k]:.3f} s   max displacement {h.dmax[k] * 1e3:.1f} mm")
        return patches + [cursor, label]

    writer = animation.PillowWriter(fps=fps) if ext == ".gif" else animation.FFMpegWriter(fps=fps)
    with atomic_path(out, overwrite=overwrite) as tmp:
        tmp_ext = tmp.with_suffix(ext)
        try:  # the animation is made only once its file can be: an unsaved one is a library warning
            anim = animation.FuncAnimation(fig, update, frames=list(frames), blit=False)
            anim.save(str(tmp_ext), writer=writer)
            tmp_ext.replace(tmp)
        finally:
            if tmp_ext.exists():
                tmp_ext.unlink()
    return out
