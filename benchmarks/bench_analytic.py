"""Speed of the limit analyses (issue targets: catalogue enumeration + LP < 2 s; continuous
minimisation of the 11 specimens < 10 s; the 48-arch full-scale set < 30 s; one core).

Prints the timings and writes them to benchmarks/results/analytic.json (atomically; a new
numbered file if it exists).
"""
from __future__ import annotations

import platform
import time

from _common import report

from analytic.limit.limit_continuous import continuous_collapse
from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
from specimens.blocks import discretise
from specimens.catalogue import CATALOGUE, full_scale_set
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT


def main() -> dict:
    asms = [discretise(s.arch, config=c) for s in CATALOGUE for c in ("free", "glued")]
    t0 = time.perf_counter()
    for a in asms:
        enumerate_mechanisms(a)
    t_enum = time.perf_counter() - t0
    t0 = time.perf_counter()
    for a in asms:
        solve_lp(a, REFERENCE_MU_JOINT, REFERENCE_MU_BASE)
    t_lp = time.perf_counter() - t0
    t0 = time.perf_counter()
    for s in CATALOGUE:
        continuous_collapse(s.arch)
    t_cont = time.perf_counter() - t0
    fs = full_scale_set()
    t0 = time.perf_counter()
    for s in fs:
        continuous_collapse(s.arch)
    t_fs = time.perf_counter() - t0
    res = {
        "catalogue_enumeration_s": t_enum, "catalogue_lp_s": t_lp, "catalogue_enum_plus_lp_s": t_enum + t_lp,
        "target_enum_plus_lp_s": 2.0,
        "catalogue_continuous_s": t_cont, "target_continuous_s": 10.0,
        "full_scale_continuous_s": t_fs, "n_full_scale": len(fs), "target_full_scale_s": 30.0,
        "python": platform.python_version(), "machine": platform.machine(),
    }
    report("analytic", res, digits=3)
    return res


if __name__ == "__main__":
    main()
