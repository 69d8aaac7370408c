"""Convergence of the shake threshold (least collapsing amplitude of a one-cycle sine, scan +
bisection to 1 %) in the engine's numerical settings: one specimen and frequency, a threshold
per ``engine:dt:iterations[:table-5.1]`` (the last: the study's compliant joints for the id; iterations are PyBullet's solver iterations; MuJoCo takes its own
from ``MuJoCoOptions`` and sub-steps at <= 0.25 ms, so its dt refines the step only below that).
Scan from the static onset lambda to ``--max-ratio`` x lambda (5, as ``bench_shake.py``; the
campaign scans to 4 x quick and 6 x full).
Writes benchmarks/results/shake_convergence_<id>_<f>Hz[-N].json (not part of ``make bench``:
a threshold costs 5-40 s on 2 cores at these settings).

    python benchmarks/shake_convergence.py [--id Sh06-Sd015] [--freq 6]
        [--settings pybullet:5e-4:100,pybullet:5e-4:200,pybullet:2.5e-4:200,mujoco:5e-4:100]
"""
from __future__ import annotations

import argparse
import os
import time

from _common import report


def main() -> None:
    from dem.core.model import as_model
    from dem.core.settings import Settings
    from dem.experiments.shake.run import ShakeProtocol
    from dem.experiments.shake.thresholds import static_onset, threshold
    from specimens.catalogue import STUDY_JOINTS

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--id", default="Sh06-Sd015")
    ap.add_argument("--freq", type=float, default=6.0)
    ap.add_argument("--config", default="glued")
    ap.add_argument("--settings", default="pybullet:5e-4:100,pybullet:5e-4:200,pybullet:5e-4:400,"
                    "pybullet:2.5e-4:100,pybullet:2.5e-4:200,mujoco:5e-4:100,mujoco:1.25e-4:100",
                    help="comma-separated engine:dt:iterations[:table-5.1]")
    ap.add_argument("--max-ratio", type=float, default=5.0, help="scan up to this x the static onset")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    a = ap.parse_args()
    model = as_model(a.id, config=a.config)
    st0 = Settings()
    lam = static_onset(model, st0)
    rows = []
    for spec in a.settings.split(","):
        eng, dt, it, *law = spec.split(":")
        st = st0.with_(engine=eng, dt=float(dt),
                       engine_options={"solver_iterations": int(it)} if eng == "pybullet" else None)
        if law == ["table-5.1"]:
            kn, _, beta = STUDY_JOINTS[a.id]
            st = st.with_(contact_law="compliant", kn=kn, damping_beta=beta)
        t0 = time.perf_counter()
        th = threshold(model, a.freq, st, ShakeProtocol(), a_min_g=lam, a_max_g=a.max_ratio * lam, tol=0.01, workers=a.workers)
        rows.append({"engine": eng, "contact_law": st.contact_law, "dt": float(dt), "solver_iterations": int(it), "amplitude_g": th.amplitude_g,
                     "bracket_g": list(th.bracket_g) if th.bracket_g else None, "n_sims": th.n_sims,
                     "survival_bands_above": th.survival_bands_above, "wall_s": time.perf_counter() - t0,
                     "load_avg_1min": os.getloadavg()[0]})
        got = f"{th.amplitude_g:.4f} g" if th.amplitude_g is not None else "no collapse in the scan"
        print(f"{spec}: {got} ({th.n_sims} sims, {rows[-1]['wall_s']:.1f} s)", flush=True)
    amps = [r["amplitude_g"] for r in rows if r["amplitude_g"] is not None]
    report(f"shake_convergence_{a.id}_{a.freq:g}Hz",
           {"id": a.id, "config": a.config, "freq_hz": a.freq, "static_lambda": lam, "workers": a.workers,
            "max_ratio": a.max_ratio,
            "max_over_min": max(amps) / min(amps) if amps else None, "rows": rows})


if __name__ == "__main__":
    main()
