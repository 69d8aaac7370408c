"""``archdem assess``: is this arch safe here? The codes' kinematic analysis of its mechanism, linear
and non-linear, against a site's elastic spectrum, with and without FRP strips
(docs/physics/assessment.md)."""
from __future__ import annotations

import argparse
import math

from analytic.codes.assessment import assess, monument_site, monument_strips
from analytic.codes.frp import ETA_A, GAMMA_F, GAMMA_FD, MASONRY_TYPES, BondFactors, Masonry, Strips, masonry_type
from analytic.codes.kinematic import CONFIDENCE_FACTORS, Height
from analytic.limit.ties import Tie
from analytic.motions.spectra import EC8_GROUND, NTC_SOIL, NTC_TOPOGRAPHY, ec8, ntc2018, read_spectrum, rebuild
from dem.common.options import (
    add_options,
    arch_from_args,
    default_of,
    discretisation_kwargs,
    option_used,
    parse_grid,
    print_json,
)
from dem.core.settings import dynamics_settings
from specimens.constants import G
from foundation.errors import ArchdemInputError
from foundation.io import writable_file

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


#: The options of the guideline's bond factors (CNR-DT 200 R1/2013 §5.3): (dest, BondFactors field,
#: scale of the option's unit to SI, the option's unit, what the factor is).
BOND_OPTIONS = (("frp_kG", "k_G", 1e-3, "MM", "k_G, correction factor of the fracture energy, end debonding"),
                ("frp_kG2", "k_G2", 1e-3, "MM", "k_G2, correction factor of the fracture energy, intermediate "
                                                "debonding"),
                ("frp_su", "s_u", 1e-3, "MM", "s_u, ultimate slip of the bond law (f_bd = 2 Gamma_Fd / s_u)"),
                ("frp_gamma_rd", "gamma_Rd", 1.0, "FACTOR", "gamma_Rd, model factor of the optimal bond length"),
                ("frp_led_min", "l_ed_min", 1e-3, "MM", "the least optimal bond length l_ed"),
                ("frp_fmt_ratio", "fmt_ratio", 1.0, "RATIO", "f_mtm / f_mm, the masonry's tensile strength as a share "
                                                          "of its compressive one for a named masonry type"))


def _bond(args: argparse.Namespace, debonding: bool, named_masonry: bool, why: str) -> BondFactors:
    """The guideline's bond factors: those given by hand, the unverified defaults otherwise. Each is
    refused in one line where no debonding is designed (``why`` says what they belong to), and
    ``--frp-fmt-ratio`` where the masonry's tensile strength is given rather than taken from a type."""
    for dest, *_ in BOND_OPTIONS:
        option_used(args, dest, debonding, why)
    option_used(args, "frp_fmt_ratio", named_masonry, "--masonry FM_MPA,FMT_MPA gives the tensile strength; the "
                                                      "ratio belongs to a named masonry type")
    vals = {}
    for dest, field, scale, _, _ in BOND_OPTIONS:
        v = getattr(args, dest, None)
        if v is not None:
            vals[field] = v * scale
    return BondFactors.given(**vals)


def _named_masonry(args: argparse.Namespace) -> bool:
    return args.masonry is None or args.masonry in MASONRY_TYPES


def _masonry(args: argparse.Namespace, bond: BondFactors | None = None):
    """``--masonry FM_MPA,FMT_MPA`` or a named type (its values by the knowledge level of ``--FC``;
    its tensile strength by ``bond``'s ratio)."""
    if args.masonry is None:
        return None
    if args.masonry in MASONRY_TYPES:
        return masonry_type(args.masonry, args.FC, bond)
    try:
        vals = [float(x) for x in args.masonry.split(",")]
    except ValueError:
        vals = []
    if len(vals) != 2 or not all(math.isfinite(v) for v in vals):
        raise ArchdemInputError(f"--masonry takes FM_MPA,FMT_MPA or one of {', '.join(MASONRY_TYPES)}, "
                                f"got {args.masonry!r}")
    return Masonry(vals[0] * 1e6, vals[1] * 1e6, "given")


def _strip_options(args: argparse.Namespace) -> dict:
    """The strips' design options besides their description (modulus, fibre, exposure, application, masonry,
    bond factors)."""
    bond = _bond(args, args.masonry is not None, args.masonry in MASONRY_TYPES,
                 "the bond factors design debonding from the --masonry; without it the strips are designed "
                 "for rupture only")
    masonry = _masonry(args, bond)
    if args.frp_modulus is not None and not (math.isfinite(args.frp_modulus) and args.frp_modulus > 0):
        raise ArchdemInputError(f"--frp-modulus must be a positive number of GPa, got {args.frp_modulus:g}")
    if masonry is not None and args.frp_modulus is None:
        raise ArchdemInputError("--masonry needs --frp-modulus (the strips' E_f: debonding depends on it)")
    return {"modulus": None if args.frp_modulus is None else args.frp_modulus * 1e9, "fibre": args.frp_fibre,
            "exposure": args.frp_exposure, "application": args.frp_application, "masonry": masonry, "FC": args.FC,
            "bond": bond}


def _strips(args: argparse.Namespace):
    if args.frp is None:
        option_used(args, "frp_face", False, "it places the --frp strips")
        _bond(args, False, False, "it sets a bond factor of the --frp strips' debonding (with --masonry)")
        if args.masonry is not None or args.frp_modulus is not None:
            raise ArchdemInputError("--masonry and --frp-modulus belong to --frp (the strips they design)")
        return None
    parts = args.frp.split(",")
    try:
        vals = [float(x) for x in parts]
    except ValueError:
        vals = []
    if len(vals) not in (3, 4) or not all(math.isfinite(v) for v in vals):
        raise ArchdemInputError(f"--frp takes STRENGTH_MPA,THICKNESS_MM,WIDTH_MM[,DESIGN_MPA], got {args.frp!r}")
    return Strips(vals[0] * 1e6, vals[1] * 1e-3, vals[2] * 1e-3, args.frp_face, vals[3] * 1e6 if len(vals) == 4 else None,
                  **_strip_options(args))


def _tie(args: argparse.Namespace):
    """``--tie HEIGHT,AREA_MM2,FY_MPA[,PRESTRESS_KN]``."""
    if args.tie is None:
        return None
    try:
        vals = [float(x) for x in args.tie.split(",")]
    except ValueError:
        vals = []
    if len(vals) not in (3, 4) or not all(math.isfinite(v) for v in vals):
        raise ArchdemInputError(f"--tie takes HEIGHT_M,AREA_MM2,FY_MPA[,PRESTRESS_KN], got {args.tie!r}")
    return Tie(vals[0], vals[1] * 1e-6, vals[2] * 1e6, vals[3] * 1e3 if len(vals) == 4 else 0.0)


def _sld_site(args: argparse.Namespace, site):
    """The SLD hazard (``--sld-ag`` [g], and for NTC 2018 ``--sld-F0``, ``--sld-Tc-star``): the same site's
    spectrum at the SLD return period."""
    if args.sld_ag is None:
        if args.sld_F0 is not None or args.sld_Tc_star is not None:
            raise ArchdemInputError("--sld-F0 and --sld-Tc-star belong to --sld-ag")
        return None
    if args.limit_state.upper() == "SLD":
        raise ArchdemInputError("--sld-ag is the SLD hazard beside a life-safety one; with --limit-state SLD the "
                                "spectrum itself is the SLD hazard")
    if not (math.isfinite(args.sld_ag) and 0 < args.sld_ag * G <= site.ag):
        raise ArchdemInputError(f"--sld-ag must be in (0, the spectrum's ag = {site.ag / G:.3g}] g, got {args.sld_ag:g}")
    if args.sld_F0 is not None or args.sld_Tc_star is not None:
        if site.describe().get("code") != "NTC 2018":
            raise ArchdemInputError("--sld-F0 and --sld-Tc-star belong to the NTC 2018 spectrum")
        p = site.params
        return ntc2018(args.sld_ag * G, args.sld_F0 if args.sld_F0 is not None else p["F0"],
                       args.sld_Tc_star if args.sld_Tc_star is not None else p["Tc_star"], p["soil"], p["topography"],
                       p["damping"])
    return rebuild(site, ag=args.sld_ag * G)


def _period_range(args: argparse.Namespace) -> tuple[float, float] | None:
    """``--match-periods LO,HI`` [s], or None (the library's default range)."""
    if args.match_periods is None:
        return None
    rng = parse_grid(args.match_periods, "--match-periods")
    if len(rng) != 2:
        raise ArchdemInputError(f"--match-periods takes LO,HI in s, got {args.match_periods!r}")
    return rng[0], rng[1]


def _check_report(args: argparse.Namespace) -> None:
    """Refuse a ``--report`` that is neither HTML nor PDF or would overwrite a file, and a title-block option
    without a PDF report, in one line."""
    if args.report is not None:
        if not args.report.lower().endswith((".html", ".pdf")):
            raise ArchdemInputError(f"--report must end in .html or .pdf, got {args.report!r}")
        writable_file(args.report, overwrite=False)
    for dest in ("project", "engineer"):
        option_used(args, dest, (args.report or "").lower().endswith(".pdf"),
                    "it goes in the title block of a --report FILE.pdf")


def _run_monument(args: argparse.Namespace, monument) -> int:
    """A monument's configurations (:mod:`specimens.monuments`), unreinforced, with FRP strips and with
    ``--tie``, against its site (or the spectrum given), at ground level or at ``--z-ratio``."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.run import MonumentSpec, run

    # its geometry is the reconstruction's and the records need one configuration (assess_with_records)
    given = [k for k in ("Ri", "Re", "e", "Sh", "Sd", "Rc", "width", "voussoirs", "density", "pier_height", "contact",
                         "records") if getattr(args, k, None) is not None]
    if given:
        raise ArchdemInputError(f"{monument.name} is assessed as reconstructed (its own geometry, no records): "
                                f"--{given[0].replace('_', '-')} does not apply")
    site = monument_site() if args.spectrum is None else _spectrum(args)
    height = _height(args)
    tie = _tie(args)
    sld = _sld_site(args, site)
    if args.frp is not None:
        strips = _strips(args)
    else:
        if args.frp_modulus is not None:
            raise ArchdemInputError(f"{monument.name}'s strips are described by the study (E_f assumed): "
                                    f"--frp-modulus belongs to --frp")
        bond = _bond(args, True, _named_masonry(args), "")
        strips = monument_strips(args.FC, args.frp_face, _masonry(args, bond), bond)
    _check_report(args)  # before the work: a bad report path must not cost the assessment
    res = run(MonumentSpec(monument, strips, site, args.FC, args.q, args.limit_state, height, tie, sld))
    out = res.describe()
    if args.report is not None:
        res.write_report(args.report, args.project or "-", args.engineer or "-")
        out["report"] = args.report
    if args.json:
        print_json(out)
        return 0
    print("\n".join(res.lines()))
    return 0


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.run import AssessSpec, run
    from specimens.monuments import MONUMENTS

    option_used(args, "q", args.limit_state.upper() == "SLV", "it is the behaviour factor of the linear check, "
                                                               "which only --limit-state SLV has")
    for dest in ("frp_fibre", "frp_exposure", "frp_application"):
        option_used(args, dest, args.frp is not None, "it designs the --frp strips")
    if args.id in MONUMENTS:
        return _run_monument(args, MONUMENTS[args.id])
    label, arch = arch_from_args(args)
    site = _spectrum(args)
    height = _height(args)
    strips = _strips(args)
    tie = _tie(args)
    sld = _sld_site(args, site)
    _check_report(args)
    option_used(args, "match_periods", bool(args.records), "it belongs to --records")
    a = run(AssessSpec(arch, site, tuple(args.records or ()), FC=args.FC, q=args.q, limit_state=args.limit_state,
                       height=height, period_range=_period_range(args), settings=dynamics_settings(engine=args.engine),
                       workers=args.workers, strips=strips, tie=tie, sld_site=sld, label=label,
                       **discretisation_kwargs(args, arch)))
    out = a.describe()
    if args.report is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.report_pdf import command_inputs

        a.write_report(args.report, out, args.project or "-", args.engineer or "-", command_inputs(args, arch, strips))
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
    p.add_argument("--limit-state", default=ls, choices=("SLD", "SLV", "SLC", "sld", "slv", "slc"),
                   help=f"the limit state whose hazard the spectrum is: SLD (activation check, no q), SLV (linear and "
                        f"displacement checks) or SLC (displacement check) (default {ls})")
    p.add_argument("--sld-ag", type=float, default=None,
                   help="the SLD hazard's ag [g] (same site): adds the activation check (no q) beside SLV or SLC "
                        "(any arch, and noh-gumbad)")
    p.add_argument("--sld-F0", type=float, default=None, help="NTC 2018: F0 of the SLD hazard (default the spectrum's)")
    p.add_argument("--sld-Tc-star", dest="sld_Tc_star", type=float, default=None,
                   help="NTC 2018: Tc* [s] of the SLD hazard (default the spectrum's)")
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
                   help="FRP strips along the ring: characteristic strength, equivalent thickness, total width, and "
                        "a design strength of your own (default: the guideline's rupture eta_a f_fk / gamma_f, and "
                        "with --masonry the least of it and the debonding strengths)")
    p.add_argument("--frp-modulus", type=float, default=None, metavar="GPA", help="the strips' modulus E_f [GPa]")
    fibre, exposure, application = (default_of(Strips, k) for k in ("fibre", "exposure", "application"))
    p.add_argument("--frp-fibre", default=fibre, choices=sorted(ETA_A["internal"]), help=f"fibre (default {fibre})")
    p.add_argument("--frp-exposure", default=exposure, choices=list(ETA_A),
                   help=f"exposure of the environmental factor eta_a (default {exposure})")
    p.add_argument("--frp-application", default=application, choices=list(GAMMA_F),
                   help=f"application type of the partial factors (A: gamma_f {GAMMA_F['A']:g}, gamma_fd "
                        f"{GAMMA_FD['A']:g}; B: {GAMMA_F['B']:g}, {GAMMA_FD['B']:g}; default {application})")
    p.add_argument("--masonry", default=None, metavar="FM_MPA,FMT_MPA|TYPE",
                   help=f"the substrate's mean compressive and tensile strengths, or a type "
                        f"({', '.join(MASONRY_TYPES)}): the strips' debonding strengths")
    for dest, field, _, unit, what in BOND_OPTIONS:
        d = BondFactors().describe()[field]
        shown = f"{d['value']:g}{'' if d['unit'] == '-' else ' ' + d['unit']}"
        p.add_argument("--" + dest.replace("_", "-"), dest=dest, type=float, default=None, metavar=unit,
                       help=f"CNR-DT 200 R1/2013 bond factor: {what} (default {shown}, UNVERIFIED against the "
                            f"guideline: set it from your copy); strips designed on a --masonry, and noh-gumbad's")
    p.add_argument("--frp-face", default="extrados", choices=("extrados", "intrados"),
                   help="the ring face the strips are bonded to (default extrados)")
    p.add_argument("--tie", default=None, metavar="HEIGHT_M,AREA_MM2,FY_MPA[,PRESTRESS_KN]",
                   help="a steel tie across the structure at a height above the springing line (0: the springings or "
                        "the pier tops; negative: in the piers), of cross-section area and yield strength; "
                        "rigid-plastic in the analyses (the prestress is recorded); with noh-gumbad a row per configuration "
                        "with the tie alone")
    p.add_argument("--records", nargs="+", default=None, metavar="FILE",
                   help="records (.AT2, .smc, ESM, CSV) matched to the site spectrum and shaken on the DEM (an arch, not "
                        "noh-gumbad)")
    p.add_argument("--match-periods", default=None, metavar="LO,HI",
                   help="period range [s] of the records' match (default 0.2-2 x the limit state's period)")
    p.add_argument("--report", default=None, metavar="FILE.html|FILE.pdf",
                   help="write the assessment with its figures: FILE.html one page, FILE.pdf a printable report "
                        "(title block, inputs, site, each step, verdicts, figures) (never overwrites)")
    p.add_argument("--project", default=None, help="--report FILE.pdf: the project named in the title block (default -)")
    p.add_argument("--engineer", default=None, help="--report FILE.pdf: the engineer named in the title block (default -)")
    p.set_defaults(func=_run)
