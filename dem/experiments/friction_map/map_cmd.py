"""``archdem map``: friction-threshold map (DEM tilt lambda(mu), mode(mu), mu*) with analytic curves."""
from __future__ import annotations

import argparse
import math

from dem.common.joints import contact_fraction
from dem.common.options import (
    add_options,
    can_make_dir,
    contact_law_settings,
    default_of,
    geometry_from_args,
    option_used,
    piers_from_args,
    print_json,
    study_definition,
    study_path,
    study_stopped,
)
from dem.core.settings import Settings
from dem.experiments.friction_map.run import MapSpec, catalogue_map, parse_mu_grid, run
from dem.experiments.tilt import MAP_TILT_TOL
from specimens.catalogue import FULL_SCALE_SPANS, Specimen, full_scale_set, select_specimens
from foundation.errors import ArchdemInputError


def _specimens(args: argparse.Namespace) -> list:
    if args.geometry is not None:
        for dest in ("specimens", "full_scale"):
            option_used(args, dest, False, "--geometry gives the one structure of the map")
        label, asm = geometry_from_args(args)
        return [Specimen(label, asm)]
    if not args.full_scale:
        return select_specimens(args.specimens)
    pool = {s.id: s for s in full_scale_set()}
    if args.specimens.strip() == "all":
        return list(pool.values())
    out = []
    for sid in (s.strip() for s in args.specimens.split(",") if s.strip()):
        if sid not in pool:
            raise ArchdemInputError(f"unknown full-scale specimen {sid!r}; ids look like L10-Sh0.6-Sd0.15 "
                                    f"(spans 5/10/20, Sh 0/0.2/0.6/1, Sd 0.1/0.15/0.2/0.25)")
        out.append(pool[sid])
    if not out:
        raise ArchdemInputError("no specimens selected")
    return out


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import StudyInterrupted

    specs = _specimens(args)
    mus = parse_mu_grid(args.mu)

    Settings(mu_base=args.mu_base)  # the simulator's range of frictions
    option_used(args, "refine", len(mus) > 1 or args.refine == 0,
                "it bisects mu* between the values of a --mu grid; one value has none")
    if not (0 <= args.refine <= 20):
        raise ArchdemInputError(f"--refine must be in 0..20, got {args.refine}")
    if not (math.isfinite(args.tol) and 1e-3 <= args.tol <= 0.5):
        raise ArchdemInputError(f"--tol must be a relative tolerance in [0.001, 0.5], got {args.tol}")
    piers = piers_from_args(args)
    for s in specs if piers is not None else ():
        piers.check(s.arch)
    # --joints table-5.1 on a map: of its one specimen (a study's settings are common to its cases)
    law = contact_law_settings(args, specs[0].id if len(specs) == 1 else "several specimens")
    settings = ({"engine": args.engine} if args.engine != default_of(Settings, "engine") else {}) | law
    path, resume = study_path(args, "runs/map", f"map-{args.config}")
    if args.plot:
        can_make_dir(args.plot)
    try:
        spec = MapSpec(specs, args.config, mus, args.mu_base, refine=args.refine, protocol={"kind": "hold", "tol": args.tol},
                       settings=settings or None, contact={s.id: contact_fraction(args.contact, s.arch) for s in specs},
                       piers=piers)
        res = run(spec, path, workers=args.workers, scheduler=args.scheduler, resume=resume, progress=not args.json,
                  definition=study_definition(args))
    except (StudyInterrupted, KeyboardInterrupt) as exc:
        return study_stopped(path, exc)
    if args.plot:
        res.figures(args.plot)
    if args.json:
        print_json(res.to_json())
    else:
        print("\n".join(res.lines(path)))
    return 0


def register(sub) -> None:
    mus = default_of(catalogue_map, "mus")
    p = sub.add_parser("map", help="friction-threshold map: DEM tilt lambda(mu), mode(mu) and mu* per specimen")
    p.add_argument("--specimens", default="all", help="all or comma-separated ids (default all)")
    p.add_argument("--mu", default=mus, help="joint friction grid START:STOP:STEP or a,b,c "
                   f"(default {mus}, {len(parse_mu_grid(mus))} values)")
    p.add_argument("--refine", type=int, default=default_of(catalogue_map, "refine"),
                   help=f"bisection steps on mu* after the grid (default {default_of(catalogue_map, 'refine')})")
    p.add_argument("--tol", type=float, default=MAP_TILT_TOL,
                   help=f"relative lambda tolerance of each tilt (default {MAP_TILT_TOL:g})")
    p.add_argument("--full-scale", dest="full_scale", action="store_true",
                   help="use the full-scale parametric set (spans "
                        f"{'/'.join(f'{s:g}' for s in FULL_SCALE_SPANS)} m, "
                        f"{default_of(catalogue_map, 'n_voussoirs')} voussoirs per side)")
    add_options(p, "map", **{k: default_of(catalogue_map, k) for k in ("config", "mu_base", "contact")})
    p.set_defaults(func=_run)
