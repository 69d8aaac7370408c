"""``archdem fragility``: collapse probability and lognormal fragility curves from ensembles of
perturbed realisations, under sine pulses or a suite of records (docs/physics/fragility.md)."""
from __future__ import annotations

import argparse

from dem.common.options import (
    add_options,
    answer,
    arch_request,
    figure_file,
    option_used,
    settings_kwargs,
    study_definition,
    study_stopped,
)
from dem.experiments.contract import add_spec_options
from dem.experiments.fragility import inputs
from dem.experiments.fragility.run import FragilitySpec, make_cases
from dem.experiments.fragility.run import run as run_fragility
from dem.experiments.fragility.spec import FragilityOptions
from dem.studies.files import study_file
from foundation.errors import ArchdemInputError


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import StudyInterrupted, check_scheduler
    if args.realizations is None:
        raise ArchdemInputError("give --realizations N (perturbed realisations per stripe)")
    label, structure, model = inputs.nominal(arch_request(args), args.config, args.width, args.density)
    settings = inputs.study_settings(settings_kwargs(args), args.solver_iterations)
    pert = inputs.perturbation_mm(structure["kind"], args.edge_loss, args.edge_loss_sd, args.size_sd, args.friction_cov)
    groups, info = inputs.motion_groups(args.sine, args.amplitudes, args.records, args.im, args.stripes)
    make_cases(label, structure, settings, pert, groups, args.realizations, args.seed)  # checks n and the seed
    path, resume = study_file(args.out, args.resume, "runs/fragility", f"fragility-{label}-s{args.seed}")
    if args.plot:
        figure_file(args.plot)
    if args.scheduler:
        check_scheduler(args.scheduler)  # before the deterministic runs and the study file
    sines = info["input"] == "sine"
    option_used(args, "no_deterministic", sines, "the deterministic thresholds are the sines'")
    deterministic = {} if not sines or args.no_deterministic else inputs.deterministic_thresholds(
        model, settings, groups, info["freqs"], args.workers, args.scheduler, progress=not args.json)
    spec = FragilitySpec(label, structure, settings, pert, groups, args.realizations, args.seed, path,
                         workers=args.workers, scheduler=args.scheduler, resume=resume, progress=not args.json,
                         deterministic=deterministic, definition=study_definition(args), motions=info)
    try:
        res = run_fragility(spec)
    except (StudyInterrupted, KeyboardInterrupt) as exc:
        return study_stopped(path, exc)
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.fragility.file import write_tables

    write_tables(res, path)
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.fragility.figure import save_fragility_figure

        save_fragility_figure(res, args.plot)
    answer(args.json, res.describe(), res.lines(args.realizations))
    return 0


def register(sub) -> None:
    p = sub.add_parser("fragility", help="collapse probability and lognormal fragility from ensembles of perturbed "
                                         "realisations (sine pulses or a suite of records)",
                       description=__doc__.splitlines()[0])
    add_options(p, "fragility")
    add_spec_options(p, FragilityOptions)
    p.set_defaults(func=_run)
