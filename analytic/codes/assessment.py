"""The code-based assessment of one mechanism against one site (docs/physics/assessment.md): the
linear check and the displacement check of the limit state, and the governing safety index."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from analytic.codes.frp import strengthened_collapse
from analytic.codes.kinematic import (
    CONFIDENCE_FACTORS,
    Q_MASONRY,
    CapacityCurve,
    Height,
    LinearKinematic,
    capacity_curve,
    linear_kinematic,
)
from analytic.motions.spectra import ec8
from specimens.errors import ArchdemInputError


@dataclass(frozen=True)
class Assessment:
    """``linear``: alpha0, M*, e*, a0*; ``curve``: the capacity curve; ``checks``: each check's dict
    (kind, limit state, demand, capacity, safety index, verified); ``safety_index``: the least."""

    linear: LinearKinematic
    curve: CapacityCurve
    checks: tuple[dict, ...]

    @property
    def safety_index(self) -> float:
        return min(c["safety_index"] for c in self.checks)

    @property
    def verified(self) -> bool:
        return all(c["verified"] for c in self.checks)

    def describe(self) -> dict:
        ls = self.checks[-1]["limit_state"]
        return {**self.linear.describe(), "d0_star": self.curve.d0_star,
                "du_star": next(c["d_u_star"] for c in self.checks if c["kind"] == "non-linear"),
                "limit_state": ls, "safety_index": self.safety_index, "verified": self.verified,
                "checks": list(self.checks), "capacity_curve": self.curve.describe()}


def assess(mech, site, FC: float = CONFIDENCE_FACTORS["LC1"], q: float = Q_MASONRY, limit_state: str = "SLV",
           height: Height | None = None, alpha0: float | None = None,
           extra_force: Callable[[float], float] | None = None) -> Assessment:
    """Assess ``mech`` (a one-degree-of-freedom mechanism) against the elastic spectrum ``site`` of
    ``limit_state`` (SLV: the linear check with ``q`` and the displacement check; SLC: the
    displacement check), at ground level or at ``height``; ``alpha0`` and ``extra_force``: the
    multiplier and the generalised force of strips, when they act (:mod:`analytic.codes.frp`)."""
    ls = str(limit_state).upper()
    if ls not in ("SLV", "SLC"):
        raise ArchdemInputError(f"limit state must be SLV or SLC, got {limit_state!r}")
    lin = linear_kinematic(mech, FC, alpha0=alpha0)
    curve = capacity_curve(mech, FC, extra_force=extra_force)
    checks = (lin.check(site, q, height),) if ls == "SLV" else ()
    checks += (curve.check(site, ls, height),)
    return Assessment(lin, curve, checks)


#: The Noh Gumbad site's preliminary hazard (0.375 g at 10 % in 50 years) as a peak ground acceleration [m/s^2].
NOH_GUMBAD_PGA = 3.67
#: The strips of the Noh Gumbad study: ultimate strength [Pa], equivalent thickness [m], width [m].
NOH_GUMBAD_FRP = (1964e6, 0.047e-3, 0.680)


def monument_site():
    """The Noh Gumbad hazard as an EN 1998-1 type 1 spectrum on rock (ground A, S = 1): PGA 3.67 m/s^2."""
    return ec8(NOH_GUMBAD_PGA, "A", 1)


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
            r = assess(sc.mechanism, site, FC, q, limit_state, alpha0=sc.lam, extra_force=sc.strip_force)
            by_kind = {c["kind"]: c for c in r.checks}
            rows.append({"configuration": name, "frp": s is not None, "lambda": sc.lam,
                         "hinges": sc.mechanism.summary()["hinges"], "mechanism": sc.mechanism.label,
                         **{k: v for k, v in r.describe().items() if k != "capacity_curve"},
                         "safety_index_linear": by_kind["linear"]["safety_index"] if "linear" in by_kind else None,
                         "safety_index_displacement": by_kind["non-linear"]["safety_index"]})
    return rows
