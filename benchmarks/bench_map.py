"""Speed of the friction map (DEM tilt sweeps): time per case, speed-up from 1 to 2 workers, the
catalogue map (glued, 13 friction values + bisection) measured on a subset of specimens and
extrapolated to the catalogue, and a scale check of mu* on full-scale spans.
Writes benchmarks/results/map.json.

    python benchmarks/bench_map.py [--specimens Sh06-Sd015,Sh1-Sd025] [--mu 0.3:1.5:0.1] [--refine 3]
                                   [--speedup-cases 4] [--scale-mu 0.3,0.4,0.5] [--scale-spans 5,10]
                                   [--scale-refine 2]
                                   [--skip-speedup] [--skip-map] [--skip-scale]
"""
from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from pathlib import Path

OUT = Path(__file__).resolve().parent / "results"


def _speedup(sid: str, mus: list[float]) -> dict:
    from dem.experiments.tilt.case import DEM_CASE, make_case
    from dem.studies.sweep import run_study
    from specimens.catalogue import get_specimen

    sp = get_specimen(sid)
    cases = [make_case(sid, sp.arch, "glued", m, 1.0) for m in mus]
    out = {"id": sid, "mu": mus, "cases": len(cases)}
    res = {}
    with tempfile.TemporaryDirectory() as d:
        for w in (1, 2):
            t0 = time.perf_counter()
            r = run_study(cases, DEM_CASE, Path(d, f"w{w}.h5"), workers=w, progress=False)
            out[f"wall_{w}_workers_s"] = time.perf_counter() - t0
            res[w] = [(c.results.get("lambda"), c.results.get("mode")) for c in r]
            out[f"case_wall_{w}_workers_s"] = [c.wall for c in r]
    out["speedup"] = out["wall_1_workers_s"] / out["wall_2_workers_s"]
    out["identical_1_vs_2_workers"] = res[1] == res[2]
    out["results"] = [{"mu": m, "lambda": a[0], "mode": a[1]} for m, a in zip(mus, res[1])]
    return out


def _map(specimens: str, mus: str, refine: int, workers: int) -> dict:
    from dem.experiments.friction_map.run import catalogue_map
    from specimens.catalogue import SPECIMEN_IDS

    with tempfile.TemporaryDirectory() as d:
        t0 = time.perf_counter()
        r = catalogue_map(specimens, "glued", mus, 1.0, Path(d, "map.h5"), workers=workers, progress=False,
                          refine=refine)
        wall = time.perf_counter() - t0
    n_spec = len(r.specimens)
    per_case = sum(r.case_wall_s) / max(1, len(r.case_wall_s))
    return {
        "specimens": [s.id for s in r.specimens], "grid": r.mus, "refine": refine, "workers": workers,
        "wall_s": wall, "n_cases": r.n_cases, "n_failed": r.n_failed, "bisection_rounds": r.rounds,
        "mean_case_wall_s": per_case,
        "extrapolated_catalogue_wall_s": {
            "value": wall * len(SPECIMEN_IDS) / n_spec,
            "how": f"EXTRAPOLATED, not measured: measured wall x {len(SPECIMEN_IDS)}/{n_spec} specimens "
                   f"(same grid, same refinement, {workers} workers)"},
        "summary": r.to_rows("summary"), "points": r.to_rows("points"),
    }


def _scale(spans: list[float], mus: list[float], sh: float, sd: float, workers: int, refine: int) -> dict:
    from dem.experiments.friction_map.run import catalogue_map
    from specimens.catalogue import Specimen
    from specimens.geometry import PointedArch

    specs = [Specimen(f"Rc0.2-Sh{sh:g}-Sd{sd:g}", PointedArch.from_ratios(sh, sd, 0.2, width=0.1))]
    specs += [Specimen(f"L{L:g}-Sh{sh:g}-Sd{sd:g}", PointedArch.from_ratios(sh, sd, L / 2, width=0.1 * L / 0.4))
              for L in spans]
    with tempfile.TemporaryDirectory() as d:
        t0 = time.perf_counter()
        r = catalogue_map(specs, "glued", mus, 1.0, Path(d, "scale.h5"), workers=workers, progress=False,
                          refine=refine)
        wall = time.perf_counter() - t0
    return {"Sh": sh, "Sd": sd, "mu": mus, "wall_s": wall,
            "note": "geometrically similar arches (width scaled too); protocol times, dt and record interval "
                    "scaled by sqrt(Rc / 0.2 m); span = nominal 2 Rc as in "
                    f"the full-scale set; {refine} bisection steps",
            "rows": [{"id": s.id, "Rc_m": s.arch.Rc, "span_m": s.arch.span, "mu_star_dem": s.mu_star_dem,
                      "bracket": [s.threshold.lo, s.threshold.hi], "mu_star_lp": s.analytic.mu_star_lp,
                      "points": [{"mu": p.mu, "lambda": p.lam, "mode": p.mode} for p in s.points]}
                     for s in r.specimens]}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--specimens", default="Sh06-Sd015,Sh1-Sd025")
    ap.add_argument("--mu", default="0.3:1.5:0.1")
    ap.add_argument("--refine", type=int, default=3)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--speedup-cases", type=int, default=4)
    ap.add_argument("--scale-mu", default="0.3,0.4,0.5")
    ap.add_argument("--scale-spans", default="5,10")
    ap.add_argument("--scale-refine", type=int, default=2)
    ap.add_argument("--skip-speedup", action="store_true")
    ap.add_argument("--skip-map", action="store_true")
    ap.add_argument("--skip-scale", action="store_true")
    a = ap.parse_args()
    path = OUT / "map.json"
    res: dict = json.loads(path.read_text()) if path.exists() else {}
    res["machine"] = {"cpu_count": os.cpu_count(), "load_avg_at_start": os.getloadavg(),
                      "note": "shared machine: other jobs were running; times are upper bounds"}

    def save() -> None:
        OUT.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(res, indent=2, default=float))

    if not a.skip_speedup:
        mus = [0.3, 0.5, 0.7, 0.9, 1.1, 1.3][: a.speedup_cases]
        res["speedup"] = _speedup("Sh06-Sd015", mus)
        save()
        print("speedup", res["speedup"]["speedup"], res["speedup"]["identical_1_vs_2_workers"], flush=True)
    if not a.skip_map:
        res["map"] = _map(a.specimens, a.mu, a.refine, a.workers)
        save()
        print("map", res["map"]["wall_s"], res["map"]["n_cases"], flush=True)
    if not a.skip_scale:
        res["scale"] = _scale([float(x) for x in a.scale_spans.split(",")],
                              [float(x) for x in a.scale_mu.split(",")], 0.6, 0.15, a.workers, a.scale_refine)
        save()
        print("scale", res["scale"]["wall_s"], flush=True)


if __name__ == "__main__":
    main()
