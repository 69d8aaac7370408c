"""The mode map's figure: specimens by frequency, each cell coloured by the mode of its first collapse."""
from __future__ import annotations

from matplotlib.figure import Figure
from matplotlib.patches import Patch, Rectangle

MODE_COLOURS = {"rocking": "#4c78a8", "mixed": "#f58518", "sliding": "#e45756", "none": "#e8e8e8",
                "failed": "#000000", "not run": "#ffffff"}
_HALF = {"first": "1st", "second": "2nd", "after": "later"}
_PHASE = {"before-first-rebound": "1st", "after-first-rebound": "2nd"}


def catalogue_order(sid: str) -> tuple[str, float]:
    """Catalogue ids by thickness, then shape: Sh02 is 0.2, Sh1 is 1."""
    sh, sd = sid.split("-")
    sh = sh[2:]
    return sd, float(f"0.{sh[1:]}" if sh.startswith("0") else sh)


def cell_label(r: dict) -> str:
    """A cell's text: the first collapse [g] ("*" above the table's reach) and its half cycle, the joint
    that slips first and its half cycle; the mode alone when nothing collapsed."""
    if r["amplitude_g"] is None:
        return r["mode"]
    above = " *" if r["within_reach"] is False else ""
    text = f"{r['amplitude_g']:.2f} g{above}, {_PHASE.get(r['phase'], '')}"
    return text + (f"\nslip {r['joint']} {_HALF.get(r['slip_half'], '')}" if r["joint"] else "")


def mode_map_figure(rows: list[dict], title: str = "") -> Figure:
    """The map of ``rows`` (:class:`~dem.experiments.mode_map.run.ModeMapResult` rows): a cell per specimen
    and frequency, a specimen or frequency missing from the rows left out."""
    ids = sorted({r["id"] for r in rows}, key=catalogue_order)
    freqs = sorted({r["freq"] for r in rows})
    cell = {(r["id"], r["freq"]): r for r in rows}
    fig = Figure(figsize=(1.3 * len(freqs) + 2.2, 0.42 * len(ids) + 1.6))
    ax = fig.subplots()
    for i, sid in enumerate(ids):
        for j, f in enumerate(freqs):
            r = cell.get((sid, f))
            mode = r["mode"] if r else "not run"
            ax.add_patch(Rectangle((j, i), 1, 1, color=MODE_COLOURS.get(mode, "#999999"), ec="white"))
            if r:
                ax.text(j + 0.5, i + 0.5, cell_label(r), ha="center", va="center", fontsize=7)
    ax.set_xlim(0, len(freqs))
    ax.set_ylim(0, len(ids))
    ax.set_xticks([j + 0.5 for j in range(len(freqs))], [f"{f:g} Hz" for f in freqs])
    ax.set_yticks([i + 0.5 for i in range(len(ids))], ids)
    ax.invert_yaxis()
    ax.set_title((title + "\n" if title else "") + "cell: first collapse, half cycle of the collapse (1st: before the "
                 "first rebound); the joint that slips first and its half cycle; * above the table's reach", fontsize=8)
    ax.legend(handles=[Patch(color=MODE_COLOURS[m], label=m) for m in ("rocking", "mixed", "sliding", "none")],
              loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8, title="first collapse", title_fontsize=8)
    fig.tight_layout()
    return fig
