"""A tilt test beside the limit analysis of the same blocks: the one row of every tilt validation
(the campaign's tilt step, ``archdem compare-engines``, ``benchmarks/validate_dem.py``).

The reference is the static LP (:func:`analytic.limit.limit_discrete.solve_lp`) of the blocks the DEM
simulated. A test that prevents sliding (both frictions at least ``NO_SLIDING_MU``) is checked
against the LP with infinite friction, which is exact for rocking; with Coulomb friction the
associative LP is no bound and is reported for orientation (docs/validation.md).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable

from specimens.constants import NO_SLIDING_MU

HINGE_STATES = ("hinge", "hinge+slide")
#: A tilt further than this from the LP of its own blocks warns: the tolerance the tilt is validated to
#: on the catalogue and on arches outside it (docs/validation.md#4-no-sliding-tilt-against-the-lp, #20).
LP_TOLERANCE = 0.03


@dataclass(frozen=True)
class TiltCheck:
    """One tilt test (``lam``, ``mode``, hinge joints ``(joint, face)``, slipping joints) and the LP
    multiplier ``lp_lam`` and hinges of the same blocks; ``wall_s`` [s]."""

    id: str
    config: str
    engine: str
    mu_joint: float
    mu_base: float
    lam: float
    mode: str
    hinges: tuple[tuple[str, str], ...]
    slides: tuple[str, ...]
    n_sims: int
    wall_s: float
    lp_lam: float
    lp_hinges: tuple[tuple[str, str], ...]

    @property
    def no_sliding(self) -> bool:
        return prevents_sliding(self.mu_joint, self.mu_base)

    @property
    def rel_err(self) -> float:
        """(lambda - lambda_LP) / lambda_LP: an error when sliding is prevented, else orientation only."""
        if not (math.isfinite(self.lp_lam) and self.lp_lam > 0):
            return float("nan")
        return (self.lam - self.lp_lam) / self.lp_lam

    @property
    def err_pct(self) -> float:
        """:attr:`rel_err` in percent (computed as the campaign's tables always were, so they stay bit-identical)."""
        return 100 * (self.lam - self.lp_lam) / self.lp_lam

    @property
    def hinges_match_lp(self) -> bool:
        return tuple(self.hinges) == tuple(self.lp_hinges)


def prevents_sliding(mu_joint: float, mu_base: float) -> bool:
    return mu_joint >= NO_SLIDING_MU and mu_base >= NO_SLIDING_MU


def reference_lp(assembly, mu_joint: float, mu_base: float):
    """The LP a tilt test at these frictions is checked against (module docstring)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import solve_lp

    if prevents_sliding(mu_joint, mu_base):
        return solve_lp(assembly, math.inf, math.inf)
    return solve_lp(assembly, mu_joint, mu_base)


def joint_sets(states: Iterable[tuple[str, str, str]]) -> tuple[tuple[tuple[str, str], ...], tuple[str, ...]]:
    """Hinges ``(joint, face)`` and slipping joints of ``(joint, state, face)`` triples."""
    states = list(states)
    hinges = tuple((j, f) for j, st, f in states if st in HINGE_STATES)
    slides = tuple(j for j, st, _ in states if "slide" in st)
    return hinges, slides


def check(label: str, assembly, engine: str, mu_joint: float, mu_base: float, lam: float, mode: str,
          states: Iterable[tuple[str, str, str]], n_sims: int = 0, wall_s: float = float("nan"),
          lp=None) -> TiltCheck:
    """The row of a tilt answer (``states``: ``(joint, state, face)`` of its joints at collapse);
    ``lp``: the :func:`reference_lp` if already solved."""
    lp = reference_lp(assembly, mu_joint, mu_base) if lp is None else lp
    hinges, slides = joint_sets(states)
    return TiltCheck(label, str(assembly.parameters().get("config", "")), engine, float(mu_joint), float(mu_base),
                     float(lam), str(mode), hinges, slides, int(n_sims), float(wall_s), float(lp.lam),
                     tuple(tuple(h) for h in lp.hinges))


def check_result(result, assembly, lp=None) -> TiltCheck:
    """The row of a :class:`dem.experiments.tilt.run.TiltResult` of ``assembly``."""
    st = result.settings
    return check(result.label, assembly, st.engine, st.mu_joint, st.mu_base, result.lam, result.mode,
                 ((j.joint, j.state, j.face) for j in result.joints), result.n_sims, result.wall_s, lp)


@dataclass(frozen=True)
class LpCheck:
    """A tilt's ``lam`` beside the static LP of the same blocks (same joints, same effective contact,
    same frictions; infinite friction when both prevent sliding): the check every tilt carries.

    ``lp_slides``: the LP's mechanism slides at some joint (the associative LP is then no bound);
    ``law``: the joints' contact law (the rigid-block LP is no bound for compliant joints either)."""

    label: str
    lam: float
    lp_lam: float
    lp_hinges: tuple[tuple[str, str], ...]
    lp_slides: bool
    no_sliding: bool
    law: str = "rigid"
    dem_hinges: tuple[tuple[str, str], ...] = ()
    tolerance: float = LP_TOLERANCE

    @property
    def rel_err(self) -> float:
        """(lambda - lambda_LP) / lambda_LP; NaN without an LP."""
        if not (math.isfinite(self.lp_lam) and self.lp_lam > 0 and math.isfinite(self.lam)):
            return float("nan")
        return (self.lam - self.lp_lam) / self.lp_lam

    @property
    def agrees(self) -> bool | None:
        """Within :attr:`tolerance` of the LP; None without an LP to compare with."""
        e = self.rel_err
        return None if math.isnan(e) else abs(e) <= self.tolerance

    @property
    def cause(self) -> str:
        """The likely cause of a departure (empty when the two agree)."""
        if self.agrees is not False:
            return ""
        if self.law != "rigid":
            return "compliant joints deform before they hinge, which the rigid-block LP leaves out"
        if self.rel_err < 0 and self.lp_slides:
            return ("the LP's mechanism slides, and the associative LP overestimates a sliding collapse "
                    "(no bound with Coulomb friction)")
        other = "" if not self.dem_hinges or self.dem_hinges == self.lp_hinges else (
            f"; the DEM hinges ({_hinge_text(self.dem_hinges)}) are not the LP's ({_hinge_text(self.lp_hinges)})")
        if self.rel_err < 0:
            return ("the engine tipped early: near the least thickness the collapse is sensitive to the contact "
                    "geometry and the solver's settling; rerun with --engine mujoco or a smaller --dt" + other)
        return ("the engine held above the exact limit: a slow mechanism not detected within the hold; rerun with "
                "--full-hold or --engine mujoco" + other)

    @property
    def warning(self) -> str:
        """One line naming the arch, both values and the likely cause; empty when they agree."""
        if self.agrees is not False:
            return ""
        return (f"{self.label}: tilt lambda {self.lam:.4f} is {abs(100 * self.rel_err):.1f} % "
                f"{'below' if self.rel_err < 0 else 'above'} the LP of the same blocks ({self.lp_lam:.4f}); "
                f"likely cause: {self.cause}")

    def to_dict(self) -> dict:
        """The JSON of the check (``lp_lambda``, ``error_pct``, ``agrees``, ``warning``, ...)."""
        e = self.rel_err
        return {"lp_lambda": self.lp_lam, "error_pct": None if math.isnan(e) else 100 * e, "agrees": self.agrees,
                "tolerance_pct": 100 * self.tolerance, "lp_hinges": [list(h) for h in self.lp_hinges],
                "lp_slides": self.lp_slides, "lp_friction": "none (no sliding)" if self.no_sliding else "same as the tilt",
                "warning": self.warning}


def _hinge_text(hinges) -> str:
    return " ".join(f"{j} {f}" for j, f in hinges)


def lp_slides(lp) -> bool:
    """True if the collapse mechanism of the LP ``lp`` slides at some joint (the associative LP is then no bound)."""
    return any("sliding" in str(v) for v in lp.joint_states.values())


def lp_check_of(row: TiltCheck, lp, law: str = "rigid") -> LpCheck:
    """The check of a tilt validation row (:func:`check`) against its LP ``lp`` (the one it was checked against)."""
    return LpCheck(row.id, row.lam, row.lp_lam, row.lp_hinges, lp_slides(lp), row.no_sliding, law, row.hinges)


def lp_check(result, assembly, lp=None) -> LpCheck | None:
    """The check of a :class:`dem.experiments.tilt.run.TiltResult` of ``assembly`` against :func:`reference_lp`
    (``lp`` if already solved); None without blocks to solve (a model built without an assembly)."""
    if assembly is None:
        return None
    st = result.settings
    lp = reference_lp(assembly, st.mu_joint, st.mu_base) if lp is None else lp
    dem = tuple((j.joint, j.face) for j in result.joints if j.state in HINGE_STATES)
    return LpCheck(str(result.label), float(result.lam), float(lp.lam), tuple(tuple(h) for h in lp.hinges), lp_slides(lp),
                   prevents_sliding(st.mu_joint, st.mu_base), st.contact_law, dem)


#: The non-associative mechanism's joint states in the DEM's words (both say how a joint moves).
NA_JOINT_STATE = {"hinge-intrados": "hinge", "hinge-extrados": "hinge", "sliding": "slide",
                  "hinge+sliding": "hinge+slide", "open": "open"}


def na_joints(na) -> dict[str, str]:
    """The moving joints of a non-associative collapse (:class:`analytic.limit.non_associative.NonAssociativeResult`),
    each as the DEM names its motion (``hinge``, ``slide``, ``hinge+slide``, ``open``)."""
    return {k: NA_JOINT_STATE[v] for k, v in na.joint_states.items() if v != "closed"}


def same_mechanism(dem_joints: Iterable, na) -> bool:
    """True if a tilt's moving joints (``(joint, state)`` pairs, or objects with ``.joint`` and ``.state``)
    are those of the non-associative collapse ``na``, each moving the same way."""
    pairs = (x if isinstance(x, (tuple, list)) else (x.joint, x.state) for x in dem_joints)
    return {j: st for j, st in pairs if st != "closed"} == na_joints(na)
