"""The shake table's mode map: per specimen and frequency of a one-cycle sine, the first collapse, its mode,
the joint that slips first and the half cycle it slips in, with the table as a speed-limited actuator
(docs/validation.md#22, where the ingredients were tried and fitted on Sh1-Sd015).

Every case is a threshold search (glued, MuJoCo's defaults; scan from the static onset lambda g by 1.15,
bisected to 1 %) run through the project's sweep (``dem.studies.sweep.run_study``: resumable, one case per
search). The fitted table (the defaults): a servo of 1 m/s, velocity command, the commanded amplitude
scanned up to 1.5 x the table's reach ``pi f v_max`` (above the reach the servo saturates; each row says
whether its collapse is within it). The collapsing run at the threshold is run again to read which joint
slips first (both of its ends more than ``SLIP_MM`` along it) and when.

    python benchmarks/shake_mode_map.py [--specimens all|ID,ID] [--freqs 2,4,6,8,10] [--workers 1]
        [--table-speed 1.0 (0: the ideal sine)] [--tau S] [--mu-base 1.0] [--contact 1|calibrated]
        [--restitution 0] [--scan-over 1.5] [--out benchmarks/results/shake_mode_map.h5] [--png FILE]
        [--resume] [--report]
    python benchmarks/shake_mode_map.py --ingredients [--freqs 2,4,8,10]    # Sh1-Sd015, one ingredient a row

Writes the table as CSV and the figure as PNG beside ``--out`` (``--png`` elsewhere); ``--report`` makes
them from what the study file holds, without running (a case not run reads "not run").
"""
from __future__ import annotations

import argparse
import csv
import math
import time
from functools import partial
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results"
#: A joint slips when both its ends have moved along it by more than this [mm] (a hinge turns about one end).
SLIP_MM = 0.2
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


def servo_motion(a: float, f: float, v_max: float | None = None, tau: float | None = None):
    """The table's motion for a commanded one-cycle sine ``a`` [m/s^2] at ``f`` [Hz] (module-level: it reaches
    worker processes by reference)."""
    from analytic.motions.inputs import SinePulse
    from analytic.motions.table import servo_sine

    return SinePulse(a, f) if v_max is None else servo_sine(a, f, v_max, tau)


def first_slip(model, res, slip_mm: float = SLIP_MM) -> tuple[str, float | None]:
    """The joint that slips first in a run (both ends more than ``slip_mm`` along it) and when [s], read until
    the collapse criterion (a point moved one ring thickness: past it a falling arch's joints all move)."""
    import numpy as np

    from dem.core.detect import joint_kinematics

    h = res.sim.history
    R = h.rotations()
    upto = model.size * res.settings.collapse_fraction
    for k in range(len(h.t)):
        if h.dmax[k] > upto:
            break
        d = joint_kinematics(model, h.pos[k], R[k])
        slip = np.minimum(np.abs(d["slip_i"]), np.abs(d["slip_e"])) * 1e3
        if slip.max() > slip_mm:
            return model.joints[int(np.argmax(slip))].name, float(h.t[k])
    return "", None


def reach_g(f: float, v_max: float) -> float:
    """Largest amplitude [g] of a one-cycle sine at ``f`` [Hz] a table of speed ``v_max`` [m/s] follows."""
    from specimens.constants import G

    return math.pi * f * v_max / G


def mode_case(case: dict) -> dict:
    """One threshold search of the map (a sweep case): see the module docstring."""
    from dem.common.joints import contact_fraction
    from dem.core.model import as_model
    from dem.core.settings import dynamics_settings
    from dem.experiments.shake.run import shake
    from dem.experiments.shake.thresholds import static_onset, threshold
    from specimens.catalogue import get_specimen
    from specimens.constants import G

    t0 = time.perf_counter()
    sp = get_specimen(case["id"])
    contact = contact_fraction(case["contact"], sp.arch)
    model = as_model(sp, config="glued", contact=contact)
    st = dynamics_settings(mu_base=case["mu_base"], restitution=case["restitution"])
    f = case["freq"]
    motion_fn = partial(servo_motion, v_max=case["table_speed"], tau=case["tau"])
    lam = static_onset(model, st)
    top = case["scan_over"] * reach_g(f, case["reach_speed"])
    out = {"lambda": lam, "contact_fraction": contact, "scan_top_g": top, "amplitude_g": None, "mode": "none",
           "phase": "", "joint": "", "t_slip_s": math.nan, "slip_half": "", "n_sims": 0, "bands": ""}
    if lam >= top:
        out["wall_s"] = time.perf_counter() - t0
        return out
    th = threshold(model, f, st, a_min_g=lam, a_max_g=top, workers=1, motion_fn=motion_fn)
    out.update(n_sims=th.n_sims, bands=" ".join(f"{b['outcome'][0].upper()}{b['from_g']:.3f}" for b in th.bands))
    if th.amplitude_g is not None:
        r = shake(model, motion_fn(th.amplitude_g * G, f), st, friction_work=False)
        joint, t_slip = first_slip(model, r, case["slip_mm"])
        half = "" if t_slip is None else ("first" if t_slip <= 0.5 / f else "second" if t_slip <= 1 / f else "after")
        out.update(amplitude_g=th.amplitude_g, mode=th.mode, phase=th.phase or "", joint=joint,
                   within_reach=bool(th.amplitude_g <= reach_g(f, case["reach_speed"]) * (1 + 1e-9)),
                   t_slip_s=math.nan if t_slip is None else t_slip, slip_half=half,
                   slid=" ".join(j.joint for j in r.sim.joints if "slide" in j.state))
    out["wall_s"] = time.perf_counter() - t0
    return out


def make_case(sid: str, f: float, a: argparse.Namespace, **over) -> dict:
    c = {"id": sid, "freq": float(f), "table_speed": a.table_speed, "tau": a.tau, "mu_base": a.mu_base,
         "contact": a.contact, "restitution": a.restitution, "scan_over": a.scan_over, "reach_speed": a.reach_speed,
         "slip_mm": SLIP_MM}
    c.update(over)
    if c["table_speed"] is None:
        c["tau"] = None
    return c


COLUMNS = ("label", "id", "freq", "amplitude_g", "within_reach", "mode", "phase", "joint", "t_slip_s", "slip_half", "slid",
           "lambda", "scan_top_g", "bands", "n_sims", "wall_s", "table_speed", "tau", "mu_base", "contact",
           "restitution")


def rows_of(study, cases: list[dict], labels: list[str]) -> list[dict]:
    """One row per case asked; a case the study file does not hold reads "not run"."""
    from dem.studies.sweep import case_key

    stored = study.by_key
    rows = []
    for lab, case in zip(labels, cases):
        rec = stored.get(case_key(case))
        got = {"mode": "not run"} if rec is None else (
            {k: rec.results.get(k) for k in COLUMNS if k in rec.results} if rec.ok else {"mode": "failed"})
        row = {"label": lab, **case, **got}
        rows.append({k: row.get(k, "") for k in COLUMNS})
    return rows


def write_csv(rows: list[dict], path: Path) -> None:
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4f}" if isinstance(v, float) and math.isfinite(v) else ("" if v is None else v))
                        for k, v in r.items()})


MODE_COLOURS = {"rocking": "#4c78a8", "mixed": "#f58518", "sliding": "#e45756", "none": "#e8e8e8",
                "failed": "#000000", "not run": "#ffffff"}


def _order(sid: str) -> tuple[str, float]:
    """Catalogue ids by thickness, then shape: Sh02 is 0.2, Sh1 is 1."""
    sh, sd = sid.split("-")
    sh = sh[2:]
    return sd, float(f"0.{sh[1:]}" if sh.startswith("0") else sh)


def figure(rows: list[dict], path: Path, title: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch

    ids = sorted({r["id"] for r in rows}, key=_order)
    freqs = sorted({r["freq"] for r in rows})
    cell = {(r["id"], r["freq"]): r for r in rows}
    fig, ax = plt.subplots(figsize=(1.3 * len(freqs) + 2.2, 0.42 * len(ids) + 1.6))
    for i, sid in enumerate(ids):
        for j, f in enumerate(freqs):
            r = cell.get((sid, f))
            mode = r["mode"] if r else "not run"
            ax.add_patch(plt.Rectangle((j, i), 1, 1, color=MODE_COLOURS.get(mode, "#999999"), ec="white"))
            if r and r["amplitude_g"] not in (None, ""):
                half = {"first": "1st", "second": "2nd", "after": "later"}.get(r["slip_half"], "")
                phase = {"before-first-rebound": "1st", "after-first-rebound": "2nd"}.get(r["phase"], "")
                above = "" if r.get("within_reach") in (True, "", None) else " *"
                ax.text(j + 0.5, i + 0.5, f"{float(r['amplitude_g']):.2f} g{above}, {phase}"
                        + (f"\nslip {r['joint']} {half}" if r["joint"] else ""), ha="center", va="center", fontsize=7)
            elif r:
                ax.text(j + 0.5, i + 0.5, "none" if mode == "none" else mode, ha="center", va="center", fontsize=7)
    ax.set_xlim(0, len(freqs))
    ax.set_ylim(0, len(ids))
    ax.set_xticks([j + 0.5 for j in range(len(freqs))], [f"{f:g} Hz" for f in freqs])
    ax.set_yticks([i + 0.5 for i in range(len(ids))], ids)
    ax.invert_yaxis()
    ax.set_title(title + "\ncell: first collapse, half cycle of the collapse (1st: before the first rebound); "
                 "the joint that slips first and its half cycle; * above the table's reach", fontsize=8)
    ax.legend(handles=[Patch(color=MODE_COLOURS[m], label=m) for m in ("rocking", "mixed", "sliding", "none")],
              loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8, title="first collapse", title_fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def main() -> None:
    from shake_mode_map import mode_case as case_fn  # by its module's name: the sweep's workers import it

    from dem.studies.sweep import run_study
    from specimens.catalogue import SPECIMEN_IDS

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
    a.contact = a.contact if a.contact == "calibrated" else float(a.contact)
    a.table_speed, a.tau = a.table_speed or None, a.tau or None
    freqs = [float(x) for x in a.freqs.split(",")]
    if a.ingredients:
        cases, labels = [], []
        for name, over in INGREDIENTS.items():
            base = make_case("Sh1-Sd015", 0.0, a, table_speed=None, tau=None, mu_base=1.0, contact=1.0,
                             restitution=0.0, scan_over=1.0, reach_speed=1.0)
            for f in freqs:
                cases.append({**base, "freq": f, **over, **({"scan_over": 1.5} if over.get("table_speed") else {})})
                labels.append(name)
        stem = "shake_ingredients"
    else:
        ids = SPECIMEN_IDS if a.specimens == "all" else [s.strip() for s in a.specimens.split(",")]
        cases = [make_case(s, f, a) for s in ids for f in freqs]
        labels = ["map"] * len(cases)
        stem = "shake_mode_map"
    out = Path(a.out) if a.out else RESULTS / f"{stem}.h5"
    out.parent.mkdir(parents=True, exist_ok=True)
    if a.report:
        from dem.studies.sweep import load_study

        study = load_study(out, cases)
    else:
        study = run_study(cases, case_fn, out, workers=a.workers, resume=a.resume)
    rows = rows_of(study, cases, labels)
    write_csv(rows, out.with_suffix(".csv"))
    for r in rows:
        amp = ("none" if r["mode"] == "none" else r["mode"]) if r["amplitude_g"] in (None, "") else \
            f"{float(r['amplitude_g']):.3f} g"
        print(f"{r['label']:<40} {r['id']:<11} {r['freq']:>4g} Hz  {amp:>9} {r['mode']:<8} {r['phase']:<21} "
              f"first slip {r['joint'] or '-'} {r['slip_half'] or ''}  (slid {r.get('slid') or '-'}; "
              f"scan to {float(r['scan_top_g'] or 0):.2f} g)")
    if not a.ingredients:
        speed = "ideal sine" if a.table_speed is None else f"table speed {a.table_speed:g} m/s" + (
            f", position loop {a.tau * 1e3:g} ms" if a.tau else ", velocity command")
        figure(rows, Path(a.png) if a.png else out.with_suffix(".png"),
               f"First collapse of a one-cycle sine, commanded up to {a.scan_over:g} x the table's reach "
               f"(glued, MuJoCo; {speed}, mu_base {a.mu_base:g}, contact {a.contact}, e {a.restitution:g})")
    print(f"written {out.with_suffix('.csv')}")


if __name__ == "__main__":
    main()
