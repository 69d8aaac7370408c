"""The code-based assessment of one mechanism against one site (docs/physics/assessment.md): the
activation check (SLD), the linear and displacement checks of the life-safety state (SLV) or the
displacement check of SLC, the governing safety index, and the calculation trail."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

from analytic.codes.frp import Strips, masonry_type, strengthened_collapse
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
from specimens.errors import ArchdemInputError

LIMIT_STATES = ("SLD", "SLV", "SLC")


@dataclass(frozen=True)
class Assessment:
    """``linear``: alpha0, M*, e*, a0*; ``curve``: the capacity curve; ``checks``: each check's dict
    (kind, limit state, demand, capacity, safety index, verified, ``code_check``: False for the
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
                "limit_states": self.by_limit_state(), "checks": list(self.checks),
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


def _step(symbol: str, value, unit: str, formula: str) -> dict:
    return {"symbol": symbol, "value": value, "unit": unit, "formula": formula}


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
            _step("FC", lin.FC, "-", "confidence factor of the knowledge level"),
            _step("a0*", lin.a0_star, "m/s^2", "alpha0 g / (e* FC)"),
            _step("a0*/g", lin.a0_star / G, "g", "a0* / g"),
            _step("d0*", cur.d0_star, "m", f"d* where a*(d*) vanishes (curve of {cur.d0_star_from}); "
                                           f"d* = d_C / e*, a* = alpha g / (e* FC)")]
    for c in a.checks:
        tag = f"{c['limit_state']} {c['kind']}"
        if c["kind"] in ("activation", "linear"):
            q = c.get("q", 1.0)
            out += [_step(f"{tag}: demand acceleration", c["demand_acceleration"], "m/s^2",
                          "ag S of the hazard (ground) or the floor's a_Z (at a height)"),
                    _step(f"{tag}: ag activating", c.get("capacity_ag_SLD", c["capacity_ag"]), "m/s^2",
                          "the hazard's ag at which the demand acceleration equals a0* (spectrum rebuilt)"),
                    _step(f"{tag}: q", q, "-", "behaviour factor (1: activation)"),
                    _step(f"{tag}: capacity ag", c["capacity_ag"], "m/s^2", "q x ag activating")]
        else:
            ls = c["limit_state"]
            out += [_step(f"{tag}: d_u*", c["d_u_star"], "m", f"{ULTIMATE_FRACTION[ls]:g} d0*"),
                    _step(f"{tag}: a*(d_u*)", c["a_u_star"], "m/s^2", "capacity curve at d_u*"),
                    _step(f"{tag}: T_s", c["period"], "s", f"{PERIOD_COEFFICIENT[ls]:g} pi sqrt(d_u* / a*(d_u*))"),
                    _step(f"{tag}: xi", c["damping"], "%", f"mechanism's damping at {ls} ({MECHANISM_DAMPING[ls]:g} %)"),
                    _step(f"{tag}: Se(T_s)", c.get("Se_at_period"), "m/s^2", "elastic spectrum at T_s and xi"),
                    _step(f"{tag}: demand d", c["demand_displacement"], "m",
                          "largest Se(T) (T / 2 pi)^2 for T <= T_s at xi"),
                    _step(f"{tag}: capacity ag", c["capacity_ag"], "m/s^2",
                          "the hazard's ag whose demand displacement equals d_u* (spectrum rebuilt)")]
        out += [_step(f"{tag}: site ag", c["demand_ag"], "m/s^2", "the hazard's ag"),
                _step(f"{tag}: safety index", c["safety_index"], "-", "capacity ag / site ag"),
                _step(f"{tag}: verified", c["verified"], "-", "safety index >= 1"
                      + ("" if c.get("code_check", True) else " (a convention, not a code check)"))]
    return out


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


def monument_strips(FC: float = CONFIDENCE_FACTORS["LC1"], face: str = "extrados", masonry=None):
    """The Noh Gumbad strips designed to the guideline (carbon, outdoors, application A) on the
    assumed masonry (``masonry`` None: :data:`NOH_GUMBAD_MASONRY` at the knowledge level of ``FC``)."""
    m = masonry_type(NOH_GUMBAD_MASONRY, FC) if masonry is None else masonry
    return Strips(*NOH_GUMBAD_FRP, face=face, modulus=NOH_GUMBAD_FRP_MODULUS, masonry=m, FC=FC)


def assess_monument(monument, site, strips=None, FC: float = CONFIDENCE_FACTORS["LC1"], q: float = Q_MASONRY,
                    limit_state: str = "SLV") -> list[dict]:
    """Every configuration of ``monument`` (:mod:`specimens.monuments`), unreinforced and with
    ``strips``: the least mechanism of the fine cut (:func:`analytic.codes.frp.strengthened_collapse`) and its
    assessment against ``site``; one row each."""
    rows = []
    for name, piers in monument.configurations.items():
        for s in (None, strips) if strips is not None else (None,):
            # loads along +x: the frame of the published hinge angles
            sc = strengthened_collapse(monument.arch, s, monument.density, piers, load_sign=1)
            r = assess(sc.mechanism, site, FC, q, limit_state, alpha0=sc.lam,
                       extra_force=sc.extra_force if s is not None else None)
            by_kind = {c["kind"]: c for c in r.checks}
            row = {"configuration": name, "frp": s is not None, "lambda": sc.lam,
                   "hinges": sc.mechanism.summary()["hinges"], "mechanism": sc.mechanism.label,
                   **{k: v for k, v in r.describe().items() if k != "capacity_curve"},
                   "safety_index_activation": by_kind["activation"]["safety_index"],
                   "activation_over_pga": r.linear.a0_star / site.pga,
                   "safety_index_linear": by_kind["linear"]["safety_index"] if "linear" in by_kind else None,
                   "safety_index_displacement": (by_kind["non-linear"]["safety_index"] if "non-linear" in by_kind
                                                 else None)}
            if s is not None:
                row["strip_hinges"] = sc.strip_hinges()
                row["crushing"] = sc.crushing(s.masonry, FC)
            rows.append(row)
    return rows
