"""Simulator steps of the campaign: tilt tests, friction map, shake thresholds, a recorded motion.

Each step writes its tables / figures into the step folder and returns the outputs the report
reads (see :mod:`dem.campaign.report`); findings are sentences computed from the results. The
simulations run through the sweep engine (:mod:`dem.studies.sweep`) into study files under
``OUT/studies/`` that live outside the step folders, so an interrupted campaign resumes
them without recomputing finished cases.
"""
from __future__ import annotations



from dem.campaign.context import CampaignContext
from dem.campaign.step_map import _map_plan
from dem.campaign.step_record import _record_plan
from dem.campaign.step_shake import _shake_plan
from dem.campaign.step_tilt import _tilt_frictions


# Core-seconds of one unit of work of each simulator step, PyBullet, 15 bodies, defaults dt 0.5 ms /
# 100 iterations, tilt levels ramped 0.5 s and held 1 s (wall of the step x 2 cores / units), on the
# scale of REFERENCE_SPEED: each measurement x 1.9 / the machine_speed of its machine.
# Quick values: a quick campaign run from a fresh clone (204 s at machine_speed 1.65: tilt 64.8 s for
# 11 tests, map 52.5 s for 10 cases, shake 31.8 s for 2 thresholds, record 36.2 s for 1). Full
# values: the full campaign run end to end from a fresh clone (1914 s at 1.65: tilt 164.6 s for 22
# tests, map 868.6 s for 176 cases, shake 588.8 s for 30 thresholds, record 273.3 s for 3; the
# former values estimated it at 34 min). The machine_speed reading tracks stepping only: the quick
# shake and record steps (untouched by the code changes in between) cost 1.3 and 1.6 x less on the
# 1.65 machine than on a 1.76 one, both brought to this scale.
# Since the hold's rest rule (TiltProtocol.rest_after): the quick tilt and map values from a quick
# run at machine_speed 1.40 (tilt 45.7 s for 11 tests, map 36.8 s for 10 cases; 13.6 and 12.1
# before), the full ones scaled by what the rule saved on the same machine: x 0.80 the tilt (the
# 44 tilt tests of benchmarks/validate_dem.py, 206 s against 258 s) and x 0.79 the map
# (benchmarks/bench_map.py --specimens all, 524 s against 661 s).
# The tilt values since the tilt test simulates the ends of its first bracket only when the bisection
# ends on one (TiltProtocol.probe_ends) and the quick step runs the tilt test's protocol too: the tilt
# step alone (--steps tilt), quick 32.5 s for 11 tests at machine_speed 1.24, full 53.2 s for 22
# tests at 1.27 (the quick step's 11 tests on 2 workers leave one idle for the last one). The map
# values since the map does the same: quick, the map step alone, 25.2 s and 22.9 s for 10 cases at
# about 1.33; full, benchmarks/bench_map.py --specimens all, 345 s for 167 cases at about 1.28.
# The shake values since a shake run ends once at rest after the motion (ShakeProtocol.rest_after):
# the shake step alone, quick 20.4 s for 2 thresholds at machine_speed 1.28, full 339.3 s for 30 at
# 1.26 (458 s without the rule, same machine).
UNIT_CORE_S = {
    ("tilt", True): 9.1,  # one tilt test, bisected to 0.5 % from the LP bracket (3 simulations)
    ("tilt", False): 7.2,
    ("map", True): 6.9,  # one map case (tilt to 2 %, LP-started bracket, 2.5 simulations)
    ("map", False): 6.1,
    ("shake", True): 30.3,  # one threshold (scan + bisection) at one frequency, tol 2 %
    ("shake", False): 34.1,  # ... ceiling 6 x lambda and tol 1 %
    ("record", True): 83.4,  # one scaled-record threshold, 3 s window
    ("record", False): 209.8,  # ... 7 s window, tol 1 %
}
ENGINE_COST = {"pybullet": 1.0, "mujoco": 0.7}
# Wall seconds per simulated second that :func:`machine_speed` reads on the machine of UNIT_CORE_S
# (5 calls on an idle 2-core machine: PyBullet 1.80-2.09, median 1.93; MuJoCo 1.15-1.31, median 1.24;
# another machine read 1.64-1.65, e.g. at the start of the quick run above). The estimate scales
# the unit costs by this machine's own reading over these, so it holds on a faster machine too.
REFERENCE_SPEED = {"pybullet": 1.9, "mujoco": 1.25}
CALIBRATION_SPECIMEN = "Sh06-Sd015"


def machine_speed(engine: str = "pybullet", steps: int = 200, repeats: int = 3) -> float:
    """Wall seconds per simulated second of this machine for ``engine``: the glued
    CALIBRATION_SPECIMEN at rest with the default settings, the median of ``repeats`` runs of
    ``steps`` steps after the build (about 1.5 s of wall time with PyBullet on a 2-core machine)."""
    import statistics
    import time

    from dem.core.engines import get_engine
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    settings = Settings(engine=engine)
    model = from_assembly(discretise(get_specimen(CALIBRATION_SPECIMEN).arch, config="glued"),
                          name=CALIBRATION_SPECIMEN)
    walls = []
    with get_engine(engine) as eng:
        eng.build(model, settings)
        eng.step(20)  # contacts found and warm-started before timing
        for _ in range(repeats):
            t0 = time.perf_counter()
            eng.step(steps)
            walls.append(time.perf_counter() - t0)
    return statistics.median(walls) / (steps * settings.dt)


def estimate(ctx: CampaignContext, steps: list[str], speed: float | None = None) -> dict[str, dict]:
    """Per simulator step in ``steps``: number of units (tilt tests, map cases, thresholds) and
    estimated wall time [s] on ``ctx.workers`` cores (all cores by default). ``speed``: this
    machine's :func:`machine_speed` for ``ctx.engine``; the unit costs are scaled by it over
    REFERENCE_SPEED (None: the reference machine's costs as they are)."""
    import os

    from dem.experiments.friction_map import parse_mu_grid

    cores = max(1, ctx.workers or os.cpu_count() or 1)
    map_specs, mus, refine = _map_plan(ctx)
    shake_specs, freqs = _shake_plan(ctx)
    units = {
        "tilt": (len(ctx.specimens) * len(_tilt_frictions(ctx)), "tilt tests"),
        "map": (len(map_specs) * (len(parse_mu_grid(mus)) + refine), "map tilt cases"),
        "shake": (len(shake_specs) * len(freqs), "sine-pulse thresholds"),
        "record": (len(_record_plan(ctx)), "record thresholds"),
    }
    ref = REFERENCE_SPEED.get(ctx.engine)
    scale = speed / ref if speed is not None and ref else 1.0
    out = {}
    for name in (s for s in steps if s in units):
        n, what = units[name]
        # units (or, for thresholds, the simulations inside one unit) run in parallel on the cores
        unit = UNIT_CORE_S[(name, ctx.quick)] * ENGINE_COST.get(ctx.engine, 1.0) * scale
        out[name] = {"units": n, "what": what, "wall_s": n * unit / cores}
    return out


