"""The shake table's mode map as the program, the campaign and the report see it (dem.experiments.contract)."""
from __future__ import annotations

from dem.experiments.contract import Experiment, Step, Summary, Tables, fmt

_HALF = {"first": "1st", "second": "2nd", "after": "after"}
_PHASE = {"before-first-rebound": "1st", "after-first-rebound": "2nd"}


def cell_text(r: dict) -> str:
    """One cell of the map as docs/validation.md#22 writes it: the first collapse [g], its mode's initial
    and half cycle (1st: before the first rebound), "(above reach)", then the joint that slips first and
    its half cycle; "none up to" the scan's top when the arch stands."""
    if r["amplitude_g"] is None:
        return f"none up to {fmt(r['scan_top_g'])} g" if r["mode"] == "none" and r["scan_top_g"] else r["mode"]
    text = f"<b>{r['amplitude_g']:.3f}</b> {r['mode'][:1]} {_PHASE.get(r['phase'], r['phase'])}"
    text += " (above reach)" if r["within_reach"] is False else ""
    return text + (f"; {fmt(r['joint'])} {_HALF.get(r['slip_half'], '')}".rstrip() if r["joint"] else "")


def summary_table(tables: Tables) -> tuple[str, tuple[str, ...], list[tuple[str, ...]]] | None:
    """The map as a table, a row per specimen and a column per frequency (None when the step did not run)."""
    rows = tables.get("mode_map")
    if not rows:
        return None
    ids = list(dict.fromkeys(r["id"] for r in rows))
    freqs = sorted({r["freq"] for r in rows})
    cell = {(r["id"], r["freq"]): cell_text(r) for r in rows}
    return ("The shake table's mode map: the first collapse [g], r rocking, m mixed, s sliding, its half cycle; "
            "the joint that slips first and its half cycle",
            ("specimen",) + tuple(f"{f:g} Hz" for f in freqs),
            [(fmt(sid),) + tuple(cell.get((sid, f), "") for f in freqs) for sid in ids])


EXPERIMENT = Experiment(
    name="mode_map", title="the shake table's mode map",
    steps=(Step("mode-map", "dem.experiments.mode_map.step_mode_map:step_mode_map",
                "the shake table's mode map: per specimen and sine frequency the first collapse within a "
                "speed-limited table's reach, its mode and the joint that slips first", rank=140, optional=True),),
    summary=Summary(table=summary_table, rank=90),
)
