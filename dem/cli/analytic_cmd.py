"""``archdem analytic``: limit analysis of one arch (continuous, discrete, LP, two-bar) or figures; of a
drawing's blocks (``--geometry``), the static LP with its hinges and mu*. ``--friction non-associative``
adds the least multiplier with Coulomb friction without dilatancy."""
from __future__ import annotations

import argparse
import math

from analytic.limit.summary import ARCH_ONLY_ANALYSES, analyse, analyse_drawing
from dem.common.options import (
    add_options,
    arch_from_args,
    default_of,
    density_text,
    discretisation_kwargs,
    option_used,
    print_json,
    writable_dir,
)
from specimens.blocks import discretise
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from specimens.drawn import DrawnAssembly, gaps_text
from foundation.errors import ArchdemInputError


#: The choices of ``--friction``: the associative LP alone, or the non-associative collapse beside it.
FRICTION_LAWS = ("associative", "non-associative")


#: What each line of the output is (``archdem analytic --help``); lambda is the horizontal load as a
#: fraction of the weight at collapse (the tilt test's tan(theta)).
TERMS = """terms (lambda: the horizontal load at collapse over the weight):
  continuous     four-hinge mechanism of the continuous ring (hinges anywhere, no sliding); a hinge
                 is its half (L, R) and its polar angle [rad] about that half's centre, 0 at the
                 springing; in a pier (LP, RP) its height h [m] above the ground
  discrete       four-hinge enumeration over the joints of the voussoirs (no sliding)
  LP (friction)  static linear program over the same joints with Coulomb friction (joints may
                 hinge or slide; associative: sliding joints dilate)
  two-bar        the ring as two halves hinged at the springings with a frictionless slider at
                 the crown (lambda); mu*: the friction at the crown above which it stops sliding
                 and the arch rocks (four hinges) instead
  mu* (LP)       of a drawing: the least joint friction at which no joint between blocks slides in
                 the LP's collapse
faces: int = intrados, ext = extrados."""


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


def _lam(v: float | None, fmt: str = ".4f") -> str:
    """A multiplier as printed: a number, or "-" where the analysis has none."""
    return "-" if v is None else format(v, fmt)


def _no_nan(v: object) -> object:
    """``v`` with every NaN float, nested in dicts and lists too, replaced by None (JSON null)."""
    if isinstance(v, float) and math.isnan(v):
        return None
    if isinstance(v, dict):
        return {k: _no_nan(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_no_nan(x) for x in v]
    return v


def _json_ready(res: dict) -> dict:
    """``res`` with NaN as None: its own floats and, nested, the non-associative entry's (the other
    entries as before)."""
    return {k: _no_nan(v) if k == "non_associative" or isinstance(v, float) else v for k, v in res.items()}


def _non_associative_lines(na: dict, between: dict[str, list[str]] | None = None, width: int = 17) -> list[str]:
    """The two lines of ``--friction non-associative``: the associative LP (the upper bound) and the
    non-associative multiplier with its mechanism, how the search ended and its cost. ``between``: the
    bodies each joint lies between (a drawing's), shown after the joint."""
    def joint(k: str, what: str = "") -> str:
        return f"{k}{' ' + what if what else ''}" + (f" ({'|'.join(between[k])})" if between and k in between else "")

    lp, lam = na["lambda_associative"], na["lambda_non_associative"]
    lines = [f"  {'LP (associative)':<{width}}lambda = {_lam(lp)}   (upper bound: sliding joints dilate)"]
    if lam is None or not math.isfinite(lam):  # no mechanism found, or none can form
        lines.append(f"  {'non-associative':<{width}}lambda = {_lam(lam)}   [{na['message']}; {na['seconds']:.1f} s]")
        return lines
    below = f"{100 * (1 - lam / lp):.2f} % below" if lp and math.isfinite(lp) else "below the LP"
    mech = [", ".join(joint(h["joint"], h["face"] + ("+sliding" if h["sliding"] else "")) for h in na["hinges"]) or "-"]
    for key in ("sliding", "open"):
        if na[key]:
            mech.append(f"{key}: {', '.join(joint(k) for k in na[key])}")
    lines.append(f"  {'non-associative':<{width}}lambda = {_lam(lam)}   {below}; hinges: {'; '.join(mech)}   "
                 f"[{na['message']}; {na['seconds']:.1f} s, {na['nodes']} nodes]")
    return lines


def run(args: argparse.Namespace) -> int:
    if args.plot is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.limit.figures import catalogue_figures

        out = writable_dir(args.plot)
        files = catalogue_figures(out)
        if args.json:
            print_json({"figures": [str(f) for f in files]})
        else:
            for f in files:
                print(f)
        return 0  # the table refuses --plot beside an arch
    label, arch = arch_from_args(args)
    mu_j = REFERENCE_MU_JOINT if args.mu_joint is None else args.mu_joint
    mu_b = REFERENCE_MU_BASE if args.mu_base is None else args.mu_base
    if isinstance(arch, DrawnAssembly):
        return _run_drawing(args, label, arch, mu_j, mu_b)
    if not (0.05 <= args.effective_thickness <= 1):
        raise ArchdemInputError(f"--effective-thickness must be in [0.05, 1], got {args.effective_thickness}")
    disc_kw = discretisation_kwargs(args, arch)
    if "piers" in disc_kw and (args.effective_thickness != 1.0 or args.min_spacing != 0.0):
        raise ArchdemInputError("--effective-thickness and --min-spacing apply to the ring on a rigid base; on piers "
                                "use --contact")
    res = analyse(arch, args.config, mu_j, mu_b, args.effective_thickness, args.min_spacing, disc_kw,
                  non_associative=args.friction == "non-associative")
    res["id"] = label
    res = _json_ready(res)
    if args.json:
        print_json(res)
        return 0
    on_piers = "piers" in disc_kw
    print(f"{label}  (config {args.config}, mu_joint {mu_j:g}, mu_base {mu_b:g})"
          + (f"  on piers {res['piers']['height']:g} m high, {res['piers']['width']:g} m wide, "
             f"{res['piers']['courses']} course(s)" if on_piers else ""))
    if not res["stands"]:  # its multipliers are negative or missing: no load capacity to print
        print("  the arch cannot stand under self-weight: no collapse multiplier (see --json for the analyses)")
        return 1
    # the angle's unit on every hinge: a bare 0.074 reads as a length in metres as easily
    hc = ", ".join(f"{h['half'][0].upper()} {h['angle_rad']:.3f} rad {h['face'][:3]}" if "half" in h else
                   f"{h['pier'][0].upper()}P h={h['height_m']:.3f} m {h['face'][:3]}" for h in res["hinges_continuous"])
    print(f"  continuous   lambda = {_lam(res['lambda_continuous'])}   hinges: {hc}")
    if on_piers:
        print(f"    ({res['continuous_message']})")
    hd = ", ".join(f"{h['joint']} {h['face'][:3]}" for h in res["hinges_discrete"])
    print(f"  discrete     lambda = {_lam(res['lambda_discrete'])}   hinges: {hd}")
    act = ", ".join(f"{k} {v['state']}" for k, v in res["joints_lp"].items() if v["state"] != "closed")
    print(f"  LP (friction) lambda = {_lam(res['lambda_lp'])}   {act}   [{res['lp_status']}]")
    if "non_associative" in res:
        print("\n".join(_non_associative_lines(res["non_associative"])))
    if on_piers:
        print(f"  two-bar      ({res['two_bar_message']})")
    else:
        print(f"  two-bar      lambda = {_lam(res['lambda_two_bar'])} (frictionless crown slider)   "
              f"mu* = {_lam(res['mu_star'], '.3f')} (friction above which the crown stops sliding and the arch rocks)")
    for w in res["warnings"]:
        print(f"  warning: {w}")
    lam = res["lambda_continuous"]
    return 0 if lam is not None and math.isfinite(lam) else 1


def _joint_text(h: dict) -> str:
    """``J5 intrados (V1|V2)``: a joint of the LP's mechanism, what it does and the bodies it lies between."""
    what = h["face"] + ("+sliding" if h.get("sliding") else "") if "face" in h else h["state"]
    return f"{h['joint']} {what} ({'|'.join(h['between'])})"


def _mechanism_text(res: dict, key: str) -> str:
    hinges = ", ".join(_joint_text(h) for h in res[f"hinges_{key}"])
    moving = ", ".join(_joint_text(m) for m in res.get(f"moving_{key}", []))
    return f"hinges: {hinges or '-'}" + (f"; {moving}" if moving else "")


def _run_drawing(args: argparse.Namespace, label: str, drawn: DrawnAssembly, mu_j: float, mu_b: float) -> int:
    """``archdem analytic --geometry FILE``: the static LP of the drawn blocks, its hinges and mu*."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.friction_map.run import lp_mu_star

    for dest in ("effective_thickness", "min_spacing"):
        option_used(args, dest, False, "it belongs to the continuous ring of a two-centred arch, not to a drawing")
    asm = discretise(drawn, **discretisation_kwargs(args, drawn))
    res = analyse_drawing(asm, mu_j, mu_b, non_associative=args.friction == "non-associative")
    if not res["stands"]:  # no equilibrium even without sliding: the drawing, not an analysis, is at fault
        raise ArchdemInputError(asm.cannot_stand(label))
    # mu* as the friction map defines it: the least joint friction at which the LP reaches its value
    # with the joints not sliding (at the same base friction); none without joints between blocks
    inner = any(not j.is_base for j in asm.joints)
    res["mu_star_lp"] = lp_mu_star(asm, mu_b, res["lambda_no_joint_sliding"]) if inner else None
    res = {"id": label, **_json_ready(res)}
    if args.json:
        print_json(res)
        return 0
    print(f"{label}  (drawing {asm.source.get('file', '')}: {res['n_blocks']} blocks, {res['n_joints']} joints, "
          f"{'one chain' if res['chain'] else 'not one chain'}; contact {res['contact']:g}, mu_joint {mu_j:g}, "
          f"mu_base {mu_b:g})")
    print(f"  {density_text(asm)}: {res['total_mass_kg']:.4g} kg in all; masses and forces scale with it, "
          "the multipliers do not")
    if asm.gaps:
        print(f"  gaps (no joint between them): {gaps_text(asm.gaps)}")
    if res["stands_at_friction"]:
        print(f"  LP (friction)    lambda = {_lam(res['lambda_lp'])}   {_mechanism_text(res, 'lp')}   "
              f"[{res['lp_status']}]")
    else:
        print(f"  LP (friction)    the blocks cannot stand under self-weight at these frictions [{res['lp_status']}]")
    if "non_associative" in res and res["stands_at_friction"]:
        between = {k: v["between"] for k, v in res["joints_lp"].items()}
        print("\n".join(_non_associative_lines(res["non_associative"], between)))
    print(f"  LP (no sliding)  lambda = {_lam(res['lambda_no_sliding'])}   {_mechanism_text(res, 'no_sliding')}")
    ns, nsb = res["lambda_no_sliding"], res["lambda_no_joint_sliding"]
    if nsb is not None and ns is not None and not math.isclose(ns, nsb, rel_tol=1e-9):
        print(f"  LP (joints not sliding, base at mu_base {mu_b:g})  lambda = {_lam(nsb)}")
    if res["chain"]:
        hd = ", ".join(_joint_text(h) for h in res["hinges_discrete"])
        print(f"  discrete         lambda = {_lam(res['lambda_discrete'])}   hinges: {hd}   (four-hinge enumeration)")
    ms = res["mu_star_lp"]
    if not inner:
        print("  mu* (LP)         -   no joint between blocks (the base's friction is --mu-base)")
    elif ms is None:
        print("  mu* (LP)         -   the LP's collapse still slides at a joint between blocks at a friction of 10")
    elif ms == 0:
        print("  mu* (LP)         0   no joint between blocks slides in the LP's collapse, at any friction")
    else:
        print(f"  mu* (LP)         {ms:.3f}   below it a joint between blocks slides in the LP's collapse, above it "
              "none does")
    print(f"  not for a drawing (they need a two-centred arch's parameters): {'; '.join(ARCH_ONLY_ANALYSES)}")
    return 0 if res["stands_at_friction"] else 1
