"""``archdem map``: friction-threshold map (DEM tilt lambda(mu), mode(mu), mu*) with analytic curves."""
from __future__ import annotations

import argparse

from dem.common.options import (
    add_options,
    answer,
    arch_request,
    can_make_dir,
    contact_law_settings,
    default_of,
    study_definition,
    study_stopped,
)
from dem.experiments.contract import add_spec_options, spec_from_args
from dem.experiments.friction_map.run import catalogue_map, run
from dem.experiments.friction_map.spec import MapOptions
from dem.studies.files import study_file


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import StudyInterrupted

    opts = spec_from_args(MapOptions, args, mu_base=args.mu_base, geometry=args.geometry is not None)
    req = arch_request(args)
    specs = opts.structures(req)
    # --joints table-5.1 on a map: of its one specimen (a study's settings are common to its cases)
    law = contact_law_settings(args, specs[0].id if len(specs) == 1 else "several specimens")
    path, resume = study_file(args.out, args.resume, "runs/map", f"map-{args.config}")
    if args.plot:
        can_make_dir(args.plot)
    spec = opts.map_spec(specs, args.config, args.engine, law, args.contact, req.piers)
    try:
        res = run(spec, path, workers=args.workers, scheduler=args.scheduler, resume=resume, progress=not args.json,
                  definition=study_definition(args))
    except (StudyInterrupted, KeyboardInterrupt) as exc:
        return study_stopped(path, exc)
    if args.plot:
        res.figures(args.plot)
    answer(args.json, res.to_json(), res.lines(path))
    return 0


def register(sub) -> None:
    p = sub.add_parser("map", help="friction-threshold map: DEM tilt lambda(mu), mode(mu) and mu* per specimen")
    add_spec_options(p, MapOptions)
    add_options(p, "map", **{k: default_of(catalogue_map, k) for k in ("config", "mu_base", "contact")})
    p.set_defaults(func=_run)
