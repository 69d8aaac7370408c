"""Speed and memory of the two engines, measured in the same run (ratios MuJoCo / PyBullet):

* wall time per simulated second at rest vs number of bodies (side-by-side copies of a glued
  15-body specimen: 15 ... ~1000 bodies), median of repeats, and the scaling exponent (least
  squares slope of log time vs log bodies) per engine;
* wall time of one hold-protocol tilt test per specimen per engine (reference friction);
* wall time of one shake threshold per specimen per engine (one-cycle sine, scan + bisection);
* peak resident memory of each measurement (each runs in a fresh process: ``ru_maxrss``).

The load average of the machine is recorded before, during (after each measurement) and after.
Writes benchmarks/results/engines.json and engines.md.

    python benchmarks/bench_engines.py [--repeats 3] [--copies 1,4,16,67] [--specimens all|IDs]
                                       [--tilt-repeats 3] [--skip-tilt] [--threshold-repeats 3]
                                       [--skip-threshold] [--threshold-freq 4] [--workers N]
                                       [--engines pybullet,mujoco]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

OUT = Path(__file__).resolve().parent / "results"
SPECIMEN = "Sh06-Sd015"


def _peak_rss_mb() -> float:
    import resource
    import sys

    r = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return r / 1024**2 if sys.platform == "darwin" else r / 1024  # bytes on macOS, KiB on Linux


def _step_time(engine: str, copies: int, seconds: float) -> dict:
    """Wall time per simulated second of ``copies`` side-by-side arches at rest (fresh process).

    Times the engine alone as the protocols drive it (gravity set, one step, repeated), after
    0.05 s of settling; the build time is reported separately.
    """
    import numpy as np

    from dem.core.engines import get_engine
    from dem.core.model import from_assembly, side_by_side
    from dem.core.settings import Settings
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    m = from_assembly(discretise(get_specimen(SPECIMEN).arch, config="glued"))
    if copies > 1:
        m = side_by_side(m, copies)
    s = Settings(engine=engine)
    g = np.array([0.0, -s.g, 0.0])
    eng = get_engine(engine)
    t0 = time.perf_counter()
    eng.build(m, s)
    t_build = time.perf_counter() - t0
    try:
        eng.step(int(round(0.05 / s.dt)))
        n = int(round(seconds / s.dt))
        t0 = time.perf_counter()
        for _ in range(n):
            eng.set_gravity(g)
            eng.step(1)
        wall = time.perf_counter() - t0
        pos, _ = eng.poses()
        drift = float(np.abs(pos - np.array([b.centroid for b in m.bodies])).max())
    finally:
        eng.close()
    return {"engine": engine, "bodies": m.n_bodies, "simulated_s": seconds, "wall_s": wall,
            "wall_per_sim_s": wall / seconds, "steps": n, "build_s": t_build, "max_centroid_drift_mm": 1e3 * drift,
            "peak_rss_mb": _peak_rss_mb(), "load_avg_1min": os.getloadavg()[0]}


def _tilt_time(engine: str, sid: str) -> dict:
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.compare_engines.run import engine_tilt
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    asm = discretise(get_specimen(sid).arch, config="glued")
    m = from_assembly(asm, name=sid)
    t0 = time.perf_counter()
    r = engine_tilt(m, Settings(engine=engine), assembly=asm)  # the default protocol: LP-started bracket
    return {"engine": engine, "id": sid, "lambda": r.lam, "mode": r.mode, "n_sims": r.n_sims,
            "wall_s": time.perf_counter() - t0, "peak_rss_mb": _peak_rss_mb(), "load_avg_1min": os.getloadavg()[0]}


def _threshold_time(engine: str, sid: str, freq: float, workers: int) -> dict:
    from _common import timed_threshold

    th, _, wall = timed_threshold(sid, freq, engine, workers)
    return {"engine": engine, "id": sid, "freq_hz": freq, "amplitude_g": th.amplitude_g, "n_sims": th.n_sims,
            "wall_s": wall, "workers": workers, "load_avg_1min": os.getloadavg()[0]}


def _fresh(fn, *args):
    """Run ``fn(*args)`` in a new single-worker process (clean memory peak, no shared state)."""
    with ProcessPoolExecutor(1) as ex:
        return ex.submit(fn, *args).result()


def _slope(x, y) -> float:
    import numpy as np

    return float(np.polyfit(np.log(x), np.log(y), 1)[0])


def main() -> None:
    from dem.core.provenance import engine_version
    from dem.core.settings import Settings
    from specimens.catalogue import select_specimens
    from foundation.io import atomic_path

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--copies", default="1,4,16,67", help="side-by-side copies of the 15-body arch")
    ap.add_argument("--sim-seconds", type=float, default=None,
                    help="simulated seconds per measurement (default: 1 s up to 60 bodies, then 0.2 s)")
    ap.add_argument("--specimens", default="all")
    ap.add_argument("--tilt-repeats", type=int, default=3)
    ap.add_argument("--skip-tilt", action="store_true")
    ap.add_argument("--threshold-repeats", type=int, default=3)
    ap.add_argument("--skip-threshold", action="store_true")
    ap.add_argument("--threshold-freq", type=float, default=4.0, help="frequency of the threshold runs [Hz]")
    ap.add_argument("--workers", type=int, default=None, help="processes of a threshold run (default: all cores)")
    ap.add_argument("--engines", default="pybullet,mujoco")
    ap.add_argument("--out", default=str(OUT / "engines.json"))
    a = ap.parse_args()
    engines = [e.strip() for e in a.engines.split(",") if e.strip()]
    copies = [int(c) for c in a.copies.split(",")]
    res: dict = {"specimen": SPECIMEN, "config": "glued", "engines": engines,
                 "versions": {e: engine_version(e) for e in engines}, "cpu_count": os.cpu_count(),
                 "load_avg_start": list(os.getloadavg()), "repeats": a.repeats, "tilt_repeats": a.tilt_repeats,
                 "threshold_repeats": a.threshold_repeats,
                 "protocol_dt_s": Settings().dt}
    if "mujoco" in engines:
        from dem.core.engines.mujoco_engine import DEFAULT_OPTIONS

        res["mujoco_internal_dt_s"] = DEFAULT_OPTIONS.max_dt
    t_start = time.perf_counter()
    # -- cost per simulated second vs bodies (engines interleaved so that load changes hit both)
    rows = []
    for c in copies:
        secs = a.sim_seconds or (1.0 if c <= 4 else 0.2)
        for _ in range(a.repeats):
            for e in engines:
                rows.append(_fresh(_step_time, e, c, secs))
                print(json.dumps(rows[-1]), flush=True)
    scaling: dict = {}
    for e in engines:
        pts = []
        for c in copies:
            rs = [r for r in rows if r["engine"] == e and r["bodies"] == 15 * c]
            pts.append({"bodies": rs[0]["bodies"], "median_wall_per_sim_s": statistics.median(r["wall_per_sim_s"] for r in rs),
                        "wall_per_step_ms": 1e3 * statistics.median(r["wall_s"] / r["steps"] for r in rs),
                        "peak_rss_mb": max(r["peak_rss_mb"] for r in rs),
                        "build_s": statistics.median(r["build_s"] for r in rs),
                        "max_centroid_drift_mm": max(r["max_centroid_drift_mm"] for r in rs)})
        slope = _slope([p["bodies"] for p in pts], [p["median_wall_per_sim_s"] for p in pts]) if len(pts) > 1 else None
        scaling[e] = {"points": pts, "exponent": slope}
    res["per_simulated_second"] = scaling
    if len(engines) == 2:
        e1, e2 = engines
        res["ratio_per_simulated_second"] = {
            f"{e2}/{e1}": [{"bodies": p1["bodies"], "ratio": p2["median_wall_per_sim_s"] / p1["median_wall_per_sim_s"]}
                           for p1, p2 in zip(scaling[e1]["points"], scaling[e2]["points"])]}
    res["raw_step"] = rows
    # -- tilt test per specimen
    if not a.skip_tilt:
        ids = [s.id for s in select_specimens(a.specimens)]
        trows = []
        for sid in ids:
            for _ in range(a.tilt_repeats):
                for e in engines:
                    trows.append(_fresh(_tilt_time, e, sid))
                    print(json.dumps(trows[-1]), flush=True)
        per = {}
        for sid in ids:
            per[sid] = {e: statistics.median(r["wall_s"] for r in trows if r["id"] == sid and r["engine"] == e)
                        for e in engines}
        res["tilt_wall_s"] = per
        if len(engines) == 2:
            e1, e2 = engines
            ratios = [per[s][e2] / per[s][e1] for s in ids]
            res["ratio_tilt"] = {f"{e2}/{e1}": {"per_specimen": dict(zip(ids, ratios)), "median": statistics.median(ratios),
                                                "geometric_mean": math.exp(statistics.fmean(math.log(r) for r in ratios))}}
        res["tilt_total_wall_s"] = {e: sum(per[s][e] for s in ids) for e in engines}
        res["raw_tilt"] = trows
    # -- shake threshold per specimen (each on all cores, as archdem threshold runs it)
    if not a.skip_threshold:
        ids = [s.id for s in select_specimens(a.specimens)]
        workers = a.workers or os.cpu_count() or 1
        hrows = []
        for sid in ids:
            for _ in range(a.threshold_repeats):
                for e in engines:
                    hrows.append(_threshold_time(e, sid, a.threshold_freq, workers))
                    print(json.dumps(hrows[-1]), flush=True)
        res["threshold_wall_s"] = {sid: {e: statistics.median(r["wall_s"] for r in hrows if r["id"] == sid and r["engine"] == e)
                                         for e in engines} for sid in ids}
        if len(engines) == 2:
            e1, e2 = engines
            ratios = [res["threshold_wall_s"][s][e2] / res["threshold_wall_s"][s][e1] for s in ids]
            res["ratio_threshold"] = {f"{e2}/{e1}": {"per_specimen": dict(zip(ids, ratios)),
                                                     "median": statistics.median(ratios)}}
        res["raw_threshold"] = hrows
    res["load_avg_end"] = list(os.getloadavg())
    res["wall_s"] = time.perf_counter() - t_start
    out = Path(a.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(out, overwrite=True) as tmp:
        Path(tmp).write_text(json.dumps(res, indent=2))
    with atomic_path(out.with_suffix(".md"), overwrite=True) as tmp:
        Path(tmp).write_text(markdown(res))
    print(f"wrote {out}")


def markdown(res: dict) -> str:
    """Markdown summary of a result dict of :func:`main`."""
    eng = res["engines"]
    lines = ["# Engine benchmark", "",
             f"versions {res['versions']}; load average start {res['load_avg_start'][0]:.2f}, "
             f"end {res['load_avg_end'][0]:.2f} on {res['cpu_count']} cores; medians of {res['repeats']} repeats; "
             f"protocol step {res.get('protocol_dt_s', 1e-3) * 1e3:g} ms (PyBullet's step; MuJoCo sub-steps it to "
             f"{res.get('mujoco_internal_dt_s', float('nan')) * 1e3:g} ms).", "",
             "## Wall time per simulated second at rest (" + res["specimen"] + " glued, side-by-side copies)", "",
             "| bodies | " + " | ".join(f"{e} [s/s] | {e} ms per protocol step | {e} peak MB" for e in eng) + " | ratio |",
             "|---" * (1 + 3 * len(eng) + 1) + "|"]
    sc = res["per_simulated_second"]
    ratio = list(res.get("ratio_per_simulated_second", {}).values())
    for k, p in enumerate(sc[eng[0]]["points"]):
        cells = []
        for e in eng:
            q = sc[e]["points"][k]
            cells.append(f"{q['median_wall_per_sim_s']:.3g} | {q['wall_per_step_ms']:.3g} | {q['peak_rss_mb']:.0f}")
        r = f"{ratio[0][k]['ratio']:.2f}" if ratio else ""
        lines.append(f"| {p['bodies']} | " + " | ".join(cells) + f" | {r} |")
    if sc[eng[0]]["exponent"] is not None:
        lines += ["", "Scaling exponent (log-log slope of cost vs bodies): "
                  + ", ".join(f"{e} {sc[e]['exponent']:.2f}" for e in eng)]
    lines.append("")
    if "tilt_wall_s" in res:
        lines += [f"## Tilt test (hold protocol, reference friction) wall time [s], median of {res.get('tilt_repeats', 1)}", "",
                  "| specimen | " + " | ".join(eng) + " | ratio |", "|---" * (len(eng) + 2) + "|"]
        rt = list(res.get("ratio_tilt", {}).values())
        for sid, v in res["tilt_wall_s"].items():
            r = f"{rt[0]['per_specimen'][sid]:.2f}" if rt else ""
            lines.append(f"| {sid} | " + " | ".join(f"{v[e]:.1f}" for e in eng) + f" | {r} |")
        if rt:
            lines += ["", f"Median tilt time ratio {list(res['ratio_tilt'])[0]}: {rt[0]['median']:.2f}"]
        lines += ["", "Total (campaign of the listed specimens, one process): "
                  + ", ".join(f"{e} {t:.0f} s" for e, t in res["tilt_total_wall_s"].items())]
    if "threshold_wall_s" in res:
        raw = res["raw_threshold"]
        lines += ["", f"## Shake threshold ({raw[0]['freq_hz']:g} Hz one-cycle sine, scan + bisection to 1 %, "
                  f"{raw[0]['workers']} processes) wall time [s] (median of {res.get('threshold_repeats', 1)}) and amplitude [g]", "",
                  "| specimen | " + " | ".join(f"{e} [s] | {e} [g] | {e} runs" for e in eng) + " | ratio |",
                  "|---" * (3 * len(eng) + 2) + "|"]
        rh = list(res.get("ratio_threshold", {}).values())
        for sid, v in res["threshold_wall_s"].items():
            rows = {r["engine"]: r for r in raw if r["id"] == sid}
            amp = lambda a: "none" if a is None else f"{a:.3f}"  # noqa: E731
            cells = [f"{v[e]:.1f} | {amp(rows[e]['amplitude_g'])} | {rows[e]['n_sims']}" for e in eng]
            r = f"{rh[0]['per_specimen'][sid]:.2f}" if rh else ""
            lines.append(f"| {sid} | " + " | ".join(cells) + f" | {r} |")
        if rh:
            lines += ["", f"Median threshold time ratio {list(res['ratio_threshold'])[0]}: {rh[0]['median']:.2f}"]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
