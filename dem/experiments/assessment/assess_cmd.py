"""``archdem assess``: is this arch safe here? The codes' kinematic analysis of its mechanism, linear
and non-linear, against a site's elastic spectrum, with and without FRP strips
(docs/physics/assessment.md)."""
from __future__ import annotations

import argparse
import math

from analytic.codes.assessment import NOH_GUMBAD_FRP, assess, assess_monument, monument_site
from analytic.codes.frp import GAMMA_FRP, Strips, strengthened_collapse
from analytic.codes.kinematic import CONFIDENCE_FACTORS, Height
from analytic.motions.spectra import EC8_GROUND, NTC_SOIL, NTC_TOPOGRAPHY, ec8, ntc2018, read_spectrum
from dem.common.options import (
    add_arch_arguments,
    add_engine_argument,
    arch_from_args,
    default_of,
    discretisation_kwargs,
    parse_grid,
    print_json,
    workers_option,
)
from dem.core.settings import Settings
from specimens.blocks import DEFAULT_DENSITY
from specimens.constants import G
from specimens.errors import ArchdemInputError
from specimens.io import writable_file

CODES = ("ntc2018", "ec8")


def _spectrum(args: argparse.Namespace):
    if args.spectrum is None:
        raise ArchdemInputError("--spectrum ntc2018|ec8|FILE is needed (the site's elastic spectrum)")
    if args.spectrum not in CODES:
        if args.ag is not None or args.F0 is not None or args.Tc_star is not None or args.type is not None:
            raise ArchdemInputError("a spectrum file gives the whole spectrum: --ag, --F0, --Tc-star and --type "
                                    "belong to the codes' spectra")
        return read_spectrum(args.spectrum)
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


def _height(args: argparse.Namespace):
    given = [args.z_ratio, args.T1, args.floors]
    if all(v is None for v in given):
        if args.building_damping != default_of(Height, "damping1"):
            raise ArchdemInputError("--building-damping belongs to a mechanism at a height (--z-ratio, --T1, --floors)")
        return None
    if any(v is None for v in given):
        raise ArchdemInputError("a mechanism at a height needs --z-ratio, --T1 and --floors together")
    return Height(args.z_ratio, args.T1, args.floors, args.building_damping)


def _strips(args: argparse.Namespace):
    if args.frp is None:
        return None
    parts = args.frp.split(",")
    try:
        vals = [float(x) for x in parts]
    except ValueError:
        vals = []
    if len(vals) not in (3, 4) or not all(math.isfinite(v) for v in vals):
        raise ArchdemInputError(f"--frp takes STRENGTH_MPA,THICKNESS_MM,WIDTH_MM[,DESIGN_MPA], got {args.frp!r}")
    return Strips(vals[0] * 1e6, vals[1] * 1e-3, vals[2] * 1e-3, args.frp_face, vals[3] * 1e6 if len(vals) == 4 else None)


def _period_range(args: argparse.Namespace) -> tuple[float, float] | None:
    """``--match-periods LO,HI`` [s], or None (the library's default range)."""
    if args.match_periods is None:
        return None
    rng = parse_grid(args.match_periods, "--match-periods")
    if len(rng) != 2:
        raise ArchdemInputError(f"--match-periods takes LO,HI in s, got {args.match_periods!r}")
    return rng[0], rng[1]


def _run_monument(args: argparse.Namespace, monument) -> int:
    """A monument's configurations (:mod:`specimens.monuments`), unreinforced and with FRP strips,
    against its site (or the spectrum given)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.figure import hinges_text

    given = [k for k in ("Ri", "Re", "e", "Sh", "Sd", "Rc", "width", "voussoirs", "density", "pier_height", "contact",
                         "records", "report", "z_ratio") if getattr(args, k, None) is not None]
    if given:
        raise ArchdemInputError(f"{monument.name} is assessed as reconstructed (its own geometry, at ground level, "
                                f"no records or report): --{given[0].replace('_', '-')} does not apply")
    site = monument_site() if args.spectrum is None else _spectrum(args)
    strips = _strips(args) or Strips(*NOH_GUMBAD_FRP, face=args.frp_face)
    rows = assess_monument(monument, site, strips, args.FC, args.q, args.limit_state)
    out = {"id": monument.name, "source": monument.source, "arch": {"e": monument.arch.e, "t": monument.arch.t,
           "Rp": monument.arch.Rp, "width": monument.arch.width, "span": monument.arch.span,
           "rise": monument.arch.rise},
           "configurations": {k: (None if v is None else vars(v)) for k, v in monument.configurations.items()},
           "density": monument.density, "spectrum": site.describe(), "strips": strips.describe(), "rows": rows}
    if args.json:
        print_json(out)
        return 0
    print(f"{monument.name}: {site.describe()['code']} site, PGA {site.pga:.3g} m/s^2 ({site.pga / G:.3f} g); "
          f"FRP {strips.describe()['strength_MPa']:g} MPa x {strips.thickness * 1e3:g} mm x {strips.width * 1e3:g} mm "
          f"on the {strips.face} (design force {strips.force / 1e3:.3g} kN)")
    print(f"  {'configuration':18s} {'FRP':4s} {'lambda':>7s} {'e*':>6s} {'a0* [g]':>8s} {'d0* [mm]':>9s} "
          f"{'SI lin':>7s} {'SI disp':>7s}  hinges")
    for r in rows:
        lin = r["safety_index_linear"]
        print(f"  {r['configuration']:18s} {'yes' if r['frp'] else 'no':4s} {r['lambda']:7.4f} {r['e_star']:6.3f} "
              f"{r['a0_star'] / G:8.4f} {r['d0_star'] * 1e3:9.4g} {'' if lin is None else f'{lin:7.2f}'} "
              f"{r['safety_index_displacement']:7.2f}  {hinges_text(r['hinges'])}")
    return 0


def _print(title: str, hinges: list[dict], res) -> None:
    d = res.describe()
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.figure import hinges_text

    print(f"  {title}: hinges at {hinges_text(hinges)}")
    print(f"    alpha0 = {d['alpha0']:.4f}   M* = {d['M_star']:.4g} kg   e* = {d['e_star']:.3f}   "
          f"a0* = {d['a0_star'] / G:.4f} g (FC {d['FC']:g})   d0* = {d['d0_star'] * 1e3:.4g} mm")
    for c in d["checks"]:
        what = (f"linear, q = {c['q']:g}" if c["kind"] == "linear"
                else f"displacement, d_u* = {c['d_u_star'] * 1e3:.4g} mm vs demand {c['demand_displacement'] * 1e3:.4g} mm "
                     f"at T = {c['period']:.3f} s")
        print(f"    {c['limit_state']} {what} ({c['where']}): capacity ag {c['capacity_ag'] / G:.3f} g vs "
              f"{c['demand_ag'] / G:.3f} g -> safety index {c['safety_index']:.2f} "
              f"({'verified' if c['verified'] else 'NOT verified'})")


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.run import assess_with_records
    from specimens.monuments import MONUMENTS

    if args.id in MONUMENTS:
        return _run_monument(args, MONUMENTS[args.id])
    label, arch = arch_from_args(args)
    site = _spectrum(args)
    height = _height(args)
    strips = _strips(args)
    if args.report is not None:
        if not args.report.lower().endswith(".html"):
            raise ArchdemInputError(f"--report must end in .html, got {args.report!r}")
        writable_file(args.report, overwrite=False)
    if not args.records and (args.match_periods is not None or args.workers is not None):
        raise ArchdemInputError("--match-periods and --workers belong to --records")
    a = assess_with_records(arch, args.records or (), site, FC=args.FC, q=args.q, limit_state=args.limit_state,
                            height=height, period_range=_period_range(args), settings=Settings(engine=args.engine),
                            workers=args.workers, **discretisation_kwargs(args, arch))
    mech, res = a.mechanism, a.assessment
    out = {"id": label, "spectrum": site.describe(), "height": None if height is None else vars(height),
           "mechanism": mech.summary(), **res.describe()}
    frp = None
    if strips is not None:
        kw = discretisation_kwargs(args, arch)
        sc = strengthened_collapse(arch, strips, kw.get("density", DEFAULT_DENSITY), kw.get("piers"))
        frp = assess(sc.mechanism, site, args.FC, args.q, args.limit_state, height, alpha0=sc.lam,
                     extra_force=sc.strip_force)
        out["frp"] = {"strips": strips.describe(), "lambda": sc.lam, "mechanism": sc.mechanism.summary(),
                      "hinges": sc.mechanism.summary()["hinges"], **frp.describe()}
    if a.records is not None:
        out["records"] = a.records.describe()
    if args.report is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.figure import write_report

        write_report(args.report, label, site, mech, res, out, frp, out.get("frp"))
        out["report"] = args.report
    if args.json:
        print_json(out)
        return 0
    where = "ground level" if height is None else f"z/H = {height.z_ratio:g} of a {height.floors}-floor building"
    print(f"{label}: {site.describe()['code']} site, ag = {site.ag / G:.3f} g, PGA = {site.pga / G:.3f} g; "
          f"{args.limit_state.upper()}, mechanism at {where}")
    _print(f"unreinforced ({mech.label})", out["mechanism"].get("hinges", []), res)
    if frp is not None:
        _print(f"with FRP strips on the {strips.face} (T = {strips.force / 1e3:.3g} kN)", out["frp"]["hinges"], frp)
    if "records" in out:
        rec = out["records"]
        print(f"  records matched over {rec['period_range'][0]:.3g}-{rec['period_range'][1]:.3g} s, DEM "
              f"({rec['engine']}, unreinforced):")
        for m, r in zip(rec["matched"], rec["runs"]):
            print(f"    {m['record'][:48]:48s} x{m['scale']:.3g} (misfit {m['misfit_mean_ln']:.2f}): "
                  f"{'COLLAPSE' if r['collapsed'] else 'stands'}, peak d* {r['peak_d_star'] * 1e3:.3g} mm")
        v = rec["verdict"]
        print(f"    mean peak d* {v['mean_peak_d_star'] * 1e3:.3g} mm vs d_u* {v['du_star'] * 1e3:.3g} mm, "
              f"{v['n_reach_d0']} of {v['n_records']} reach d0* -> {'verified' if v['verified'] else 'NOT verified'}"
              f" (code check: {'verified' if res.verified else 'NOT verified'})")
    if args.report is not None:
        print(f"  report: {args.report}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("assess", help="code-based check: kinematic analysis (linear and non-linear) of the arch's "
                                      "mechanism against a site spectrum, with or without FRP strips",
                       description=__doc__.splitlines()[0])
    add_arch_arguments(p)
    p.add_argument("--spectrum", default=None, metavar="ntc2018|ec8|FILE",
                   help="the code's elastic spectrum, or a file of period [s] and Se [g] at 5 %% damping (a monument "
                        "such as noh-gumbad: its site's by default)")
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
                   help=f"damping ratio of the site spectrum [%%] (default {default_of(ntc2018, 'damping'):g})")
    ls = default_of(assess, "limit_state")
    p.add_argument("--limit-state", default=ls, choices=("SLV", "SLC", "slv", "slc"),
                   help=f"the limit state whose hazard the spectrum is: SLV (linear and displacement checks) or SLC "
                        f"(displacement check) (default {ls})")
    p.add_argument("--FC", type=float, default=default_of(assess, "FC"),
                   help=f"confidence factor of the knowledge level (LC1 {CONFIDENCE_FACTORS['LC1']:g}, "
                        f"LC2 {CONFIDENCE_FACTORS['LC2']:g}, LC3 {CONFIDENCE_FACTORS['LC3']:g}; "
                        f"default {default_of(assess, 'FC'):g})")
    q = default_of(assess, "q")
    p.add_argument("--q", type=float, default=q, help=f"behaviour factor of the linear check (default {q:g})")
    p.add_argument("--z-ratio", type=float, default=None, help="mechanism at a height: z/H in the building (0, 1]")
    p.add_argument("--T1", type=float, default=None, help="mechanism at a height: the building's first period [s]")
    p.add_argument("--floors", type=int, default=None, help="mechanism at a height: the building's number of floors")
    bd = default_of(Height, "damping1")
    p.add_argument("--building-damping", type=float, default=bd,
                   help=f"mechanism at a height: the building's first-mode damping [%%] (default {bd:g})")
    p.add_argument("--frp", default=None, metavar="STRENGTH_MPA,THICKNESS_MM,WIDTH_MM[,DESIGN_MPA]",
                   help=f"FRP strips along the ring: ultimate strength, equivalent thickness, total width, and the "
                        f"design (debonding) strength (default strength / {GAMMA_FRP:g})")
    p.add_argument("--frp-face", default="extrados", choices=("extrados", "intrados"),
                   help="the ring face the strips are bonded to (default extrados)")
    p.add_argument("--records", nargs="+", default=None, metavar="FILE",
                   help="records (.AT2, .smc, ESM, CSV) matched to the site spectrum and shaken on the DEM")
    p.add_argument("--match-periods", default=None, metavar="LO,HI",
                   help="period range [s] of the records' match (default 0.2-2 x the limit state's period)")
    add_engine_argument(p)
    p.add_argument("--workers", type=workers_option, default=None,
                   help="processes for the record runs (default: all cores, at most one per record)")
    p.add_argument("--report", default=None, metavar="FILE.html", help="write a one-page assessment with its figures "
                                                                       "(never overwrites)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=_run)
