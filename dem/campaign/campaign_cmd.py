"""``archdem campaign``: the virtual test campaign (the main job of ``make demo``)."""
from __future__ import annotations

import argparse
import time

from dem.campaign.spec import RESUMED, campaign_steps, estimate_line, resumed
from dem.common.campaign import CampaignContext
from dem.common.joints import STUDY_JOINTS
from dem.common.options import add_options, contact_law_settings, default_of, given, writable_dir
from specimens.catalogue import select_specimens


def _campaign(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.campaign.runner import default_steps, run_campaign

    vars(args).update(resumed(args.out, {k: getattr(args, k) for k in RESUMED}, given(args)))
    specs = select_specimens(args.specimens)
    steps = campaign_steps(args.steps, tuple(n for n in ("piers", "fragility", "drawing") if getattr(args, n)))
    if args.scheduler:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.studies.sweep import check_scheduler

        check_scheduler(args.scheduler)  # before the output folder is made
    # --joints table-5.1: each catalogue specimen its own (checked on the first: no --kn beside it, the engine)
    joints = STUDY_JOINTS if args.joints and contact_law_settings(args, specs[0].id) else (
        contact_law_settings(args, None) or None)
    ctx = CampaignContext(out=writable_dir(args.out), specimens=specs, config=args.config, engine=args.engine,
                          dynamics_engine=args.dynamics_engine, quick=args.quick, workers=args.workers,
                          contact=args.contact, scheduler=args.scheduler, joints=joints)
    t0 = time.perf_counter()
    line = estimate_line(ctx, steps or default_steps())  # simulator steps ahead: this machine timed first
    if line:
        print(line, flush=True)
    manifest = run_campaign(ctx, steps)
    print(f"campaign finished in {time.perf_counter() - t0:.1f} s; results in {ctx.out}")
    if manifest.get("report"):
        print(f"report: {manifest['report']}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("campaign", help="run the virtual test campaign and write its report")
    p.add_argument("--specimens", default="all", help="all or a comma-separated list of ids")
    add_options(p, "campaign", out="runs/campaign", **{k: default_of(CampaignContext, k) for k in
                                                       ("config", "contact", "dynamics_engine")})
    p.add_argument("--quick", action="store_true", help="coarse version (a few minutes on 2 cores)")
    p.add_argument("--steps", default=None, help="comma-separated subset of steps (the optional piers, fragility, "
                                                 "drawing, settle and mode-map only when named, or with --piers / "
                                                 "--fragility / --drawing)")
    p.add_argument("--fragility", action="store_true",
                   help="add the fragility study: ensembles under sine pulses (one specimen at 2 Hz when quick)")
    p.add_argument("--piers", action="store_true",
                   help="add the piers study: one arch on piers of growing height, limit analysis and DEM tilt")
    p.add_argument("--drawing", action="store_true",
                   help="add the drawing step: the shipped drawing of an arch on piers, read and run end to end")
    p.set_defaults(func=_campaign)
