"""One arch's or one drawing's limit analysis as ``archdem analytic`` answers it: a frozen spec
(:class:`ArchAnalysisSpec`), its run (:func:`run`) and results whose JSON (``to_json``) and text
(``lines``) are written here (:class:`ArchAnalysis`, :class:`DrawingAnalysis`)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable

from analytic.limit.summary import ARCH_ONLY_ANALYSES, analyse, analyse_drawing
from foundation.errors import ArchdemInputError
from specimens.drawn import gaps_text

#: The friction laws of the joints: the associative LP alone, or the non-associative collapse beside it.
FRICTION_LAWS = ("associative", "non-associative")

#: What each line of the text answer is; lambda is the horizontal load as a fraction of the weight at
#: collapse (the tilt test's tan(theta)).
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


def json_ready(res: dict) -> dict:
    """``res`` with NaN as None: its own floats and, nested, the non-associative entry's (the other
    entries as before)."""
    return {k: _no_nan(v) if k == "non_associative" or isinstance(v, float) else v for k, v in res.items()}


def non_associative_lines(na: dict, between: dict[str, list[str]] | None = None, width: int = 17) -> list[str]:
    """The two lines of the non-associative entry: the associative LP (the upper bound) and the
    non-associative multiplier with its mechanism, how the search ended and its cost [s]. ``between``:
    the bodies each joint lies between (a drawing's), shown after the joint."""
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


@dataclass(frozen=True)
class ArchAnalysisSpec:
    """The analyses of one two-centred ``arch`` named ``label`` (:func:`analyse`'s arguments): the
    frictions [-], the continuous ring's kept thickness fraction [-] and least hinge spacing [rad],
    the discretisation keywords ``disc_kw`` and whether to solve without dilatancy too."""

    label: str
    arch: Any
    config: str
    mu_joint: float
    mu_base: float
    effective_thickness: float
    min_spacing: float
    disc_kw: dict = field(default_factory=dict)
    non_associative: bool = False

    def __post_init__(self) -> None:
        if not (0.05 <= self.effective_thickness <= 1):
            raise ArchdemInputError(f"--effective-thickness must be in [0.05, 1], got {self.effective_thickness}")
        if self.disc_kw.get("piers") is not None and (self.effective_thickness != 1.0 or self.min_spacing != 0.0):
            raise ArchdemInputError("--effective-thickness and --min-spacing apply to the ring on a rigid base; on "
                                    "piers use --contact")


@dataclass(frozen=True)
class ArchAnalysis:
    """:func:`analyse`'s answer (``values``) for the arch ``label``."""

    label: str
    values: dict

    def to_json(self) -> dict:
        """The answer, its id last, NaN as None."""
        return json_ready({**self.values, "id": self.label})

    @property
    def exit_code(self) -> int:
        """0 when the continuous ring has a finite collapse multiplier and the arch stands, else 1."""
        lam = self.to_json()["lambda_continuous"]
        return 0 if self.values["stands"] and lam is not None and math.isfinite(lam) else 1

    def lines(self) -> list[str]:
        """The analyses as ``archdem analytic`` prints them, one line each."""
        res = self.to_json()
        on_piers = "piers" in res
        out = [f"{self.label}  (config {res['config']}, mu_joint {res['mu_joint']:g}, mu_base {res['mu_base']:g})"
               + (f"  on piers {res['piers']['height']:g} m high, {res['piers']['width']:g} m wide, "
                  f"{res['piers']['courses']} course(s)" if on_piers else "")]
        if not res["stands"]:  # its multipliers are negative or missing: no load capacity to print
            return [*out, "  the arch cannot stand under self-weight: no collapse multiplier (see --json for the analyses)"]
        # the angle's unit on every hinge: a bare 0.074 reads as a length in metres as easily
        hc = ", ".join(f"{h['half'][0].upper()} {h['angle_rad']:.3f} rad {h['face'][:3]}" if "half" in h else
                       f"{h['pier'][0].upper()}P h={h['height_m']:.3f} m {h['face'][:3]}" for h in res["hinges_continuous"])
        out.append(f"  continuous   lambda = {_lam(res['lambda_continuous'])}   hinges: {hc}")
        if on_piers:
            out.append(f"    ({res['continuous_message']})")
        hd = ", ".join(f"{h['joint']} {h['face'][:3]}" for h in res["hinges_discrete"])
        out.append(f"  discrete     lambda = {_lam(res['lambda_discrete'])}   hinges: {hd}")
        act = ", ".join(f"{k} {v['state']}" for k, v in res["joints_lp"].items() if v["state"] != "closed")
        out.append(f"  LP (friction) lambda = {_lam(res['lambda_lp'])}   {act}   [{res['lp_status']}]")
        if "non_associative" in res:
            out += non_associative_lines(res["non_associative"])
        if on_piers:
            out.append(f"  two-bar      ({res['two_bar_message']})")
        else:
            out.append(f"  two-bar      lambda = {_lam(res['lambda_two_bar'])} (frictionless crown slider)   "
                       f"mu* = {_lam(res['mu_star'], '.3f')} (friction above which the crown stops sliding and the "
                       "arch rocks)")
        return out + [f"  warning: {w}" for w in res["warnings"]]


def run(spec: ArchAnalysisSpec) -> ArchAnalysis:
    """Every analysis of ``spec``'s arch (:func:`analyse`, about 1 s; a few with ``non_associative``)."""
    return ArchAnalysis(spec.label, analyse(spec.arch, spec.config, spec.mu_joint, spec.mu_base,
                                            spec.effective_thickness, spec.min_spacing, spec.disc_kw,
                                            non_associative=spec.non_associative))


def _joint_text(h: dict) -> str:
    """``J5 intrados (V1|V2)``: a joint of the LP's mechanism, what it does and the bodies it lies between."""
    what = h["face"] + ("+sliding" if h.get("sliding") else "") if "face" in h else h["state"]
    return f"{h['joint']} {what} ({'|'.join(h['between'])})"


def _mechanism_text(res: dict, key: str) -> str:
    hinges = ", ".join(_joint_text(h) for h in res[f"hinges_{key}"])
    moving = ", ".join(_joint_text(m) for m in res.get(f"moving_{key}", []))
    return f"hinges: {hinges or '-'}" + (f"; {moving}" if moving else "")


@dataclass(frozen=True)
class DrawingAnalysis:
    """:func:`~analytic.limit.summary.analyse_drawing`'s answer (``values``) for the drawn blocks
    ``assembly`` named ``label``, with the LP's ``mu_star_lp`` [-] (None without a joint between blocks or
    beyond the search) and ``density_note``, the line saying the density and where it came from."""

    label: str
    assembly: Any
    values: dict
    mu_star_lp: float | None
    density_note: str

    def to_json(self) -> dict:
        """The answer, its id first, NaN as None."""
        return {"id": self.label, **json_ready({**self.values, "mu_star_lp": self.mu_star_lp})}

    @property
    def exit_code(self) -> int:
        """0 when the blocks stand at the frictions, else 1."""
        return 0 if self.values["stands_at_friction"] else 1

    def lines(self) -> list[str]:
        """The analyses as ``archdem analytic --geometry`` prints them, one line each."""
        res, asm = self.to_json(), self.assembly
        mu_b = res["mu_base"]
        out = [f"{self.label}  (drawing {asm.source.get('file', '')}: {res['n_blocks']} blocks, {res['n_joints']} "
               f"joints, {'one chain' if res['chain'] else 'not one chain'}; contact {res['contact']:g}, mu_joint "
               f"{res['mu_joint']:g}, mu_base {mu_b:g})",
               f"  {self.density_note}: {res['total_mass_kg']:.4g} kg in all; masses and forces scale with it, "
               "the multipliers do not"]
        if asm.gaps:
            out.append(f"  gaps (no joint between them): {gaps_text(asm.gaps)}")
        if res["stands_at_friction"]:
            out.append(f"  LP (friction)    lambda = {_lam(res['lambda_lp'])}   {_mechanism_text(res, 'lp')}   "
                       f"[{res['lp_status']}]")
        else:
            out.append(f"  LP (friction)    the blocks cannot stand under self-weight at these frictions "
                       f"[{res['lp_status']}]")
        if "non_associative" in res and res["stands_at_friction"]:
            between = {k: v["between"] for k, v in res["joints_lp"].items()}
            out += non_associative_lines(res["non_associative"], between)
        out.append(f"  LP (no sliding)  lambda = {_lam(res['lambda_no_sliding'])}   {_mechanism_text(res, 'no_sliding')}")
        ns, nsb = res["lambda_no_sliding"], res["lambda_no_joint_sliding"]
        if nsb is not None and ns is not None and not math.isclose(ns, nsb, rel_tol=1e-9):
            out.append(f"  LP (joints not sliding, base at mu_base {mu_b:g})  lambda = {_lam(nsb)}")
        if res["chain"]:
            hd = ", ".join(_joint_text(h) for h in res["hinges_discrete"])
            out.append(f"  discrete         lambda = {_lam(res['lambda_discrete'])}   hinges: {hd}   "
                       "(four-hinge enumeration)")
        ms = res["mu_star_lp"]
        if not any(not j.is_base for j in asm.joints):
            out.append("  mu* (LP)         -   no joint between blocks (the base's friction is --mu-base)")
        elif ms is None:
            out.append("  mu* (LP)         -   the LP's collapse still slides at a joint between blocks at a friction "
                       "of 10")
        elif ms == 0:
            out.append("  mu* (LP)         0   no joint between blocks slides in the LP's collapse, at any friction")
        else:
            out.append(f"  mu* (LP)         {ms:.3f}   below it a joint between blocks slides in the LP's collapse, "
                       "above it none does")
        out.append(f"  not for a drawing (they need a two-centred arch's parameters): {'; '.join(ARCH_ONLY_ANALYSES)}")
        return out


def run_drawing(label: str, assembly, mu_joint: float, mu_base: float, non_associative: bool,
                mu_star: Callable[[Any, float, float], float | None], density_note: str) -> DrawingAnalysis:
    """The analyses of a drawing's blocks ``assembly`` (:func:`~analytic.limit.summary.analyse_drawing`) with
    the LP's mu*: ``mu_star(assembly, mu_base, lambda without joint sliding)``, the least joint friction at
    which the LP reaches its value with the joints not sliding (none without a joint between blocks).
    Refuses blocks that cannot stand under their own weight even without sliding."""
    res = analyse_drawing(assembly, mu_joint, mu_base, non_associative=non_associative)
    if not res["stands"]:  # no equilibrium even without sliding: the drawing, not an analysis, is at fault
        raise ArchdemInputError(assembly.cannot_stand(label))
    inner = any(not j.is_base for j in assembly.joints)
    ms = mu_star(assembly, mu_base, res["lambda_no_joint_sliding"]) if inner else None
    return DrawingAnalysis(label, assembly, res, ms, density_note)


__all__ = ["ArchAnalysisSpec", "ArchAnalysis", "DrawingAnalysis", "run", "run_drawing", "json_ready",
           "non_associative_lines", "FRICTION_LAWS", "TERMS"]
