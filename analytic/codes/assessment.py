"""The code-based assessment of one mechanism against one site (docs/physics/assessment.md): the
activation check (SLD), the linear and displacement checks of the life-safety state (SLV) or the
displacement check of SLC, the governing safety index, and the calculation trail."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

from analytic.codes.frp import BondFactors, Strips, masonry_type, strengthened_collapse
from analytic.codes.kinematic import (
    CONFIDENCE_FACTORS,
    MECHANISM_DAMPING,
    PERIOD_COEFFICIENT,
    Q_MASONRY,
    ULTIMATE_FRACTION,
    CapacityCurve,
    Height,
    LinearKinematic,
    capacity_curve,
    linear_kinematic,
    virtual_displacements,
)
from analytic.motions.spectra import ec8
from specimens.constants import G
from foundation.errors import ArchdemInputError

LIMIT_STATES = ("SLD", "SLV", "SLC")


@dataclass(frozen=True)
class Assessment:
    """``linear``: alpha0, M*, e*, a0*; ``curve``: the capacity curve; ``checks``: each check's dict
    (kind, limit state, ``demand`` and ``capacity`` in the clause's quantity, safety index = capacity /
    demand, verified, ``code_check``: False for the
    activation against a life-safety hazard, a convention reported beside the code's checks);
    ``bodies``: the virtual displacements of the bodies; ``safety_index``: the least of the code checks."""

    linear: LinearKinematic
    curve: CapacityCurve
    checks: tuple[dict, ...]
    bodies: tuple[dict, ...] = field(default=())

    @property
    def code_checks(self) -> tuple[dict, ...]:
        return tuple(c for c in self.checks if c.get("code_check", True))

    @property
    def safety_index(self) -> float:
        return min(c["safety_index"] for c in self.code_checks)

    @property
    def verified(self) -> bool:
        return all(c["verified"] for c in self.code_checks)

    def by_limit_state(self) -> dict:
        """Per limit state checked: its checks' safety indices, the least and which check governs."""
        out: dict[str, dict] = {}
        for c in self.code_checks:
            out.setdefault(c["limit_state"], {"checks": {}})["checks"][c["kind"]] = c["safety_index"]
        for d in out.values():
            k = min(d["checks"], key=d["checks"].get)
            d.update(governing=k, safety_index=d["checks"][k], verified=d["checks"][k] >= 1)
        return out

    def describe(self) -> dict:
        nl = [c for c in self.checks if c["kind"] == "non-linear"]
        gov = min(self.code_checks, key=lambda c: c["safety_index"])
        return {**self.linear.describe(), "d0_star": self.curve.d0_star,
                "du_star": nl[0]["d_u_star"] if nl else None,
                "limit_state": self.checks[-1]["limit_state"], "safety_index": self.safety_index,
                "governing_check": f"{gov['limit_state']} {gov['kind']}", "verified": self.verified,
                "limit_states": self.by_limit_state(), "checks": list(self.checks), "check_rows": check_rows(self),
                "trail": trail(self), "capacity_curve": self.curve.describe()}


def assess(mech, site, FC: float = CONFIDENCE_FACTORS["LC1"], q: float = Q_MASONRY, limit_state: str = "SLV",
           height: Height | None = None, alpha0: float | None = None,
           extra_force: Callable[[float], float] | None = None, sld_site=None) -> Assessment:
    """Assess ``mech`` (a one-degree-of-freedom mechanism) against the elastic spectrum ``site`` of
    ``limit_state`` (SLD: the activation check; SLV: the linear check with ``q`` and the displacement
    check; SLC: the displacement check), at ground level or at ``height``; ``sld_site``: the SLD
    hazard, whose activation check is added beside a life-safety one. Without it, a life-safety
    assessment also reports the activation against its own hazard (no ``q``: the "a0*/PGA"
    convention), not counted among the code's checks. ``alpha0`` and ``extra_force``: the multiplier
    and the generalised force of strips, when they act (:mod:`analytic.codes.frp`)."""
    ls = str(limit_state).upper()
    if ls not in LIMIT_STATES:
        raise ArchdemInputError(f"limit state must be SLD, SLV or SLC, got {limit_state!r}")
    if sld_site is not None and ls == "SLD":
        raise ArchdemInputError("the SLD hazard is the spectrum itself when the limit state is SLD")
    lin = linear_kinematic(mech, FC, alpha0=alpha0)
    curve = capacity_curve(mech, FC, extra_force=extra_force)
    checks: tuple[dict, ...] = ()
    if ls == "SLD":
        checks += ({**lin.activation(site, height, "SLD"), "code_check": True},)
    elif sld_site is not None:
        checks += ({**lin.activation(sld_site, height, "SLD"), "code_check": True},)
    else:
        checks += ({**lin.activation(site, height, ls), "code_check": False,
                    "convention": "activation against this hazard, no q (a0* / PGA at ground with S = 1)"},)
    if ls == "SLV":
        checks += ({**lin.check(site, q, height), "code_check": True},)
    if ls in ("SLV", "SLC"):
        checks += ({**curve.check(site, ls, height), "code_check": True},)
    return Assessment(lin, curve, checks, tuple(virtual_displacements(mech)))


#: How the trail words where d0* was read (CapacityCurve.d0_star_from).
_D0_FROM = {"this curve": "on the mechanism's own capacity curve", "gravity alone": "on the curve of gravity alone"}


#: The clauses of the Circolare 2019 the trail's steps come from, at section level (no equation numbers:
#: they are not checked against the text).
LINEAR_CLAUSE = "C8.7.1.2 linear"
NON_LINEAR_CLAUSE = "C8.7.1.2 non-linear"
FC_CLAUSE = "C8.5 knowledge levels"


def _step(symbol: str, value, unit: str, formula: str, clause: str = LINEAR_CLAUSE) -> dict:
    return {"symbol": symbol, "value": value, "unit": unit, "formula": formula, "clause": clause}


def trail(a: Assessment) -> list[dict]:
    """Every intermediate quantity of the assessment with its unit and the formula it comes from,
    in the order an engineer writes the verification."""
    lin, cur = a.linear, a.curve
    sm = sum(b["m"] * b["dx"] for b in a.bodies)
    smm = sum(b["m"] * b["dx"] ** 2 for b in a.bodies)
    out = [_step("alpha0", lin.alpha0, "-", "collapse multiplier of the mechanism (limit analysis = virtual work)")]
    for b in a.bodies:
        out.append(_step(f"body {b['body']}: m, dx, dy, dtheta", [b["m"], b["dx"], b["dy"], b["dtheta"]],
                         "kg, m/rad, m/rad, -", "virtual displacements of the centroid per unit rotation of the "
                                                "first link (dx along the load)"))
    out += [_step("sum m dx", sm, "kg m", "sum over the bodies"),
            _step("sum m dx^2", smm, "kg m^2", "sum over the bodies"),
            _step("M*", lin.M_star, "kg", "(sum m dx)^2 / sum m dx^2"),
            _step("sum m", lin.mass, "kg", "mass of the moving bodies"),
            _step("e*", lin.e_star, "-", "M* / sum m"),
            _step("FC", lin.FC, "-", "confidence factor of the knowledge level", FC_CLAUSE),
            _step("a0*", lin.a0_star, "m/s^2", "alpha0 g / (e* FC)"),
            _step("a0*/g", lin.a0_star / G, "g", "a0* / g"),
            _step("d0*", cur.d0_star, "m", f"d* where a*(d*) vanishes ({_D0_FROM.get(cur.d0_star_from, cur.d0_star_from)}); "
                                           f"d* = d_C / e*, a* = alpha g / (e* FC)", NON_LINEAR_CLAUSE)]
    for c in a.checks:
        tag = f"{c['limit_state']} {c['kind']}"
        if c["kind"] in ("activation", "linear"):
            q = c.get("q", 1.0)
            out += [_step(f"{tag}: demand acceleration", c["demand"], "m/s^2",
                          "ag S of the hazard (ground) or the floor's a_Z (at a height)"),
                    _step(f"{tag}: q", q, "-", "behaviour factor (1: activation)"),
                    _step(f"{tag}: capacity acceleration", c["capacity"], "m/s^2", "q a0*"),
                    _step(f"{tag}: ag activating", c["activation_ag"], "m/s^2",
                          "the hazard's ag at which the demand acceleration equals a0* (spectrum rebuilt)"),
                    _step(f"{tag}: capacity ag", c["capacity_ag"], "m/s^2",
                          "the hazard's ag at which the demand acceleration equals q a0* (spectrum rebuilt)")]
        else:
            ls, nl = c["limit_state"], NON_LINEAR_CLAUSE
            out += [_step(f"{tag}: d_u*", c["d_u_star"], "m", f"{ULTIMATE_FRACTION[ls]:g} d0*", nl),
                    _step(f"{tag}: a*(d_u*)", c["a_u_star"], "m/s^2", "capacity curve at d_u*", nl),
                    _step(f"{tag}: T_s", c["period"], "s", f"{PERIOD_COEFFICIENT[ls]:g} pi sqrt(d_u* / a*(d_u*))", nl),
                    _step(f"{tag}: xi", c["damping"], "%", f"mechanism's damping at {ls} ({MECHANISM_DAMPING[ls]:g} %)", nl),
                    _step(f"{tag}: Se(T_s)", c.get("Se_at_period"), "m/s^2", "elastic spectrum at T_s and xi", nl),
                    _step(f"{tag}: demand d", c["demand_displacement"], "m",
                          "largest Se(T) (T / 2 pi)^2 for T <= T_s at xi", nl),
                    _step(f"{tag}: capacity ag", c["capacity_ag"], "m/s^2",
                          "the hazard's ag whose demand displacement equals d_u* (spectrum rebuilt)", nl)]
        cl = NON_LINEAR_CLAUSE if c["kind"] == "non-linear" else LINEAR_CLAUSE
        out += [_step(f"{tag}: site ag", c["demand_ag"], "m/s^2", "the hazard's ag", cl),
                _step(f"{tag}: safety index", c["safety_index"], "-",
                      "capacity / demand: " + ("q a0* / demand acceleration" if c["kind"] != "non-linear"
                                               else "d_u* / demand d"), cl),
                _step(f"{tag}: verified", c["verified"], "-", "safety index >= 1"
                      + ("" if c.get("code_check", True) else " (a convention, not a code check)"), cl)]
    return out


#: The clause each check states (NTC 2018 §8.7.1, Circolare 2019 §C8.7.1.2), in the form of the rows:
#: capacity >= demand.
CLAUSES = {
    ("activation", "ground"): "C8.7.1.2 linear, SLD: a0* >= ag S",
    ("activation", "height"): "C8.7.1.2 linear, SLD: a0* >= a_Z",
    ("linear", "ground"): "C8.7.1.2 linear, SLV: a0* >= ag S / q, i.e. q a0* >= ag S",
    ("linear", "height"): "C8.7.1.2 linear, SLV: a0* >= a_Z / q, i.e. q a0* >= a_Z",
    ("non-linear", "ground"): "C8.7.1.2 non-linear: d_u* >= demand displacement",
    ("non-linear", "height"): "C8.7.1.2 non-linear: d_u* >= demand displacement (floor spectrum)",
}
CONVENTION = "convention a0*/PGA, not a code check"


def check_rows(checks) -> list[dict]:
    """The checks as the code states them, one row each, for every printed or written table.

    ``checks``: an :class:`Assessment` or its ``checks`` (as in ``describe()["checks"]``). Each row:
    ``limit_state`` ("SLD", "SLV", "SLC"), ``kind`` ("activation", "linear", "non-linear"), ``check``
    (its name), ``where`` ("ground" or "z/H = ..."), ``demand_symbol`` / ``capacity_symbol`` (e.g.
    "ag S" / "q a0*", "d" / "d_u*"), ``demand`` and ``capacity`` in SI (``unit``: "m/s^2" for the
    activation and linear checks, "m" for the displacement check), ``safety_index`` = capacity /
    demand (>= 1 passes), ``verified`` and ``verdict`` ("verified" / "not verified"), ``code_check``
    (False: the a0*/PGA convention, outside the governing index) and ``clause``. No I/O: print with
    :func:`quantity_text` and :func:`index_text`.
    """
    out = []
    for c in getattr(checks, "checks", checks):
        at = "ground" if c.get("where", "ground") == "ground" else "height"
        if c["kind"] == "non-linear":
            dem_sym, cap_sym, unit = f"d (T_s {c['period']:.3f} s)", "d_u*", "m"
            name = "displacement"
        else:
            q = c.get("q", 1.0)
            dem_sym, cap_sym, unit = ("ag S" if at == "ground" else "a_Z"), ("a0*" if q == 1 else "q a0*"), "m/s^2"
            name = "activation (no q)" if c["kind"] == "activation" else f"linear (q = {q:g})"
        code = c.get("code_check", True)
        out.append({"limit_state": c["limit_state"], "kind": c["kind"], "check": name, "where": c.get("where", "ground"),
                    "demand_symbol": dem_sym, "capacity_symbol": cap_sym, "demand": c["demand"],
                    "capacity": c["capacity"], "unit": unit, "safety_index": c["safety_index"],
                    "verified": bool(c["verified"]), "verdict": "verified" if c["verified"] else "not verified",
                    "code_check": code, "clause": CLAUSES[(c["kind"], at)] if code else CONVENTION})
    return out


def quantity_text(value: float, unit: str) -> str:
    """An acceleration [m/s^2] as "0.6926 g (6.794 m/s^2)", a displacement [m] as "127.0 mm"; four
    significant digits, so that an index of three can be recomputed from two of them."""
    if unit == "m/s^2":
        return f"{value / G:#.4g} g ({value:#.4g} m/s^2)"
    if unit == "m":
        return f"{value * 1e3:#.4g} mm"
    return f"{value:#.4g} {unit}"


def index_text(index: float) -> str:
    """A safety index to three decimals (0.995, 1.851), with more where rounding would cross 1, so the
    printed figure never contradicts the verdict (0.9996 is not "1.000")."""
    if not math.isfinite(index):
        return "inf"
    for nd in range(3, 8):
        text = f"{index:.{nd}f}"
        if (float(text) >= 1) == (index >= 1):
            return text
    return f"{index:.8f}"


#: Labels and units of the site's description (the spectra's ``describe()``), in print order.
_SITE_FIELDS = (("code", "code", ""), ("ground", "ground type", ""), ("soil", "soil category", ""),
                ("type", "spectrum type", ""), ("topography", "topography", ""), ("ag", "ag (on rock)", "m/s^2"),
                ("pga", "PGA = ag S", "m/s^2"), ("S", "S", "-"), ("S_S", "S_S", "-"), ("S_T", "S_T", "-"),
                ("F0", "F0", "-"), ("Tc_star", "Tc*", "s"), ("C_C", "C_C", "-"), ("TB", "TB", "s"), ("TC", "TC", "s"),
                ("TD", "TD", "s"), ("damping", "damping", "%"), ("eta", "eta", "-"), ("t_max", "last period", "s"))


def site_table(site) -> list[tuple[str, str]]:
    """The site's spectrum as (quantity, value with unit) pairs, accelerations in g with m/s^2 in
    brackets; ``site``: a spectrum of :mod:`analytic.motions.spectra` or its ``describe()`` dict."""
    d = dict(site.describe()) if hasattr(site, "describe") else dict(site)
    if "pga" not in d and hasattr(site, "pga"):
        d["pga"] = site.pga
    elif "pga" not in d and isinstance(d.get("ag"), (int, float)) and isinstance(d.get("S"), (int, float)):
        d["pga"] = d["ag"] * d["S"]
    rows, seen = [], set()
    for key, label, unit in _SITE_FIELDS:
        if key in d and d[key] is not None:
            v = d[key]
            seen.add(key)
            if unit == "m/s^2":
                rows.append((label, quantity_text(float(v), unit)))
            elif isinstance(v, float):
                rows.append((label, f"{v:.4g}" + ("" if unit in ("", "-") else f" {unit}")))
            else:
                rows.append((label, str(v) + ("" if unit in ("", "-") else f" {unit}")))
    rows += [(k, str(v)) for k, v in d.items() if k not in seen]  # anything a new spectrum adds
    return rows


#: The Noh Gumbad site's preliminary hazard (0.375 g at 10 % in 50 years) as a peak ground acceleration [m/s^2].
NOH_GUMBAD_PGA = 3.67
#: The strips of the Noh Gumbad study: ultimate strength [Pa], equivalent thickness [m], width [m].
NOH_GUMBAD_FRP = (1964e6, 0.047e-3, 0.680)
#: The strips' modulus [Pa] (not published: a carbon fibre's) and the vault's masonry type (not published).
NOH_GUMBAD_FRP_MODULUS = 230e9
NOH_GUMBAD_MASONRY = "solid-brick-lime"


def monument_site():
    """The Noh Gumbad hazard as an EN 1998-1 type 1 spectrum on rock (ground A, S = 1): PGA 3.67 m/s^2."""
    return ec8(NOH_GUMBAD_PGA, "A", 1)


def monument_strips(FC: float = CONFIDENCE_FACTORS["LC1"], face: str = "extrados", masonry=None,
                    bond: BondFactors | None = None):
    """The Noh Gumbad strips designed to the guideline (carbon, outdoors, application A) on the
    assumed masonry (``masonry`` None: :data:`NOH_GUMBAD_MASONRY` at the knowledge level of ``FC``);
    ``bond``: the guideline's bond factors (None: the unverified defaults)."""
    bond = BondFactors() if bond is None else bond
    m = masonry_type(NOH_GUMBAD_MASONRY, FC, bond) if masonry is None else masonry
    return Strips(*NOH_GUMBAD_FRP, face=face, modulus=NOH_GUMBAD_FRP_MODULUS, masonry=m, FC=FC, bond=bond)


def assess_monument(monument, site, strips=None, FC: float = CONFIDENCE_FACTORS["LC1"], q: float = Q_MASONRY,
                    limit_state: str = "SLV", *, height: Height | None = None, tie=None, sld_site=None) -> list[dict]:
    """Every configuration of ``monument`` (:mod:`specimens.monuments`), unreinforced, with ``strips``
    and with ``tie`` alone (:class:`analytic.limit.ties.Tie`): the
    least mechanism of the fine cut (:func:`analytic.codes.frp.strengthened_collapse`) and its
    assessment against ``site`` (at ``height`` if given, with the SLD hazard ``sld_site`` if given);
    one row each, with its :func:`check_rows`."""
    variants: list[tuple[object, object]] = [(None, None)]
    if strips is not None:
        variants.append((strips, None))
    if tie is not None:
        variants.append((None, tie))
    rows = []
    for name, piers in monument.configurations.items():
        for s, t in variants:
            # loads along +x: the frame of the published hinge angles
            sc = strengthened_collapse(monument.arch, s, monument.density, piers, load_sign=1, tie=t)
            strengthened = s is not None or t is not None
            r = assess(sc.mechanism, site, FC, q, limit_state, height, alpha0=sc.lam,
                       extra_force=sc.extra_force if strengthened else None, sld_site=sld_site)
            by_kind = {c["kind"]: c for c in r.checks}
            row = {"configuration": name, "frp": s is not None, "tie": t is not None, "lambda": sc.lam,
                   "hinges": sc.mechanism.summary()["hinges"], "mechanism": sc.mechanism.label,
                   **{k: v for k, v in r.describe().items() if k != "capacity_curve"},
                   "check_rows": check_rows(r),
                   "safety_index_activation": by_kind["activation"]["safety_index"],
                   "activation_over_pga": r.linear.a0_star / site.pga,
                   "safety_index_linear": by_kind["linear"]["safety_index"] if "linear" in by_kind else None,
                   "safety_index_displacement": (by_kind["non-linear"]["safety_index"] if "non-linear" in by_kind
                                                 else None)}
            if s is not None:
                row["strip_hinges"] = sc.strip_hinges()
                row["crushing"] = sc.crushing(s.masonry, FC)
            if t is not None:
                row["tie_force_at_collapse_kN"] = sc.tie_lp_force / 1e3
            rows.append(row)
    return rows
