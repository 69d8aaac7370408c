"""Limit analysis of an arch strengthened with FRP strips (docs/physics/assessment.md#5-frp-strips).

Strips bonded along the ring's extrados (or intrados), from springing to springing, cross every
joint of the ring; at a joint whose hinge opens on the strips' side they carry their design force
``T = f_fd t_f w_f``. In the static LP that is a tension down to ``-T`` allowed at the joint's end on
that side; in the kinematic form it is the work ``T c |dtheta|`` of a hinge turning by
``dtheta`` with the strip a distance ``c`` (the joint's depth) from the hinge. The strips end at the
springing joints (no anchorage into the base or the piers). Sliding is not considered (mu = inf).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from specimens.blocks import DEFAULT_DENSITY, discretise
from specimens.errors import ArchdemInputError

#: Partial factor on the strips' ultimate strength when no design strength is given (rupture).
GAMMA_FRP = 1.1
#: Voussoirs per side of the fine ring on which the strengthened mechanism is sought.
N_RING = 96


@dataclass(frozen=True)
class Strips:
    """FRP strips on one ``face`` ("extrados"/"intrados") of the ring: ultimate tensile ``strength``
    [Pa], ``thickness`` [m] (equivalent dry-fibre thickness), total ``width`` [m] across the ring, and
    the ``design_strength`` [Pa] (debonding or rupture, e.g. from a bond design rule; None:
    ``strength / GAMMA_FRP``)."""

    strength: float
    thickness: float
    width: float
    face: str = "extrados"
    design_strength: float | None = None

    def __post_init__(self) -> None:
        for name, v, hi in (("strength", self.strength, 1e11), ("thickness", self.thickness, 0.1),
                            ("width", self.width, 100.0)):
            if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and 0 < v <= hi):
                raise ArchdemInputError(f"FRP {name} must be a positive number up to {hi:g} (SI), got {v!r}")
        if self.face not in ("extrados", "intrados"):
            raise ArchdemInputError(f"FRP face must be extrados or intrados, got {self.face!r}")
        fd = self.design_strength
        if fd is not None and not (isinstance(fd, (int, float)) and math.isfinite(fd) and 0 < fd <= self.strength):
            raise ArchdemInputError(f"FRP design strength must be in (0, strength = {self.strength / 1e6:g} MPa], "
                                    f"got {fd!r}")

    @property
    def design_stress(self) -> float:
        """``f_fd`` [Pa]."""
        return float(self.design_strength if self.design_strength is not None else self.strength / GAMMA_FRP)

    @property
    def force(self) -> float:
        """Design force ``T = f_fd t_f w_f`` [N] of the strips crossing one joint."""
        return self.design_stress * self.thickness * self.width

    def describe(self) -> dict:
        return {"face": self.face, "strength_MPa": self.strength / 1e6, "thickness_mm": self.thickness * 1e3,
                "width_mm": self.width * 1e3, "design_strength_MPa": self.design_stress / 1e6, "force_N": self.force}


def strip_joint(joint) -> bool:
    """Strips cross the ring's joints, not the springings nor the piers."""
    return not joint.in_pier and joint.name not in ("L0", "R0")


def tension_of(assembly, strips: Strips) -> np.ndarray:
    """(n_joints, 2) tension [N] each joint carries at its intrados / extrados end."""
    k = 1 if strips.face == "extrados" else 0
    T = np.zeros((len(assembly.joints), 2))
    for j in assembly.joints:
        if strip_joint(j):
            T[j.index, k] = strips.force
    return T


@dataclass(frozen=True)
class StrengthenedCollapse:
    """``lam``: multiplier of the strengthened arch (under the loads of ``strengthened_collapse``);
    ``hinges``: (joint, face) left to right; ``mechanism``: its four-bar; ``assembly``: the fine cut;
    ``strips``."""

    lam: float
    hinges: tuple[tuple[str, str], ...]
    mechanism: object  # a FourBar or a RigidRotation
    assembly: object
    strips: Strips | None

    def strip_force(self, phi: float) -> float:
        """Generalised force ``W'(phi)`` [J/rad] of the strips resisting the mechanism at rotation ``phi``:
        ``sum T c_k cos(dtheta_k / 2) d(dtheta_k)/dphi sign(dtheta_k)`` over the hinges opening on their side."""
        st = self.mechanism.body_states(phi)
        th = [0.0] + [b.theta for b in st] + [0.0]  # hinge k joins body k-1 (or the ground) to body k
        w = [0.0] + [b.dtheta for b in st] + [0.0]
        out = 0.0
        if self.strips is None:
            return 0.0
        for k, (name, face) in enumerate(self.hinges):
            j = self.assembly.joint(name)
            if not strip_joint(j) or face == self.strips.face:
                continue
            c = float(np.linalg.norm(j.contact_points[1] - j.contact_points[0]))
            rel, drel = th[k + 1] - th[k], w[k + 1] - w[k]
            sign = math.copysign(1.0, drel if abs(rel) < 1e-12 else rel)  # the gap opens either way of turning
            out += self.strips.force * c * math.cos(rel / 2) * sign * drel
        return out


def strengthened_collapse(arch, strips: Strips | None, density: float = DEFAULT_DENSITY, piers=None,
                          n_ring: int = N_RING, load_sign: int = -1) -> StrengthenedCollapse:
    """The strengthened arch's (on ``piers`` or not; ``strips`` None: unreinforced) least multiplier
    and mechanism: the static LP with the strips' tension on the fine cut (``n_ring`` voussoirs per side; on piers the cut of
    :func:`analytic.limit.limit_piers.continuous_on_piers`), and the mechanism through its hinges (four, or
    one when the strips hold the ring whole and it turns on a springing); ``load_sign`` -1: loads along
    -x (those of a positive ground acceleration), +1 along +x."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import solve_lp
    from analytic.rocking.linkage import four_bar_through

    if getattr(arch, "arch", True) is None:  # a drawn assembly (specimens.drawn): no ring to cut finely
        raise ArchdemInputError("FRP strips are modelled on the fine cut of a two-centred ring; a drawing of blocks "
                                "has no ring to cut: assess it without --frp")
    if piers is None:
        asm = discretise(arch, n_voussoirs=n_ring, config="free", density=density)
    else:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.limit.limit_piers import fine_cut

        asm = fine_cut(arch, piers, n_ring, density, 1.0)
    lp = solve_lp(asm, math.inf, math.inf, load_sign=load_sign, tension=None if strips is None else tension_of(asm, strips))
    if not lp.success:
        raise ArchdemInputError(f"strengthened arch: {lp.message}")
    if len(lp.hinges) not in (1, 4):
        raise ArchdemInputError(f"the strengthened arch's mechanism has {len(lp.hinges)} hinges, neither one nor "
                                f"four ({', '.join(f'{n}:{f}' for n, f in lp.hinges)})")
    fb = four_bar_through(asm, lp.hinges, name="four-bar (fine cut)" if strips is None else "four-bar (with FRP)")
    return StrengthenedCollapse(float(lp.lam), lp.hinges, fb, asm, strips)
