"""``archdem assess``: is this arch safe here? The codes' kinematic analysis of its mechanism, linear
and non-linear, against a site's elastic spectrum, with and without FRP strips
(docs/physics/assessment.md)."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, answer, arch_request, print_json
from dem.core.settings import dynamics_settings
from dem.experiments.assessment.spec import AssessOptions
from dem.experiments.contract import add_spec_options, spec_from_args
from foundation.errors import ArchdemInputError

#: What a monument assessed as reconstructed does not take: its geometry is the reconstruction's, and the
#: records need one configuration (assess_with_records).
NOT_FOR_A_MONUMENT = ("Ri", "Re", "e", "Sh", "Sd", "Rc", "width", "voussoirs", "density", "pier_height", "contact",
                      "records")


def _run_monument(args: argparse.Namespace, monument) -> int:
    """A monument's configurations (:mod:`specimens.monuments`), unreinforced, with FRP strips and with
    ``--tie``, against its site (or the spectrum given), at ground level or at ``--z-ratio``."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.run import run

    given = [k for k in NOT_FOR_A_MONUMENT if getattr(args, k, None) is not None]
    if given:
        raise ArchdemInputError(f"{monument.name} is assessed as reconstructed (its own geometry, no records): "
                                f"--{given[0].replace('_', '-')} does not apply")
    res = run(spec_from_args(AssessOptions, args, monument=monument).run_spec())
    out = res.describe()
    if args.report is not None:
        res.write_report(args.report, args.project or "-", args.engineer or "-")
        out["report"] = args.report
    answer(args.json, out, res.lines())
    return 0


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.run import run
    from specimens.monuments import MONUMENTS

    if args.id in MONUMENTS:
        return _run_monument(args, MONUMENTS[args.id])
    req = arch_request(args)
    label, arch = req.structure()
    opts = spec_from_args(AssessOptions, args)
    a = run(opts.run_spec(arch, label, dynamics_settings(engine=args.engine), args.workers,
                          **req.discretise_kwargs(arch)))
    out = a.describe()
    if args.report is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.report_pdf import command_inputs

        a.write_report(args.report, out, args.project or "-", args.engineer or "-",
                       command_inputs(args, arch, opts.strips))
        out["report"] = args.report
    if args.json:
        print_json(out)
        return 0
    print("\n".join(a.lines(out)))
    if args.report is not None:
        print(f"  report: {args.report}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("assess", help="code-based check: kinematic analysis (linear and non-linear) of the arch's "
                                      "mechanism against a site spectrum, with or without FRP strips",
                       description=__doc__.splitlines()[0],
                       epilog="Every option applies to a catalogue arch, a parametric arch and a drawing. The built-in "
                              "noh-gumbad has its own reconstructed geometry, piers, density and site (its spectrum by "
                              "default): the geometry options, --density, --contact and --records do not apply to it; "
                              "--spectrum, --sld-ag, --limit-state, --FC, --q, the height options, --frp and its "
                              "options, --tie (a row per configuration with the tie alone) and --json do. Each check "
                              "prints its demand and capacity as the clause compares them and the safety index "
                              "capacity / demand (docs/physics/assessment.md).")
    add_options(p, "assess")
    add_spec_options(p, AssessOptions)
    p.set_defaults(func=_run)
