"""The shake table's mode map: per specimen and frequency of a one-cycle sine, the first collapse, its mode,
the joint that slips first and the half cycle it slips in, with the table as a speed-limited actuator
(docs/validation.md#22, where the ingredients were tried and fitted on Sh1-Sd015).

The map is the experiment ``dem.experiments.mode_map`` (its spec, case function, table and figure; the
campaign's optional step ``mode-map``); this script runs it from the command line and keeps the ingredient
study. Every case is a threshold search (glued, MuJoCo's defaults; scan from the static onset lambda g by
1.15, bisected to 1 %) run through the project's sweep (``dem.studies.sweep.run_study``: resumable, one case
per search). The fitted table (the defaults): a servo of 1 m/s, velocity command, the commanded amplitude
scanned up to 1.5 x the table's reach ``pi f v_max`` (above the reach the servo saturates; each row says
whether its collapse is within it). The collapsing run at the threshold is run again to read which joint
slips first (both of its ends more than ``SLIP_MM`` along it) and when.

    python benchmarks/shake_mode_map.py [--specimens all|ID,ID] [--freqs 2,4,6,8,10] [--workers 1]
        [--table-speed 1.0 (0: the ideal sine)] [--tau S] [--mu-base 1.0] [--contact 1|calibrated]
        [--restitution 0] [--scan-over 1.5] [--out benchmarks/results/shake_mode_map.h5] [--png FILE]
        [--resume] [--report]
    python benchmarks/shake_mode_map.py --ingredients [--freqs 2,4,8,10]    # Sh1-Sd015, one ingredient a row

Writes the table as CSV (its schema beside it) and the figure as PNG beside ``--out`` (``--png``
elsewhere); ``--report`` makes them from what the study file holds, without running (a case not run reads
"not run").
"""
from __future__ import annotations

import argparse
from pathlib import Path

from dem.common.figures import save_figure
from dem.experiments.mode_map.case import SLIP_MM
from dem.experiments.mode_map.case import mode_case as map_case
from dem.experiments.mode_map.figure import mode_map_figure
from dem.experiments.mode_map.run import ModeMapResult, ModeMapSpec

RESULTS = Path(__file__).resolve().parent / "results"
#: The ingredient study: name -> the case's settings over the ideal table's (docs/validation.md#22).
INGREDIENTS = {
    "ideal sine (archdem today)": {},
    "servo, velocity command": {"table_speed": 1.0},
    "servo, position loop 20 ms": {"table_speed": 1.0, "tau": 0.02},
    "calibrated contact": {"contact": "calibrated"},
    "feet on steel mu_base 0.6": {"mu_base": 0.6},
    "restitution 0.3": {"restitution": 0.3},
    "feet on steel mu_base 0.4": {"mu_base": 0.4},
}
__all__ = ["INGREDIENTS", "SLIP_MM", "mode_case"]


def mode_case(case: dict) -> dict:
    """One threshold search of the map (:func:`dem.experiments.mode_map.case.mode_case`). The study files
    this script writes record their case function as ``shake_mode_map:mode_case`` and a resume checks the
    name, so the script keeps its own."""
    return map_case(case)


def main() -> None:
    from shake_mode_map import mode_case as case_fn  # by its module's name: the sweep's workers import it

    from dem.studies.sweep import load_study, run_study

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--specimens", default="all", help="all, or comma-separated catalogue ids")
    ap.add_argument("--freqs", default="2,4,6,8,10", help="comma-separated sine frequencies [Hz]")
    ap.add_argument("--table-speed", dest="table_speed", type=float, default=1.0,
                    help="the table's speed limit [m/s] (0: the ideal sine)")
    ap.add_argument("--tau", type=float, default=0.0, help="the servo's position-loop time constant [s] "
                    "(default 0: a velocity command, the fit of docs/validation.md#22)")
    ap.add_argument("--mu-base", dest="mu_base", type=float, default=1.0, help="friction of the feet on the table")
    ap.add_argument("--contact", default=1.0, help="contact fraction of the joints, or 'calibrated'")
    ap.add_argument("--restitution", type=float, default=0.0)
    ap.add_argument("--reach-speed", dest="reach_speed", type=float, default=1.0,
                    help="the speed [m/s] whose reach pi f v caps the scan (the laboratory's servo: 1)")
    ap.add_argument("--scan-over", dest="scan_over", type=float, default=1.5,
                    help="scan the commanded amplitude up to this x the reach")
    ap.add_argument("--ingredients", action="store_true", help="the ingredient study on Sh1-Sd015")
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--out", default=None, help="study file (.h5); the CSV and PNG are written beside it")
    ap.add_argument("--png", default=None, help="the figure's file (default beside --out)")
    ap.add_argument("--resume", action="store_true")
    ap.add_argument("--report", action="store_true", help="no runs: the table and figure of what --out holds")
    a = ap.parse_args()
    contact = a.contact if a.contact == "calibrated" else float(a.contact)
    freqs = tuple(float(x) for x in a.freqs.split(","))
    if a.ingredients:
        # the ideal table on Sh1-Sd015, each ingredient's settings over it (a servo scanned to 1.5 x its reach)
        ideal = ModeMapSpec(specimens=("Sh1-Sd015",), freqs=freqs, table_speed=None, scan_over=1.0)
        cases, labels = [], []
        for name, over in INGREDIENTS.items():
            for f in freqs:
                cases.append({**ideal.case("Sh1-Sd015", f), **over, **({"scan_over": 1.5} if over.get("table_speed") else {})})
                labels.append(name)
        spec, stem = None, "shake_ingredients"
    else:
        ids = {} if a.specimens == "all" else {"specimens": tuple(s.strip() for s in a.specimens.split(","))}
        spec = ModeMapSpec(**ids, freqs=freqs, table_speed=a.table_speed or None, tau=a.tau or None,
                           mu_base=a.mu_base, contact=contact, restitution=a.restitution, reach_speed=a.reach_speed,
                           scan_over=a.scan_over)
        cases, labels, stem = spec.cases(), None, "shake_mode_map"
    out = Path(a.out) if a.out else RESULTS / f"{stem}.h5"
    out.parent.mkdir(parents=True, exist_ok=True)
    study = load_study(out, cases) if a.report else run_study(cases, case_fn, out, workers=a.workers, resume=a.resume)
    res = ModeMapResult.from_study(study, cases, labels, title=spec.title() if spec else "")
    res.write_csv(out.with_suffix(".csv"))
    print("\n".join(res.lines()))
    if spec is not None:
        save_figure(mode_map_figure(res.rows(), spec.title()), Path(a.png) if a.png else out.with_suffix(".png"),
                    overwrite=True, dpi=130)
    print(f"written {out.with_suffix('.csv')}")


if __name__ == "__main__":
    main()
