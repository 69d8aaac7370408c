"""``archdem campaign``: the virtual test campaign (the main job of ``make demo``)."""
from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from dem.common.campaign import CampaignContext
from dem.common.joints import STUDY_JOINTS
from dem.common.options import add_options, contact_law_settings, default_of, given, option_name, writable_dir
from specimens.catalogue import select_specimens
from foundation.errors import ArchdemInputError


def _campaign(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.campaign.runner import all_steps, run_campaign

    _restore(args)
    specs = select_specimens(args.specimens)
    steps = None
    if args.steps is not None:  # checked before the output folder is made
        steps = [s.strip() for s in args.steps.split(",")]
        if not all(steps):
            raise ArchdemInputError(f"--steps: give step names separated by commas, got {args.steps!r}")
        unknown = [s for s in steps if s not in all_steps()]
        if unknown:
            raise ArchdemInputError(f"unknown campaign step(s) {', '.join(unknown)}; steps: {', '.join(all_steps())}")
    for name in ("piers", "fragility", "drawing"):
        if getattr(args, name):
            # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
            from dem.campaign.runner import default_steps

            steps = (steps or default_steps()) + ([] if steps and name in steps else [name])
    if args.scheduler:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.studies.sweep import check_scheduler

        check_scheduler(args.scheduler)  # before the output folder is made
    # --joints table-5.1: each catalogue specimen its own (checked on the first: no --kn beside it, the engine)
    joints = STUDY_JOINTS if args.joints and contact_law_settings(args, specs[0].id) else (
        contact_law_settings(args, None) or None)
    out = writable_dir(args.out)
    ctx = CampaignContext(out=Path(out), specimens=specs, config=args.config, engine=args.engine,
                          dynamics_engine=args.dynamics_engine,
                          quick=args.quick, workers=args.workers, contact=args.contact, scheduler=args.scheduler,
                          joints=joints)
    t0 = time.perf_counter()
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.campaign.estimate import REFERENCE_SPEED, estimate, machine_speed
    from dem.campaign.runner import default_steps

    steps_run = steps or default_steps()
    if estimate(ctx, steps_run):  # simulator steps ahead: time this machine (about 1 s), then estimate
        speed = machine_speed(ctx.engine)
        est = estimate(ctx, steps_run, speed=speed)
        total = sum(e["wall_s"] for e in est.values())
        parts = "; ".join(f"{k}: {e['units']} {e['what']}" for k, e in est.items())
        print(f"{'quick' if ctx.quick else 'full'} campaign, {ctx.engine} (shakes {ctx.dynamics_engine}): {parts}; "
              "estimated "
              f"{_duration(total)} of simulation at this machine's {speed:.2f} s per simulated second "
              f"(the unit costs are for a machine reading {REFERENCE_SPEED[ctx.engine]:.2f}; steps already finished "
              f"in {out} are kept)", flush=True)
    manifest = run_campaign(ctx, steps)
    print(f"campaign finished in {time.perf_counter() - t0:.1f} s; results in {out}")
    report = manifest.get("report")
    if report:
        print(f"report: {report}")
    return 0


def _restore(args: argparse.Namespace) -> None:
    """A campaign folder resumes its campaign: the parameters of its ``campaign.json`` replace those not
    given by hand; one given with another value is refused in one line, before any simulation."""
    try:
        params = json.loads((Path(args.out) / "campaign.json").read_text()).get("parameters") or {}
    except (OSError, ValueError, AttributeError):
        return  # no campaign there yet (or no readable one: the runner says so)
    stored = {"specimens": params.get("specimens"), "config": params.get("config"), "engine": params.get("engine"),
              "dynamics_engine": params.get("dynamics_engine"),
              "quick": params.get("quick"), "contact": params.get("contact", 1.0)}
    if params.get("joints") == "table-5.1":
        stored["joints"] = "table-5.1"
    mine = given(args)
    for k, v in stored.items():
        if v is None:
            continue
        have = [s.id for s in select_specimens(args.specimens)] if k == "specimens" else getattr(args, k)
        if k in mine and have != v:
            raise ArchdemInputError(f"{option_name(k)} {args.specimens if k == 'specimens' else have} is not the "
                                    f"campaign's in {args.out} ({','.join(v) if k == 'specimens' else v}); give it "
                                    "without it, or choose another --out")
        setattr(args, k, ",".join(v) if k == "specimens" else v)


def _duration(seconds: float) -> str:
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"


def register(sub) -> None:
    p = sub.add_parser("campaign", help="run the virtual test campaign and write its report")
    p.add_argument("--specimens", default="all", help="all or a comma-separated list of ids")
    add_options(p, "campaign", out="runs/campaign", **{k: default_of(CampaignContext, k) for k in
                                                       ("config", "contact", "dynamics_engine")})
    p.add_argument("--quick", action="store_true", help="coarse version (a few minutes on 2 cores)")
    p.add_argument("--steps", default=None, help="comma-separated subset of steps (piers, fragility and drawing only "
                                                 "when named or with --piers / --fragility / --drawing)")
    p.add_argument("--fragility", action="store_true",
                   help="add the fragility study: ensembles under sine pulses (one specimen at 2 Hz when quick)")
    p.add_argument("--piers", action="store_true",
                   help="add the piers study: one arch on piers of growing height, limit analysis and DEM tilt")
    p.add_argument("--drawing", action="store_true",
                   help="add the drawing step: the shipped drawing of an arch on piers, read and run end to end")
    p.set_defaults(func=_campaign)
