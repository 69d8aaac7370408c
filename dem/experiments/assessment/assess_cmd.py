"""``archdem assess``: is this arch safe here? The codes' kinematic analysis of its mechanism, linear
and non-linear, against a site's elastic spectrum, with and without FRP strips
(docs/physics/assessment.md)."""
from __future__ import annotations

import argparse
import math

from analytic.codes.assessment import (
    assess,
    assess_monument,
    index_text,
    monument_site,
    monument_strips,
    quantity_text,
)
from analytic.codes.frp import ETA_A, GAMMA_F, GAMMA_FD, MASONRY_TYPES, BondFactors, Masonry, Strips, masonry_type
from analytic.codes.kinematic import CONFIDENCE_FACTORS, Height
from analytic.limit.ties import Tie
from analytic.motions.spectra import EC8_GROUND, NTC_SOIL, NTC_TOPOGRAPHY, ec8, ntc2018, read_spectrum, rebuild
from dem.common.options import (
    add_arch_arguments,
    add_engine_argument,
    arch_from_args,
    default_of,
    discretisation_kwargs,
    option_used,
    parse_grid,
    print_json,
    workers_option,
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


def _strengthening(row: dict) -> str:
    return "+".join(k for k, on in (("FRP", row.get("frp")), ("tie", row.get("tie"))) if on) or "none"


def check_table(rows: list[dict], lead: list[tuple[str, int, list[str]]] | None = None) -> list[str]:
    """The terminal table of :func:`analytic.codes.assessment.check_rows`: demand and capacity as the
    clause compares them, the index (capacity / demand), the verdict and the clause; ``lead``: columns
    before them, as (header, width, one value per row)."""
    lead = lead or []
    head = "".join(f"{h:{w}s} " for h, w, _ in lead)
    out = [f"  {head}{'limit state / check':28s} {'demand':>32s} {'capacity':>34s} {'index':>7s}  {'verdict':12s}  clause"]
    for k, r in enumerate(rows):
        cols = "".join(f"{vals[k]:{w}s} " for _, w, vals in lead)
        name = f"{r['limit_state']} {r['check']}" + ("" if r["code_check"] else " *")
        out.append(f"  {cols}{name:28s} {r['demand_symbol'] + ' ' + quantity_text(r['demand'], r['unit']):>32s} "
                   f"{r['capacity_symbol'] + ' ' + quantity_text(r['capacity'], r['unit']):>34s} "
                   f"{index_text(r['safety_index']):>7s}  {r['verdict']:12s}  {r['clause']}")
    if any(not r["code_check"] for r in rows):
        out.append("  * the a0*/PGA convention of published tables: reported, not a code check, never governs")
    return out


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
    from dem.experiments.assessment.figure import hinges_text

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
    rows = assess_monument(monument, site, strips, args.FC, args.q, args.limit_state, height=height, tie=tie,
                           sld_site=sld)
    out = {"id": monument.name, "source": monument.source, "arch": {"e": monument.arch.e, "t": monument.arch.t,
           "Rp": monument.arch.Rp, "width": monument.arch.width, "span": monument.arch.span,
           "rise": monument.arch.rise},
           "configurations": {k: (None if v is None else vars(v)) for k, v in monument.configurations.items()},
           "density": monument.density, "spectrum": site.describe(),
           "sld_spectrum": None if sld is None else sld.describe(),
           "height": None if height is None else vars(height), "strips": strips.describe(monument.arch.width),
           "tie": None if tie is None else tie.describe(), "rows": rows}
    if args.report is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.figure import write_report
        from dem.experiments.assessment.report_pdf import monument_governing, write_monument_pdf_report

        if args.report.lower().endswith(".pdf"):
            write_monument_pdf_report(args.report, monument, site, strips, args.FC, args.q, args.limit_state,
                                      args.project or "-", args.engineer or "-", rows=rows, height=height,
                                      sld_site=sld)
        else:
            _, name, *gov = monument_governing(monument, site, strips, args.FC, args.q, args.limit_state, rows,
                                               height, sld)
            write_report(args.report, f"{monument.name} ({name})", site, *gov)
        out["report"] = args.report
    if args.json:
        print_json(out)
        return 0
    sd = strips.describe(monument.arch.width)
    where = "ground level" if height is None else f"z/H = {height.z_ratio:g} of a {height.floors}-floor building"
    print(f"{monument.name}: {site.describe()['code']} site, PGA {site.pga / G:.3f} g ({site.pga:.3g} m/s^2); "
          f"{args.limit_state.upper()}{'' if sld is None else f' and SLD (ag {sld.ag / G:.3f} g)'}, at {where}; "
          f"FRP {sd['strength_MPa']:g} MPa x {strips.thickness * 1e3:g} mm x {strips.width * 1e3:g} mm "
          f"on the {strips.face}: design {sd['design_strength_MPa']:.4g} MPa ({sd['governing']}), "
          f"force {sd['force_N'] / 1e3:.3g} kN" + ("" if tie is None else f"; tie at {tie.height:g} m yielding at "
                                                  f"{tie.force / 1e3:.4g} kN (without the strips)"))
    print(f"  {'configuration':18s} {'strengthening':13s} {'lambda':>7s} {'e*':>6s} {'a0* [g]':>8s} {'d0* [mm]':>9s} "
          f"{'a0*/PGA':>7s} {'governing':>22s} {'index':>7s}  {'verdict':12s}  hinges")
    for r in rows:
        print(f"  {r['configuration']:18s} {_strengthening(r):13s} {r['lambda']:7.4f} {r['e_star']:6.3f} "
              f"{r['a0_star'] / G:8.4f} {r['d0_star'] * 1e3:9.4g} {r['activation_over_pga']:7.3f} "
              f"{r['governing_check']:>22s} {index_text(r['safety_index']):>7s}  "
              f"{'verified' if r['verified'] else 'not verified':12s}  {hinges_text(r['hinges'])}")
    print("  checks (safety index = capacity / demand):")
    flat = [(r, c) for r in rows for c in r["check_rows"]]
    for line in check_table([c for _, c in flat], [("configuration", 18, [r["configuration"] for r, _ in flat]),
                                                   ("strengthening", 13, [_strengthening(r) for r, _ in flat])]):
        print(line)
    if strips.masonry is not None:
        print(f"  FRP bond factors (CNR-DT 200 R1/2013): {strips.bond.text(_named_masonry(args))}")
    return 0


def _print(title: str, hinges: list[dict], res) -> None:
    d = res.describe()
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.figure import hinges_text

    print(f"  {title}: hinges at {hinges_text(hinges)}")
    print(f"    alpha0 = {d['alpha0']:.4f}   M* = {d['M_star']:.4g} kg   e* = {d['e_star']:.3f}   "
          f"a0* = {d['a0_star'] / G:.4f} g (FC {d['FC']:g})   d0* = {d['d0_star'] * 1e3:.4g} mm")
    for line in check_table(d["check_rows"]):
        print("  " + line)
    print(f"    governing: {d['governing_check']}, safety index {index_text(d['safety_index'])} "
          f"({'verified' if d['verified'] else 'not verified'})")


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.run import assess_with_records
    from specimens.monuments import MONUMENTS

    option_used(args, "engine", bool(args.records), "the engine runs the --records on the DEM")
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
    if not args.records and (args.match_periods is not None or args.workers is not None):
        raise ArchdemInputError("--match-periods and --workers belong to --records")
    a = assess_with_records(arch, args.records or (), site, FC=args.FC, q=args.q, limit_state=args.limit_state,
                            height=height, period_range=_period_range(args), settings=dynamics_settings(engine=args.engine),
                            workers=args.workers, strips=strips, tie=tie, sld_site=sld,
                            **discretisation_kwargs(args, arch))
    mech, res = a.mechanism, a.assessment
    out = {"id": label, "spectrum": site.describe(), "height": None if height is None else vars(height),
           "mechanism": mech.summary(), **res.describe()}
    frp, sc = a.strengthened_assessment, a.strengthened
    key = "frp" if strips is not None else "tie"
    if sc is not None:
        out[key] = {"strips": None if strips is None else strips.describe(arch.width), "lambda": sc.lam,
                    "mechanism": sc.mechanism.summary(), "hinges": sc.mechanism.summary()["hinges"],
                    "strip_hinges": sc.strip_hinges(),
                    "crushing": None if strips is None else sc.crushing(strips.masonry, args.FC),
                    "tie": None if tie is None else {**tie.describe(), "force_at_collapse_kN": sc.tie_lp_force / 1e3,
                                                     "anchors_m": [sc.tie_link.p_a.tolist(), sc.tie_link.p_b.tolist()]},
                    **frp.describe()}
    if a.records is not None:
        out["records"] = a.records.describe()
    if args.report is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.figure import write_report
        from dem.experiments.assessment.report_pdf import command_inputs, write_pdf_report

        if args.report.lower().endswith(".pdf"):
            write_pdf_report(args.report, label, site, mech, res, out, frp, out.get(key), project=args.project or "-",
                             engineer=args.engineer or "-", inputs=command_inputs(args, arch, strips))
        else:
            write_report(args.report, label, site, mech, res, out, frp, out.get(key))
        out["report"] = args.report
    if args.json:
        print_json(out)
        return 0
    where = "ground level" if height is None else f"z/H = {height.z_ratio:g} of a {height.floors}-floor building"
    print(f"{label}: {site.describe()['code']} site, ag = {site.ag / G:.3f} g, PGA = {site.pga / G:.3f} g; "
          f"{args.limit_state.upper()}, mechanism at {where}")
    _print(f"unreinforced ({mech.label})", out["mechanism"].get("hinges", []), res)
    if frp is not None:
        parts = []
        if strips is not None:
            sd = out[key]["strips"]
            parts.append(f"FRP strips on the {strips.face}, f_fd = {sd['design_strength_MPa']:.4g} MPa "
                         f"({sd['governing']}), T = {sd['force_N'] / 1e3:.3g} kN")

        if tie is not None:
            parts.append(f"a tie at {tie.height:g} m yielding at {tie.force / 1e3:.4g} kN "
                         f"({out[key]['tie']['force_at_collapse_kN']:.4g} kN at collapse)")
        _print("with " + " and ".join(parts), out[key]["hinges"], frp)
        if strips is not None and strips.masonry is not None:
            print(f"    FRP bond factors (CNR-DT 200 R1/2013): {strips.bond.text(_named_masonry(args))}")
        for c in out[key]["crushing"] or []:
            print(f"    crushing at {c['joint']} ({c['face']}): C = {c['C_kN']:.3g} kN, stress block "
                  f"{c['y_mm']:.3g} mm of {c['t_mm']:.3g} mm ({'verified' if c['verified'] else 'not verified'})")
    if "records" in out:
        rec = out["records"]
        print(f"  records matched over {rec['period_range'][0]:.3g}-{rec['period_range'][1]:.3g} s, DEM "
              f"({rec['engine']}, {'tied' if a.records.tied else 'unreinforced'}):")
        for m, r in zip(rec["matched"], rec["runs"]):
            print(f"    {m['record'][:48]:48s} x{m['scale']:.3g} (misfit {m['misfit_mean_ln']:.2f}): "
                  f"{'COLLAPSE' if r['collapsed'] else 'stands'}, peak d* {r['peak_d_star'] * 1e3:.3g} mm")
        v = rec["verdict"]
        print(f"    mean peak d* {v['mean_peak_d_star'] * 1e3:.3g} mm vs d_u* {v['du_star'] * 1e3:.3g} mm, "
              f"{v['n_reach_d0']} of {v['n_records']} reach d0* -> {'verified' if v['verified'] else 'NOT verified'}"
              f" (code check: {'verified' if (frp if a.records.tied else res).verified else 'NOT verified'})")
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
    add_engine_argument(p, dynamics=True)
    p.add_argument("--workers", type=workers_option, default=None,
                   help="processes for the record runs (default: all cores, at most one per record)")
    p.add_argument("--report", default=None, metavar="FILE.html|FILE.pdf",
                   help="write the assessment with its figures: FILE.html one page, FILE.pdf a printable report "
                        "(title block, inputs, site, each step, verdicts, figures) (never overwrites)")
    p.add_argument("--project", default=None, help="--report FILE.pdf: the project named in the title block (default -)")
    p.add_argument("--engineer", default=None, help="--report FILE.pdf: the engineer named in the title block (default -)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=_run)
