"""``archdem domain``: the failure domain of a rocking linkage (analytic), or of the DEM arch over sine
frequencies (``--engine dem``) plotted over the four-bar and two-bar domains of the same specimen
(:class:`~dem.experiments.shake.domain_spec.DomainSpec` -> :func:`~dem.experiments.shake.domain_spec.run`)."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, answer, arch_request, contact_law_settings, figure_file
from dem.experiments.contract import add_spec_options, spec_from_args
from dem.experiments.shake.domain_spec import DomainSpec, run


def _run_domain(args: argparse.Namespace) -> int:
    req = arch_request(args)  # first: a drawing's configuration is DRAWN_CONFIG
    spec = spec_from_args(DomainSpec, args, request=req, engine=args.engine, config=args.config,
                          mu_joint=args.mu_joint, mu_base=args.mu_base, dt=args.dt, check=not args.no_check,
                          joints=contact_law_settings(args, args.id) or None, workers=args.workers,
                          scheduler=args.scheduler, plot=args.plot)
    if args.plot:
        figure_file(args.plot)
    res = run(spec, progress=not args.json)
    answer(args.json, res.to_json(), res.lines())
    return 0


def register(sub) -> None:
    p = sub.add_parser("domain", help="failure domain of a rocking linkage (collapse amplitude vs frequency/duration)",
                       description="Failure domain: amplitude scan and bisection at every frequency (sines) or "
                                   "duration (pulses), all collapse/survival bands.")
    add_options(p, "domain", config=DomainSpec.config)
    add_spec_options(p, DomainSpec)
    p.set_defaults(func=_run_domain)
