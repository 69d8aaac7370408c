"""The campaign's time estimate: what each simulator step will run, its unit costs, and this
machine's speed reading (:func:`machine_speed`) that scales them (docs/timings.md)."""
from __future__ import annotations

import os
import statistics
import time

from dem.common.campaign import CampaignContext
from dem.core.engines import get_engine
from dem.core.model import as_model, from_assembly
from dem.core.settings import DYNAMICS_ENGINE, Settings
from dem.experiments.friction_map.run import parse_mu_grid
from dem.experiments.friction_map.step_map import map_plan
from dem.experiments.record.step_record import record_plan
from dem.experiments.shake.domain import dem_failure_domain
from dem.experiments.shake.step_shake import SHAKE_CHECK, SHAKE_SEARCH, shake_plan
from dem.experiments.shake.thresholds import (
    REFERENCE_ENGINE,
    bisections,
    reference_needed,
    reference_unavailable,
    scan_grid,
)
from dem.experiments.tilt.step_lab import lab_plan
from dem.experiments.tilt.step_tilt import tilt_frictions
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from foundation.fields import default_of

# Core-seconds of one unit of work of each simulator step (PyBullet, 15 bodies, the defaults) on a
# machine whose machine_speed reads REFERENCE_SPEED, from timed campaign runs (docs/timings.md#4-unit-costs)
UNIT_CORE_S = {
    ("tilt", True): 9.1,  # one tilt test, bisected to 0.5 % from the LP bracket (3 simulations)
    ("tilt", False): 7.2,
    ("lab", True): 12.2,  # one tilt test of imperfect blocks (relieved joints: PyBullet's pads)
    ("lab", False): 12.2,  # ... the same protocol in the full campaign (measured on the quick one)
    ("map", True): 6.9,  # one map case (tilt to 2 %, LP-started bracket, 2.5 simulations)
    ("map", False): 6.1,
    ("shake", True): 30.3,  # one threshold (scan + bisection) at one frequency, tol 2 %
    ("shake", False): 34.1,  # ... ceiling 6 x lambda and tol 1 %
    ("record", True): 83.4,  # one scaled-record threshold, 3 s window
    ("record", False): 209.8,  # ... 7 s window, tol 1 %
}
# Cost of a threshold search per engine at the protocol's 0.5 ms step, over PyBullet's: the sums of the
# engines' shake study on one machine (docs/validation.md#19-three-engine-shake-study)
ENGINE_COST = {"pybullet": 1.0, "mujoco": 0.78, "lmgc90": 11.6}
DYNAMICS_DT_COST = 2.05  # DYNAMICS_ENGINE's searches at DYNAMICS_DT over its own at 0.5 ms (the same study)
# Wall seconds per simulated second that machine_speed reads on the machine of UNIT_CORE_S; the estimate
# scales the unit costs by this machine's reading over these (docs/timings.md#3-the-campaigns-time-estimate)
REFERENCE_SPEED = {"pybullet": 1.9, "mujoco": 1.25, "lmgc90": 2.85}  # lmgc90: 1.5 x PyBullet's, paired at rest
CALIBRATION_SPECIMEN = "Sh06-Sd015"
DYNAMIC_STEPS = ("shake", "record", "fragility")  # the steps that run CampaignContext.dynamics_engine
# The shake step's scan ratio: with its search (SHAKE_SEARCH) a threshold's runs, the unit its checks' runs
# are counted in (docs/timings.md#3-the-campaigns-time-estimate)
SHAKE_SCAN_RATIO = default_of(dem_failure_domain, "scan_ratio")


def machine_speed(engine: str = "pybullet", steps: int = 200, repeats: int = 3) -> float:
    """Wall seconds per simulated second of this machine for ``engine``: the glued
    CALIBRATION_SPECIMEN at rest with the default settings, the median of ``repeats`` runs of
    ``steps`` steps after the build (about 1.5 s of wall time with PyBullet on a 2-core machine)."""

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

    cores = max(1, ctx.workers or os.cpu_count() or 1)
    map_specs, mus, refine = map_plan(ctx)
    tested, predicted, n_real = lab_plan(ctx)
    shake_specs, freqs = shake_plan(ctx)
    half_runs, ref_runs = shake_check_runs(ctx, shake_specs, freqs)
    units = {
        "tilt": (len(ctx.specimens) * len(tilt_frictions(ctx)), "tilt tests"),
        "lab": (len(tested) * n_real + len(predicted), "tilt tests of imperfect blocks"),
        "map": (len(map_specs) * (len(parse_mu_grid(mus)) + refine), "map tilt cases"),
        "shake": (len(shake_specs) * len(freqs), f"sine-pulse thresholds and {half_runs + ref_runs} check runs"),
        "record": (len(record_plan(ctx)), "record thresholds"),
    }
    ref = REFERENCE_SPEED.get(ctx.engine)
    scale = speed / ref if speed is not None and ref else 1.0
    out = {}
    for name in (s for s in steps if s in units):
        n, what = units[name]
        engine = ctx.dynamics_engine if name in DYNAMIC_STEPS else ctx.engine
        dt_cost = DYNAMICS_DT_COST if name in DYNAMIC_STEPS and engine == DYNAMICS_ENGINE else 1.0
        # units (or, for thresholds, the simulations inside one unit) run in parallel on the cores
        unit = UNIT_CORE_S[(name, ctx.quick)] * ENGINE_COST.get(engine, 1.0) * dt_cost * scale
        out[name] = {"units": n, "what": what, "wall_s": n * unit / cores}
        if name == "shake":
            # a check run costs a search run, twice at half the step; LMGC90's at its own step and cost
            per_run = UNIT_CORE_S[(name, ctx.quick)] * scale / shake_search_runs(ctx.quick)
            check = (half_runs * 2 * unit / shake_search_runs(ctx.quick)
                     + ref_runs * per_run * ENGINE_COST[REFERENCE_ENGINE]) / cores
            out[name] |= {"check_runs": half_runs + ref_runs, "check_wall_s": check,
                          "wall_s": out[name]["wall_s"] + check}
    return out


def shake_search_runs(quick: bool) -> int:
    """Runs of one threshold search of the shake step: its whole scan and the bisection of one scan step."""
    top, tol = SHAKE_SEARCH[quick]
    return len(scan_grid(1.0, top, SHAKE_SCAN_RATIO)) + bisections(SHAKE_SCAN_RATIO, tol)


def shake_check_runs(ctx: CampaignContext, specs: list, freqs: tuple[float, ...]) -> tuple[int, int]:
    """The runs of the shake step's settled-or-range checks when they agree (the walks of a range not
    counted): two at half the step per threshold, and two on LMGC90 per threshold that asks it (the
    full campaign only: the quick one runs the half-step check alone, as the step asks)."""
    half = 2 * len(specs) * len(freqs)
    if SHAKE_CHECK[ctx.quick] == "half-step" or ctx.dynamics_engine == REFERENCE_ENGINE:
        return half, 0
    ref = 0
    for s in specs:
        st = ctx.dynamics_of(s)
        asked = [f for f in freqs if reference_needed(f, st)]
        if asked and not reference_unavailable(as_model(s.arch, config=ctx.config, contact=ctx.contact_of(s)), st):
            ref += 2 * len(asked)
    return half, ref
