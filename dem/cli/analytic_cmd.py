"""``archdem analytic``: limit analysis of one arch (continuous, discrete, LP, two-bar) or figures; of a
drawing's blocks (``--geometry``), the static LP with its hinges and mu*. ``--friction non-associative``
adds the least multiplier with Coulomb friction without dilatancy."""
from __future__ import annotations

import argparse
import dataclasses

from analytic.limit.analysis import FRICTION_LAWS, TERMS, ArchAnalysisSpec, run_drawing
from analytic.limit.analysis import run as run_analysis
from analytic.limit.summary import analyse
from dem.common.options import add_options, arch_request, default_of, option_used, print_json, writable_dir
from dem.common.request import density_text
from specimens.blocks import discretise
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from specimens.drawn import DrawnAssembly


def register(sub) -> None:
    p = sub.add_parser("analytic", help="limit analysis: continuous, discrete (enumeration and LP), two-bar; "
                                        "a drawing's static LP (--geometry)",
                       description=" ".join(line.strip() for line in __doc__.split("\n\n")[0].splitlines()),
                       # raw: the terms' table keeps its lines
                       epilog=TERMS, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_options(p, "analytic")
    p.add_argument("--effective-thickness", type=float, default=default_of(analyse, "effective_thickness"),
                   help="continuous analysis of the thinner ring: fraction of t kept about Rp, its "
                        "weight included (unlike --contact, which keeps the full weight) "
                        f"(default {default_of(analyse, 'effective_thickness'):g})")
    p.add_argument("--min-spacing", type=float, default=default_of(analyse, "min_spacing"),
                   help=f"least hinge spacing [rad] (continuous; default {default_of(analyse, 'min_spacing'):g})")
    # default None (the associative LP alone): a choice of what to solve, not a physical default
    p.add_argument("--friction", choices=FRICTION_LAWS, default=None,
                   help="associative (default): the LP's sliding joints dilate (an upper bound); "
                        "non-associative: also the least multiplier without dilatancy at the same frictions "
                        "(a mixed-integer program, about 1 s for a catalogue arch)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.plot is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.limit.figures import catalogue_figures

        files = [str(f) for f in catalogue_figures(writable_dir(args.plot))]
        if args.json:
            print_json({"figures": files})
        else:
            print(*files, sep="\n")
        return 0  # the table refuses --plot beside an arch
    req = arch_request(args)
    label, arch = req.structure()
    mu_j = REFERENCE_MU_JOINT if args.mu_joint is None else args.mu_joint
    mu_b = REFERENCE_MU_BASE if args.mu_base is None else args.mu_base
    non_associative = args.friction == "non-associative"
    if isinstance(arch, DrawnAssembly):  # the static LP of the drawn blocks, its hinges and mu*
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.friction_map.run import lp_mu_star

        for dest in ("effective_thickness", "min_spacing"):
            option_used(args, dest, False, "it belongs to the continuous ring of a two-centred arch, not to a drawing")
        asm = discretise(arch, **req.discretise_kwargs(arch))
        # mu* as the friction map defines it, at the same base friction
        res = run_drawing(label, asm, mu_j, mu_b, non_associative, lp_mu_star, density_text(asm))
    else:
        spec = ArchAnalysisSpec(label, arch, args.config, mu_j, mu_b, args.effective_thickness, args.min_spacing,
                                non_associative=non_associative)  # its checks before the cut's
        res = run_analysis(dataclasses.replace(spec, disc_kw=req.discretise_kwargs(arch)))
    if args.json:
        print_json(res.to_json())
        return 0
    print("\n".join(res.lines()))
    return res.exit_code  # 1 where it has no collapse multiplier
