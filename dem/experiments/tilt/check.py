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
