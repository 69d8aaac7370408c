"""All analytic multipliers of one arch in one JSON-ready dict (used by the CLI and the campaign)."""
from __future__ import annotations

import os
import warnings

from specimens.blocks import discretise
from foundation.processes import worker_pool


def analyse(arch, config: str, mu_joint: float, mu_base: float, effective_thickness: float = 1.0,
            min_spacing: float = 0.0, disc_kw: dict | None = None, continuous=None,
            non_associative: bool = False) -> dict:
    """All analytic multipliers of one arch as a JSON-ready dict. ``disc_kw``: the discretisation
    (:func:`specimens.blocks.discretise` keywords; its ``contact`` also applies to the continuous
    ring). ``continuous``: the arch's :func:`analytic.limit.limit_continuous.continuous_collapse` result
    at the same density, spacing, thickness and contact if the caller has it (e.g. the
    ``"continuous"`` of a :func:`multiplier_series` row); solved here otherwise (about 1 s).
    ``non_associative``: also the least multiplier without dilatancy of the same blocks and frictions
    (key ``"non_associative"``, :meth:`~analytic.limit.non_associative.NonAssociativeResult.to_dict`;
    a mixed-integer program, about 1 s per catalogue arch)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.limit.two_bar import lambda_slide, lambda_two_bar, mu_star

    kw = dict(disc_kw or {})
    density = kw.get("density", 500.0)
    contact = float(kw.get("contact", 1.0))
    if kw.get("piers") is not None:
        return _analyse_on_piers(arch, config, mu_joint, mu_base, kw, non_associative)
    if continuous is not None:
        want = (float(effective_thickness), float(min_spacing), contact)
        have = (continuous.effective_thickness, continuous.min_spacing, continuous.contact)
        if have != want:
            raise ValueError(f"continuous result at (thickness, spacing, contact) {have} != {want}")
        cont = continuous
        # the warning continuous_collapse raised when it solved it, rebuilt from the result
        caught_msgs = [] if cont.converged else [f"continuous_collapse: {cont.message}"]
    else:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            cont = continuous_collapse(arch, density=density, min_spacing=min_spacing,
                                       effective_thickness=effective_thickness, contact=contact)
        caught_msgs = [str(w.message) for w in caught]
    asm = discretise(arch, config=config, **kw)
    disc, stands = _discrete(asm, mu_joint, mu_base, non_associative)
    return {
        "arch": arch.describe(),
        "config": config, "mu_joint": mu_joint, "mu_base": mu_base,
        "effective_thickness": effective_thickness, "contact": asm.contact,
        "lambda_continuous": cont.lam,
        "hinges_continuous": [{"half": "left" if h.side < 0 else "right", "angle_rad": h.psi, "face": h.face,
                               "polar_angle_rad": h.polar_about_origin(arch.with_thickness(arch.t * effective_thickness)),
                               "cut_coordinate": float(u)}
                              for h, u in zip(cont.hinges, cont.u)] if cont.layout else [],
        "continuous_converged": cont.converged, "continuous_message": cont.message,
        "warnings": caught_msgs,
        **disc,
        "lambda_two_bar": lambda_two_bar(arch, density),
        "lambda_slide_two_bar": lambda_slide(arch, min(mu_joint, 1e6), density),
        "mu_star": mu_star(arch, cont.lam, density),
        "stands": bool(cont.stands and stands),
    }


def _discrete(asm, mu_joint: float, mu_base: float, non_associative: bool = False) -> tuple[dict, bool]:
    """The enumeration's and the LP's entries of :func:`analyse` for ``asm`` (and the non-associative
    one's if asked), and whether both stand."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp

    kin = enumerate_mechanisms(asm)
    lp = solve_lp(asm, mu_joint, mu_base)
    return {
        "lambda_discrete": kin.lam,
        "hinges_discrete": [{"joint": j, "face": f} for j, f in kin.hinges],
        "lambda_lp": lp.lam, "lp_status": lp.message,
        "joints_lp": {name: {"state": st, **lp.forces.get(name, {})} for name, st in lp.joint_states.items()},
        **_non_associative(asm, mu_joint, mu_base, non_associative),
    }, bool(kin.stands and lp.stands)


def _non_associative(asm, mu_joint: float, mu_base: float, wanted: bool) -> dict:
    """``{"non_associative": ...}`` of ``asm`` when ``wanted``, else nothing."""
    if not wanted:
        return {}
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.non_associative import solve_non_associative

    return {"non_associative": solve_non_associative(asm, mu_joint, mu_base).to_dict()}


#: Why an arch on piers has no two-bar multiplier (it models the ring on a rigid base).
RING_ONLY = "the two-bar sliding model is of the ring on a rigid base"


def _analyse_on_piers(arch, config: str, mu_joint: float, mu_base: float, kw: dict,
                      non_associative: bool = False) -> dict:
    """:func:`analyse` of an arch on piers: hinges anywhere (the fine LP of
    :func:`analytic.limit.limit_piers.continuous_on_piers`), the discrete enumeration and the LP, hinges
    named by joint."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_piers import continuous_on_piers

    asm = discretise(arch, config=config, **kw)
    disc, stands = _discrete(asm, mu_joint, mu_base, non_associative)
    for h in disc["hinges_discrete"]:
        h["in_pier"] = asm.joint(h["joint"]).in_pier
    cont = continuous_on_piers(arch, asm.piers, density=asm.density, contact=asm.contact)
    converged = abs(cont.lam - cont.lam_half) <= 1e-3 * abs(cont.lam)
    return {
        "arch": arch.describe(), "piers": asm.piers.describe(arch),
        "config": config, "mu_joint": mu_joint, "mu_base": mu_base, "effective_thickness": 1.0,
        "contact": asm.contact,
        "lambda_continuous": cont.lam, "hinges_continuous": list(cont.hinges), "continuous_converged": converged,
        "continuous_message": f"hinges anywhere: LP with no sliding on the ring in {cont.n_ring} voussoirs per side and "
                              f"the piers in {cont.pier_courses} courses (halved: lambda {cont.lam_half:.5f})",
        "warnings": [] if converged else [f"the fine cut has not converged: lambda {cont.lam:.5f}, "
                                          f"{cont.lam_half:.5f} on the halved cut"],
        **disc,
        "lambda_two_bar": None, "lambda_slide_two_bar": None, "mu_star": None, "two_bar_message": RING_ONLY,
        "stands": bool(cont.stands and stands),
    }


#: The analyses of `archdem analytic` that need a two-centred arch's parameters, which a drawing's blocks lack.
ARCH_ONLY_ANALYSES = ("the continuous ring (and its --effective-thickness, --min-spacing)",
                      "the two-bar sliding model and its mu*",
                      "the linkages of the continuous ring (rock and domain take --layout discrete)")


def analyse_drawing(asm, mu_joint: float, mu_base: float, non_associative: bool = False) -> dict:
    """The limit analysis of a drawing's blocks (:class:`specimens.drawn.DrawnAssembly`, its contact
    applied) as a JSON-ready dict: the static LP at the frictions and without sliding (the LP with
    ``mu_joint`` infinite at ``mu_base`` too, the reference of the LP's mu*), each with its hinges (joint,
    face, the bodies the joint lies between; ``ground`` for a support) and the joints that slide or open;
    the four-hinge enumeration when the blocks form one chain. The arch-only entries are None
    (:data:`ARCH_ONLY_ANALYSES`). ``stands``: without sliding, the blocks stand under their own weight.
    ``non_associative``: also the non-associative multiplier at the frictions, as in :func:`analyse`."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp

    inf = float("inf")
    lp, ns = solve_lp(asm, mu_joint, mu_base), solve_lp(asm, inf, inf)
    ns_base = ns if mu_base == inf else solve_lp(asm, inf, mu_base)

    def between(name: str) -> list[str]:
        j = asm.joint(name)
        return [asm.bodies[k].name if k >= 0 else "ground" for k in (j.a, j.b)]

    def hinges(res) -> list[dict]:
        return [{"joint": k, "face": f, "between": between(k), "sliding": res.joint_states[k] == "hinge+sliding"}
                for k, f in res.hinges]

    def moving(res) -> list[dict]:
        return [{"joint": k, "state": st, "between": between(k)} for k, st in res.joint_states.items()
                if st in ("sliding", "open")]

    kin = enumerate_mechanisms(asm) if asm.is_chain else None
    return {
        "drawing": dict(asm.source), "config": asm.config, "n_blocks": asm.n_bodies, "n_joints": len(asm.joints),
        "chain": asm.is_chain, "density": asm.density, "density_from": asm.source.get("density_from", ""),
        "total_mass_kg": asm.total_mass, "contact": asm.contact, "mu_joint": mu_joint, "mu_base": mu_base,
        "gaps": [g.to_dict() for g in asm.gaps],
        "lambda_lp": lp.lam, "lp_status": lp.message, "hinges_lp": hinges(lp), "moving_lp": moving(lp),
        "joints_lp": {k: {"state": st, "between": between(k), **lp.forces.get(k, {})}
                      for k, st in lp.joint_states.items()},
        "lambda_no_sliding": ns.lam, "hinges_no_sliding": hinges(ns), "moving_no_sliding": moving(ns),
        "lambda_no_joint_sliding": ns_base.lam,
        "lambda_discrete": kin.lam if kin is not None else None,
        "hinges_discrete": [{"joint": j, "face": f, "between": between(j)} for j, f in kin.hinges] if kin else [],
        "lambda_continuous": None, "hinges_continuous": [], "lambda_two_bar": None, "lambda_slide_two_bar": None,
        "mu_star": None, "not_applicable": list(ARCH_ONLY_ANALYSES),
        "stands": bool(ns.stands), "stands_at_friction": bool(lp.stands),
        **_non_associative(asm, mu_joint, mu_base, non_associative),
    }


def _series_row(arch_spec) -> dict:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.limit.limit_discrete import enumerate_mechanisms
    from analytic.limit.two_bar import lambda_two_bar

    a = arch_spec.arch
    c = continuous_collapse(a)
    c8 = continuous_collapse(a, effective_thickness=0.8)
    return dict(id=arch_spec.id, Sh=round(a.Sh, 6), Sd=round(a.Sd, 6), Rc=a.Rc, cont=c.lam, cont08=c8.lam,
                disc=enumerate_mechanisms(discretise(a, config="glued")).lam, two_bar=lambda_two_bar(a),
                polar=c.polar_angles(a), continuous=c)


def multiplier_series(specimens) -> list[dict]:
    """Per specimen (objects with ``.id`` and ``.arch``), in order: continuous lambda at full and
    80 % thickness, discrete (glued) and two-bar lambda, continuous hinge polar angles, and the
    full-thickness :func:`~analytic.limit.limit_continuous.continuous_collapse` result itself
    (``"continuous"``, density 500 kg/m^3, no least spacing) for :func:`analyse`. Computed
    on all cores (about 1 s per arch)."""
    specimens = list(specimens)
    workers = min(len(specimens), os.cpu_count() or 1)
    if workers <= 1:
        return [_series_row(s) for s in specimens]
    with worker_pool(workers) as ex:
        return list(ex.map(_series_row, specimens))
