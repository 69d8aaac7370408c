"""Impact at the return to rest (docs/physics/dynamics.md#5-impact).

When a rocking mechanism comes back to ``phi = 0`` its hinges close and a new mechanism,
opening the other way, takes over. No sliding, no bouncing, instantaneous impulses at the new
hinges only, positions unchanged. With ``Psi_b``, ``Psi_a`` the velocity maps (per unit rate of
each mechanism's own coordinate) and ``M`` the mass matrix of the free bodies::

    phi'_after = (Psi_a^T M Psi_b) / (Psi_a^T M Psi_a) phi'_before

The products ``Psi_a^T M Psi_b`` are computed as the mass-weighted inner product of the two
rigid velocity fields over the material: on a region of mass ``m``, first moments
``S = (S_x, S_y)`` and inertia about the origin ``J_O``, the fields ``v = v_o + w J p`` and
``u = u_o + z J p`` give ``m v_o.u_o + (z v_o + w u_o).(J S) + w z J_O`` (``J S = (-S_y, S_x)``).
When the two mechanisms cut the material differently (another hinge layout) the product is
summed over the common refinement of their regions (regions are intervals of a material
coordinate); with the same regions it is the block-diagonal product of the spec.

The energy restitution ``e = sqrt(T_after / T_before)`` is what is reported. The post-impact
mechanism is the mechanism's first impact candidate (face-swapped layout, other block corner)
if it is admissible and opens the other way; otherwise the admissible candidate that keeps the
most energy. A user-given ``e`` is applied as the energy ratio ``e^2``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from analytic.rocking.mechanism import Mechanism, RigidField
from foundation.errors import ArchdemInputError


def _pair(a: RigidField, b: RigidField, moments: tuple[float, float, float, float]) -> float:
    m, Sx, Sy, J = moments
    jsx, jsy = -Sy, Sx
    return (m * (a.v_o[0] * b.v_o[0] + a.v_o[1] * b.v_o[1])
            + b.omega * (a.v_o[0] * jsx + a.v_o[1] * jsy)
            + a.omega * (b.v_o[0] * jsx + b.v_o[1] * jsy)
            + a.omega * b.omega * J)


def _is_interval(r: object) -> bool:
    return isinstance(r, tuple) and len(r) == 2 and all(isinstance(x, float) for x in r)


def field_inner(fa: tuple[RigidField, ...], fb: tuple[RigidField, ...], moments) -> float:
    """``Psi_a^T M Psi_b`` of two lists of rigid fields; ``moments(region) -> (m, Sx, Sy, J_O)``.

    Regions equal in both lists pair directly; interval regions ``(u0, u1)`` are refined.
    Material outside every region of a list is at rest in that mechanism.
    """
    if all(_is_interval(f.region) for f in fa + fb):
        cuts = sorted({x for f in fa + fb for x in f.region})
        total = 0.0
        for u0, u1 in zip(cuts[:-1], cuts[1:]):
            if u1 - u0 <= 1e-14:
                continue
            a = next((f for f in fa if f.region[0] <= u0 and u1 <= f.region[1]), None)
            b = next((f for f in fb if f.region[0] <= u0 and u1 <= f.region[1]), None)
            if a is not None and b is not None:
                total += _pair(a, b, moments((u0, u1)))
        return total
    total = 0.0
    rb = {f.region: f for f in fb}
    for a in fa:
        if a.region in rb:
            total += _pair(a, rb[a.region], moments(a.region))
    regions_b = {f.region for f in fb}
    if not {f.region for f in fa} <= regions_b and not regions_b <= {f.region for f in fa}:
        raise ValueError("the two mechanisms cut the material differently and their regions cannot be refined")
    return total


@dataclass(frozen=True)
class ImpactTransition:
    """Post-impact mechanism and the velocity ratio ``phi'_after / |phi'_before|`` (> 0).

    ``e``: energy restitution of the momentum balance; ``e_applied``: the one used (differs when
    a restitution is given by the user); ``rule``: how the mechanism was chosen.
    """

    after: Mechanism
    ratio: float
    e: float
    e_applied: float
    rule: str


def momentum_ratio(before: Mechanism, after: Mechanism) -> float:
    """``(Psi_a^T M Psi_b) / (Psi_a^T M Psi_a)``: ``phi'_after / phi'_before`` (negative for a
    proper impact: ``phi'_before < 0`` closes the old mechanism, ``phi'_after > 0`` opens the new one)."""
    mom = before.region_moments
    fa, fb = after.rest_fields(), before.rest_fields()
    return field_inner(fa, fb, mom) / field_inner(fa, fa, mom)


def energy_restitution(before: Mechanism, after: Mechanism) -> float:
    """``e = sqrt(T_after / T_before)`` of the momentum balance (0 if the new mechanism cannot open)."""
    r = momentum_ratio(before, after)
    if r >= 0:
        return 0.0
    return abs(r) * math.sqrt(after.M0 / before.M0)


def post_impact(before: Mechanism, restitution: float | None = None) -> ImpactTransition:
    """The mechanism that takes over after ``before`` closes (docs/physics/dynamics.md#5-impact).

    ``restitution``: ``None`` (momentum balance) or a user energy restitution in [0, 1].
    """
    if restitution is not None and not (0.0 <= restitution <= 1.0):
        raise ArchdemInputError(f"restitution must be in [0, 1], got {restitution!r}")
    # cached on the mechanism (the search for the post-impact mechanism may be costly)
    cache = before.__dict__.setdefault("_post_impact_cache", {})
    key = None if restitution is None else float(restitution)
    if key not in cache:
        tr = _post_impact(before, restitution)
        # close the cycle: if the new mechanism is the one ``before`` came from, reuse that object
        origin = before.__dict__.get("_came_from")
        if origin is not None and hasattr(origin, "same_as") and origin.same_as(tr.after):
            tr = ImpactTransition(origin, tr.ratio, tr.e, tr.e_applied, tr.rule)
        else:
            tr.after.__dict__.setdefault("_came_from", before)
        cache[key] = tr
    return cache[key]


def _post_impact(before: Mechanism, restitution: float | None) -> ImpactTransition:
    cands = list(before.impact_candidates())
    if not cands:
        raise ValueError(f"{before.label}: no post-impact mechanism")
    first = cands[0]
    if first.admissible and first.direction != before.direction:
        e = energy_restitution(before, first)
        if e > 0:
            return _transition(before, first, e, "face-swapped" if hasattr(first, "hinges") else "default", restitution)
    more = getattr(before, "more_impact_candidates", None)
    if more is not None:
        cands = cands + list(more())
    scored = []
    for k, c in enumerate(cands):
        if not c.admissible or c.direction == before.direction:
            continue
        try:
            e = energy_restitution(before, c)
        except ValueError:
            continue
        if e > 0:
            scored.append((e, c, "max-energy"))
    if not scored:
        # no admissible mechanism can take the motion over: the impact absorbs all kinetic energy
        ok = [c for c in cands if c.admissible and c.direction != before.direction]
        if not ok:
            raise ValueError(f"{before.label}: no admissible post-impact mechanism")
        return _transition(before, ok[0], 0.0, "stops", restitution if restitution is None else 0.0)
    e, after, rule = max(scored, key=lambda s: s[0])
    return _transition(before, after, e, rule, restitution)


def _transition(before: Mechanism, after: Mechanism, e: float, rule: str, restitution: float | None) -> ImpactTransition:
    e_applied = e if restitution is None else float(restitution)
    # phi'_after = e_applied sqrt(M_b / M_a) |phi'_before|  (T_after = e^2 T_before)
    ratio = e_applied * math.sqrt(before.M0 / after.M0)
    return ImpactTransition(after, ratio, e, e_applied, rule if restitution is None else rule + "+user-e")
