"""Speed of the linkage dynamics (issue targets: one sine-pulse time history of a four-bar
< 50 ms; a failure domain of 40 frequencies with bands < 20 s on 2 cores).

Prints the timings and writes them to benchmarks/results/dynamics.json (atomically; a new
numbered file if it exists).
"""
from __future__ import annotations

import os
import platform
import statistics
import time

import numpy as np
from _common import report

from analytic.rocking.domain import failure_domain, make_input
from analytic.rocking.dynamics import simulate
from analytic.rocking.linkage import minimised_four_bar
from specimens.catalogue import get_specimen


def main() -> dict:
    arch = get_specimen("Sh06-Sd015").arch
    fb = minimised_four_bar(arch)
    a0 = abs(fb.onset)
    # one time history: median over amplitudes/frequencies that collapse and survive
    times, outcomes = [], []
    for f in (1.0, 2.0, 4.0, 8.0):
        for k in (1.2, 2.0, 4.0):
            motion = make_input("sine", k * a0, f, a0)
            t0 = time.perf_counter()
            r = simulate(fb, motion, record=False)
            times.append(time.perf_counter() - t0)
            outcomes.append(r.collapsed)
    workers = min(2, os.cpu_count() or 1)
    freqs = list(np.linspace(0.5, 20.0, 40))
    t0 = time.perf_counter()
    dom = failure_domain(fb, "sine", freqs, a_max_ratio=10.0, n_scan=24, tol=1e-3, workers=workers)
    t_dom = time.perf_counter() - t0
    runs = sum(c.n_runs for c in dom.columns)
    res = {
        "arch": "Sh06-Sd015 (minimised four-bar)",
        "time_history_median_s": statistics.median(times), "time_history_max_s": max(times),
        "time_history_runs": len(times), "time_history_collapsed": int(sum(outcomes)),
        "target_time_history_s": 0.05,
        "domain_40_freqs_s": t_dom, "domain_workers": workers, "domain_simulations": runs,
        "domain_bands": sum(len(c.bands) for c in dom.columns), "target_domain_s": 20.0,
        "python": platform.python_version(), "machine": platform.machine(),
    }
    report("dynamics", res, digits=4)
    return res


if __name__ == "__main__":
    main()
