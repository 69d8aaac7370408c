"""Limit analysis of an arch on piers with hinges anywhere along the ring and the piers
(docs/physics/limit-analysis.md#13-arches-on-piers).

The continuous analysis of the ring alone (:mod:`analytic.limit.limit_continuous`) searches radial cuts of
one ring; on piers a hinge may also open at any height of a pier (no-tension masonry cracks where
it must). Both are reached by the static LP with no sliding (= the kinematic minimum) on a fine
cut: the ring in ``n_ring`` voussoirs per side, each pier in virtual courses about a quarter of the
ring's thickness tall (its real course joints among them). Halving the cut gives the error
estimate that is reported.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

from analytic.limit.limit_discrete import solve_lp
from specimens.blocks import DEFAULT_DENSITY, discretise
from specimens.piers import MAX_COURSES

#: Voussoirs per side of the fine ring (96: within 1e-4 of the continuous ring's lambda on the catalogue).
N_RING = 96
#: Virtual courses per ring thickness of pier height (a pier hinge is placed within t / 8).
COURSES_PER_T = 4


@dataclass(frozen=True)
class PiersCollapse:
    """``lam``: the multiplier; ``hinges``: per hinge ``joint``, ``face``, and ``angle_rad`` (polar angle
    of a ring cut about its half's centre, with ``half``) or ``height_m`` (above the ground, in
    ``pier`` left/right); ``lam_half``: the same analysis on the cut halved (``lam - lam_half``
    estimates the cut's error); ``n_ring`` and ``pier_courses``: the fine cut."""

    lam: float
    hinges: tuple[dict, ...]
    lam_half: float
    n_ring: int
    pier_courses: int
    message: str

    @property
    def stands(self) -> bool:
        return self.lam >= 0


def fine_cut(arch, piers, n_ring: int, density: float, contact: float, refine: int = 1):
    """The fine cut of the arch on ``piers``: ``n_ring / refine`` voussoirs per side, virtual pier courses
    about a quarter of the ring's thickness tall."""
    t_courses = math.ceil(COURSES_PER_T * piers.height / arch.t / piers.courses) // refine
    per = max(1, min(MAX_COURSES // piers.courses, t_courses))
    fine = replace(piers, courses=piers.courses * per)
    return discretise(arch, n_voussoirs=max(2, n_ring // refine), config="free", density=density, contact=contact,
                      piers=fine)


def continuous_on_piers(arch, piers, density: float = DEFAULT_DENSITY, contact: float = 1.0,
                        n_ring: int = N_RING) -> PiersCollapse:
    """Minimum multiplier of an arch on ``piers`` with hinges anywhere (no sliding), by the static LP
    on the fine cut (module doc)."""
    asm = fine_cut(arch, piers, n_ring, density, contact, 1)
    lp = solve_lp(asm, math.inf, math.inf)
    half = solve_lp(fine_cut(arch, piers, n_ring, density, contact, 2), math.inf, math.inf)
    hinges = []
    for name, face in lp.hinges:
        j = asm.joint(name)
        if j.in_pier:
            hinges.append({"joint": name, "face": face, "pier": "left" if j.side < 0 else "right",
                           "height_m": float(j.p_i[1] + piers.height)})
        else:
            hinges.append({"joint": name, "face": face, "half": "left" if j.side < 0 else "right",
                           "angle_rad": float(j.psi)})
    pier_courses = sum(1 for b in asm.bodies if b.name.startswith("LP"))
    return PiersCollapse(lp.lam, tuple(hinges), half.lam, int(asm.n_voussoirs), pier_courses, lp.message)
