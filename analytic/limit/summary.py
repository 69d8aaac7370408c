"""All analytic multipliers of one arch in one JSON-ready dict (used by the CLI and the campaign)."""
from __future__ import annotations

import os
import warnings
from concurrent.futures import ProcessPoolExecutor

from specimens.blocks import discretise
from specimens.processes import die_with_parent


def analyse(arch, config: str, mu_joint: float, mu_base: float, effective_thickness: float = 1.0,
            min_spacing: float = 0.0, disc_kw: dict | None = None, continuous=None) -> dict:
    """All analytic multipliers of one arch as a JSON-ready dict. ``disc_kw``: the discretisation
    (:func:`specimens.blocks.discretise` keywords; its ``contact`` also applies to the continuous
    ring). ``continuous``: the arch's :func:`analytic.limit.limit_continuous.continuous_collapse` result
    at the same density, spacing, thickness and contact if the caller has it (e.g. the
    ``"continuous"`` of a :func:`multiplier_series` row); solved here otherwise (about 1 s)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.limit.two_bar import lambda_slide, lambda_two_bar, mu_star

    kw = dict(disc_kw or {})
    density = kw.get("density", 500.0)
    contact = float(kw.get("contact", 1.0))
    if kw.get("piers") is not None:
        return _analyse_on_piers(arch, config, mu_joint, mu_base, kw)
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
    disc, stands = _discrete(asm, mu_joint, mu_base)
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


def _discrete(asm, mu_joint: float, mu_base: float) -> tuple[dict, bool]:
    """The enumeration's and the LP's entries of :func:`analyse` for ``asm``, and whether both stand."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp

    kin = enumerate_mechanisms(asm)
    lp = solve_lp(asm, mu_joint, mu_base)
    return {
        "lambda_discrete": kin.lam,
        "hinges_discrete": [{"joint": j, "face": f} for j, f in kin.hinges],
        "lambda_lp": lp.lam, "lp_status": lp.message,
        "joints_lp": {name: {"state": st, **lp.forces.get(name, {})} for name, st in lp.joint_states.items()},
    }, bool(kin.stands and lp.stands)


#: Why an arch on piers has no two-bar multiplier (it models the ring on a rigid base).
RING_ONLY = "the two-bar sliding model is of the ring on a rigid base"


def _analyse_on_piers(arch, config: str, mu_joint: float, mu_base: float, kw: dict) -> dict:
    """:func:`analyse` of an arch on piers: hinges anywhere (the fine LP of
    :func:`analytic.limit.limit_piers.continuous_on_piers`), the discrete enumeration and the LP, hinges
    named by joint."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_piers import continuous_on_piers

    asm = discretise(arch, config=config, **kw)
    disc, stands = _discrete(asm, mu_joint, mu_base)
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
    with ProcessPoolExecutor(workers, initializer=die_with_parent) as ex:
        return list(ex.map(_series_row, specimens))
