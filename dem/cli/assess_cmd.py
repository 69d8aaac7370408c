"""``archdem assess``: is this arch safe here? The codes' linear kinematic analysis of its mechanism
against a site's elastic spectrum (docs/physics/assessment.md)."""
from __future__ import annotations

import argparse
import math

from dem.cli.common import (
    add_arch_arguments,
    arch_from_args,
    default_of,
    discretisation_kwargs,
    print_json,
)
from specimens.constants import G
from specimens.errors import ArchdemInputError


def _spectrum(args: argparse.Namespace):
    from analytic.spectra import ec8, ntc2018

    if args.ag is None:
        raise ArchdemInputError("--ag (peak ground acceleration on rock, in g) is needed")
    if not (math.isfinite(args.ag) and 0 < args.ag <= 3):
        raise ArchdemInputError(f"--ag must be in (0, 3] g, got {args.ag:g}")
    if args.spectrum == "ntc2018":
        if args.F0 is None or args.Tc_star is None:
            raise ArchdemInputError("the NTC 2018 spectrum needs --F0 and --Tc-star of the site")
        if args.type is not None:
            raise ArchdemInputError("--type is the EN 1998-1 spectrum type; NTC 2018 takes --F0 and --Tc-star")
        return ntc2018(args.ag * G, args.F0, args.Tc_star, args.soil, args.topography, args.damping)
    if args.F0 is not None or args.Tc_star is not None or args.topography != "T1":
        raise ArchdemInputError("--F0, --Tc-star and --topography belong to the NTC 2018 spectrum")
    return ec8(args.ag * G, args.soil, args.type or 1, args.damping)


def _mechanism(args: argparse.Namespace, arch):
    """The four-bar of the arch's governing mechanism (on piers: the discrete one through them)."""
    from analytic.linkage import governing_four_bar
    from specimens.blocks import DEFAULT_DENSITY

    kw = discretisation_kwargs(args, arch)
    return governing_four_bar(arch, kw.pop("density", DEFAULT_DENSITY), kw.pop("contact", 1.0), kw.pop("piers", None),
                              **kw)


def _run(args: argparse.Namespace) -> int:
    from analytic.kinematic import linear_kinematic

    label, arch = arch_from_args(args)
    site = _spectrum(args)
    mech = _mechanism(args, arch)
    lin = linear_kinematic(mech, args.FC)
    check = lin.ground_check(site.pga, args.q)
    out = {"id": label, "spectrum": site.describe(), "mechanism": mech.summary(), **lin.describe(),
           "a0_star_g": lin.a0_star / G, "check": {**check, "capacity_pga_g": check["capacity_pga"] / G,
                                                   "demand_pga_g": check["demand_pga"] / G}}
    if args.json:
        print_json(out)
        return 0
    hinges = " ".join(f"{h['joint']}:{h['face'][:3]}" for h in out["mechanism"].get("hinges", []))
    print(f"{label}: {site.name} site, ag S = {site.pga / G:.3f} g (soil {args.soil.upper()})")
    print(f"  mechanism  {mech.label}{'  ' + hinges if hinges else ''}")
    print(f"  alpha0 = {lin.alpha0:.4f}   M* = {lin.M_star:.4g} kg   e* = {lin.e_star:.3f}   "
          f"a0* = {lin.a0_star / G:.4f} g (FC {lin.FC:g})")
    print(f"  ground level, q = {check['q']:g}: capacity PGA {check['capacity_pga'] / G:.3f} g vs demand "
          f"{check['demand_pga'] / G:.3f} g -> safety index {check['safety_index']:.2f} "
          f"({'verified' if check['verified'] else 'NOT verified'})")
    return 0


def register(sub) -> None:
    from analytic.kinematic import CONFIDENCE_FACTORS, LinearKinematic, linear_kinematic
    from analytic.spectra import EC8_GROUND, NTC_SOIL, NTC_TOPOGRAPHY, ntc2018

    p = sub.add_parser("assess", help="code-based check: linear kinematic analysis of the arch's mechanism against "
                                      "a site spectrum (NTC 2018 or EN 1998-1)", description=__doc__.splitlines()[0])
    add_arch_arguments(p)
    p.add_argument("--spectrum", choices=("ntc2018", "ec8"), required=True, help="the code's elastic spectrum")
    p.add_argument("--ag", type=float, default=None, help="peak ground acceleration on rock [g] (NTC: of the return period)")
    p.add_argument("--F0", type=float, default=None, help="NTC 2018: the site's plateau amplification F0")
    p.add_argument("--Tc-star", dest="Tc_star", type=float, default=None, help="NTC 2018: the site's Tc* [s]")
    soil = default_of(ntc2018, "soil")
    p.add_argument("--soil", default=soil, choices=list(NTC_SOIL) + [s.lower() for s in NTC_SOIL],
                   help=f"soil category (NTC) or ground type (EC8), {'/'.join(EC8_GROUND[1])} (default {soil})")
    p.add_argument("--topography", default=default_of(ntc2018, "topography"), choices=list(NTC_TOPOGRAPHY),
                   help=f"NTC 2018 topographic category (default {default_of(ntc2018, 'topography')})")
    p.add_argument("--type", type=int, choices=(1, 2), default=None, help="EN 1998-1 spectrum type (default 1)")
    p.add_argument("--damping", type=float, default=default_of(ntc2018, "damping"),
                   help=f"damping ratio [%%] (default {default_of(ntc2018, 'damping'):g})")
    p.add_argument("--FC", type=float, default=default_of(linear_kinematic, "FC"),
                   help=f"confidence factor of the knowledge level (LC1 {CONFIDENCE_FACTORS['LC1']:g}, "
                        f"LC2 {CONFIDENCE_FACTORS['LC2']:g}, LC3 {CONFIDENCE_FACTORS['LC3']:g}; "
                        f"default {default_of(linear_kinematic, 'FC'):g})")
    q = default_of(LinearKinematic.ground_check, "q")
    p.add_argument("--q", type=float, default=q, help=f"behaviour factor (default {q:g})")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=_run)
