"""Limit analysis with Coulomb friction without dilatancy (non-associative): the least collapse multiplier.

docs/physics/limit-analysis.md#14-coulomb-friction-without-dilatancy. The associative LP of
:mod:`analytic.limit.limit_discrete` lets a sliding joint open by ``mu |slip|``; dry joints slide flat.
Here a collapse is a state in which equilibrium, the friction and no-tension limits, a mechanism
(openings ``>= 0``, no dilatancy) and the flow rule (a force only where its joint end is closed; slip
only where the shear is at ``mu N`` and against it) hold together. The least ``lambda`` of such a state
is found exactly by a mixed-integer program (HiGHS through ``scipy.optimize.milp``): one binary per
joint end (open or closed) and two per joint with friction (slipping forward or backward). The
forces of the optimal pattern are then solved again as an LP at the tolerances of the associative one,
which gives ``lambda`` to its accuracy. The associative LP stays beside it as the upper bound.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
from scipy.optimize import Bounds, LinearConstraint, linprog, milp
from scipy.sparse import vstack

from analytic.limit.limit_discrete import (
    ContactModel,
    LPResult,
    _check_sign,
    _sparse,
    contact_model,
    equilibrium_entries,
    solve_contact_lp,
)
from specimens.blocks import Assembly
from specimens.constants import G

#: Bounds the mixed-integer program puts on its unknowns, in units of the total weight (forces) and of
#: the mechanism's scale (velocities: the mass-weighted horizontal velocity is 1). A solution that comes
#: within half of one is solved again with every bound ten times larger (at most twice); the result
#: records the bounds that held.
FORCE_BOUND = 20.0
VELOCITY_BOUND = 20.0
#: Relative MIP gap at which the search stops, and its time limit [s] (the result says which ended it).
MIP_GAP = 1e-6
TIME_LIMIT = 60.0

#: Joint states of the non-associative mechanism (as :data:`analytic.limit.limit_discrete.JOINT_STATES`,
#: without dilatancy: a sliding joint stays closed at both ends).
JOINT_STATES = ("closed", "hinge-intrados", "hinge-extrados", "sliding", "hinge+sliding", "open")


@dataclass(frozen=True)
class NonAssociativeResult:
    """The least collapse multiplier with Coulomb friction without dilatancy.

    ``lam``: the multiplier (``inf``: no mechanism can form under any horizontal load; ``nan``: the
    search failed or the blocks cannot stand); ``lam_associative``: the associative LP of the same
    blocks (its upper bound); ``optimal``: the MIP proved its optimum to ``MIP_GAP``; ``gap``: the
    relative gap between ``lam`` and the proven lower bound ``lower_bound`` where it stopped;
    ``joint_states`` / ``joint_hinge_face`` / ``forces`` [N] / ``motion`` as in
    :class:`analytic.limit.limit_discrete.LPResult` (motion without dilatancy); ``nodes``: branch-and-bound
    nodes; ``seconds``: wall time of the search; ``force_bound`` / ``velocity_bound``: the bounds that
    held (:data:`FORCE_BOUND`); ``message``: how it ended.
    """

    lam: float
    lam_associative: float
    optimal: bool
    gap: float
    lower_bound: float
    joint_states: dict[str, str]
    joint_hinge_face: dict[str, str]
    forces: dict[str, dict[str, float]]
    motion: dict[str, dict[str, float]]
    nodes: int
    seconds: float
    force_bound: float
    velocity_bound: float
    message: str
    load_sign: int = 1
    mu_joint: float = math.inf
    mu_base: float = math.inf

    @property
    def hinges(self) -> tuple[tuple[str, str], ...]:
        """Joints that hinge (with or without sliding), with the face of the hinge."""
        return tuple((k, f) for k, f in self.joint_hinge_face.items() if f)

    @property
    def sliding(self) -> tuple[str, ...]:
        """Joints that slip in the mechanism (``sliding``, ``hinge+sliding`` or ``open`` with slip)."""
        return tuple(k for k, st in self.joint_states.items() if st in ("sliding", "hinge+sliding"))

    @property
    def below_associative(self) -> float:
        """``1 - lam / lam_associative``: how far below the associative LP the collapse lies."""
        return 1.0 - self.lam / self.lam_associative if self.lam_associative else math.nan

    def to_dict(self) -> dict:
        """JSON-ready summary."""
        return {"lambda_non_associative": self.lam, "lambda_associative": self.lam_associative,
                "optimal": self.optimal, "gap": self.gap, "lower_bound": self.lower_bound,
                "hinges": [{"joint": k, "face": f, "sliding": self.joint_states[k] == "hinge+sliding"}
                           for k, f in self.hinges],
                "sliding": [k for k, st in self.joint_states.items() if st == "sliding"],
                "open": [k for k, st in self.joint_states.items() if st == "open"],
                "joint_states": dict(self.joint_states), "nodes": self.nodes, "seconds": self.seconds,
                "force_bound": self.force_bound, "velocity_bound": self.velocity_bound,
                "message": self.message}


def _failed(lam: float, assoc: LPResult, message: str, s: int, seconds: float = 0.0) -> NonAssociativeResult:
    return NonAssociativeResult(lam, assoc.lam, False, math.nan, math.nan, {}, {}, {}, {}, 0, seconds,
                                math.nan, math.nan, message, s, assoc.mu_joint, assoc.mu_base)


def solve_contact_non_associative(model: ContactModel, load_sign: int = 1, length_scale: float | None = None,
                                  time_limit: float = TIME_LIMIT, mip_gap: float = MIP_GAP) -> NonAssociativeResult:
    """The least collapse multiplier of a :class:`ContactModel` with non-associative Coulomb friction
    (module docstring); ``time_limit`` [s] and ``mip_gap`` stop the search (the result says which)."""
    s = _check_sign(load_sign)
    L = float(length_scale or np.ptp(np.vstack([model.p1, model.p2, model.centroid]), axis=0).max() or 1.0)
    assoc = solve_contact_lp(model, s, length_scale=L)
    if not assoc.success and assoc.status != 3:  # unbounded associatively: sliding may still collapse it
        return _failed(assoc.lam, assoc, assoc.message, s)
    if assoc.lam < 0:
        return _failed(math.nan, assoc, assoc.message, s)
    t0 = time.perf_counter()
    W = float(model.mass.sum())
    n_max = max((f["N_intrados"] + f["N_extrados"]) / (G * W) for f in assoc.forces.values()) if assoc.forces else 0.0
    lam_hi = assoc.lam if math.isfinite(assoc.lam) else math.inf
    # forces grow with the load: the bounds start from the associative state's scale
    fb = FORCE_BOUND * max(1.0, n_max, lam_hi if math.isfinite(lam_hi) else 1.0)
    vb = VELOCITY_BOUND * float(W / model.mass.min()) ** 0.5
    out = None
    for attempt in range(3):
        out = _mip(model, s, L, fb, vb, lam_hi, time_limit, mip_gap)
        if out is not None and not out[1]:
            break
        if attempt < 2:
            fb, vb = 10 * fb, 10 * vb
    seconds = time.perf_counter() - t0
    if out is None:
        return _failed(math.inf, assoc, "no mechanism without dilatancy forms under any horizontal load up to "
                       f"{lam_hi:g} with forces up to {fb:g} times the weight", s, seconds)
    x, tight, res, ix = out
    if tight:
        return _failed(math.nan, assoc, f"the solution reaches the bounds even at forces {fb:g} times the weight "
                       f"and velocities {vb:g}", s, seconds)
    return _result(model, s, L, x, res, ix, assoc, fb, vb, seconds)


class _Index:
    """Column positions of the mixed-integer program's unknowns."""

    def __init__(self, nb: int, nj: int, fr: np.ndarray):
        self.nb, self.nj = nb, nj
        self.fr = fr  # indices of the joints with finite friction
        self.N = np.arange(2 * nj)  # 2 j + k
        self.V = 2 * nj + np.arange(2 * nj)
        self.lam = 4 * nj
        self.u = self.lam + 1 + np.arange(3 * nb)  # (u_x, u_y, omega) per body
        self.d = self.lam + 1 + 3 * nb + np.arange(2 * nj)  # openings
        self.sp = self.d[-1] + 1 + np.arange(nj)  # forward slip
        self.sm = self.sp[-1] + 1 + np.arange(nj)  # backward slip
        self.z = self.sm[-1] + 1 + np.arange(2 * nj)  # 1: the end may open (and carries no force)
        self.wp = self.z[-1] + 1 + np.arange(len(fr))  # 1: the joint may slip forward
        self.wm = (self.wp[-1] + 1 if len(fr) else self.z[-1] + 1) + np.arange(len(fr))
        self.n = int(self.z[-1] + 1 + 2 * len(fr))


def _rel_rows(model: ContactModel, L: float, j: int, p: np.ndarray, d: np.ndarray, ix: _Index) -> dict[int, float]:
    """Coefficients of ``(v_b(p) - v_a(p)) . d`` on the body velocities (``p`` in units of ``L``)."""
    row: dict[int, float] = {}
    for body, sgn in ((model.b[j], 1.0), (model.a[j], -1.0)):
        if body < 0:
            continue
        r = p - model.centroid[body] / L
        for col, v in ((ix.u[3 * body], d[0]), (ix.u[3 * body + 1], d[1]),
                       (ix.u[3 * body + 2], -r[1] * d[0] + r[0] * d[1])):
            row[col] = row.get(col, 0.0) + sgn * v
    return row


def _mip(model: ContactModel, s: int, L: float, fb: float, vb: float, lam_hi: float, time_limit: float,
         mip_gap: float):
    """Solve the mixed-integer program with force bound ``fb``, velocity bound ``vb`` and ``lambda <= lam_hi``
    (the associative LP, its upper bound); None if it is
    infeasible, else ``(x, tight, res, ix)`` with ``tight`` True when a bound is within half of reached."""
    nb, nj = len(model.mass), len(model.joint_names)
    fr = np.flatnonzero(np.isfinite(model.mu))
    ix = _Index(nb, nj, fr)
    W = float(model.mass.sum())
    eq, rhs = equilibrium_entries(model, L, s)
    rows: list[tuple[dict[int, float], float, float]] = [({}, rhs[i], rhs[i]) for i in range(3 * nb)]
    for (r, c), v in eq.items():  # the equilibrium rows, grouped in one pass
        rows[r][0][c] = v
    for j in range(nj):
        n = model.normal[j]
        t = np.array([-n[1], n[0]])
        for k, p in enumerate((model.p1[j] / L, model.p2[j] / L)):
            row = _rel_rows(model, L, j, p, n, ix)  # opening = relative normal velocity
            row[ix.d[2 * j + k]] = -1.0
            rows.append((row, 0.0, 0.0))
        row = _rel_rows(model, L, j, model.p1[j] / L, t, ix)  # slip = relative tangential velocity
        row[ix.sp[j]] = -1.0
        row[ix.sm[j]] = 1.0
        rows.append((row, 0.0, 0.0))
    rows.append(({ix.u[3 * b]: s * model.mass[b] / W for b in range(nb)}, 1.0, 1.0))  # scale of the mechanism
    for j in range(nj):
        for k in range(2):
            e = 2 * j + k
            rows.append(({ix.N[e]: 1.0, ix.z[e]: fb}, -np.inf, fb))  # an open end carries nothing
            rows.append(({ix.d[e]: 1.0, ix.z[e]: -vb}, -np.inf, 0.0))  # a closed end does not open
    for q, j in enumerate(fr):
        mu = float(model.mu[j])
        fv = 2 * (1 + mu) * fb  # bounds |V| + mu N at one end
        for k in range(2):
            e = 2 * j + k
            rows.append(({ix.V[e]: 1.0, ix.N[e]: -mu}, -np.inf, 0.0))
            rows.append(({ix.V[e]: -1.0, ix.N[e]: -mu}, -np.inf, 0.0))
            # forward slip only against a shear at -mu N, backward only at +mu N (the force on body b)
            rows.append(({ix.V[e]: 1.0, ix.N[e]: mu, ix.wp[q]: fv}, -np.inf, fv))
            rows.append(({ix.V[e]: -1.0, ix.N[e]: mu, ix.wm[q]: fv}, -np.inf, fv))
        rows.append(({ix.sp[j]: 1.0, ix.wp[q]: -vb}, -np.inf, 0.0))
        rows.append(({ix.sm[j]: 1.0, ix.wm[q]: -vb}, -np.inf, 0.0))
        rows.append(({ix.wp[q]: 1.0, ix.wm[q]: 1.0}, -np.inf, 1.0))
    A = _sparse({(i, c): v for i, (row, _, _) in enumerate(rows) for c, v in row.items()}, (len(rows), ix.n))
    lo = np.array([r[1] for r in rows])
    hi = np.array([r[2] for r in rows])
    lb, ub = np.zeros(ix.n), np.full(ix.n, np.inf)
    ub[ix.N] = fb
    lb[ix.V], ub[ix.V] = -np.inf, np.inf
    for j in np.flatnonzero(~np.isfinite(model.mu)):
        ub[ix.sp[j]] = ub[ix.sm[j]] = 0.0  # no friction limit: no slip
    for j in fr:
        lb[ix.V[2 * j:2 * j + 2]] = -fb * model.mu[j]
        ub[ix.V[2 * j:2 * j + 2]] = fb * model.mu[j]
    lb[ix.u], ub[ix.u] = -vb, vb
    ub[ix.lam] = lam_hi * (1 + 1e-9) + 1e-12
    ub[ix.d] = vb
    ub[np.concatenate([ix.sp[fr], ix.sm[fr]])] = vb
    ub[ix.z] = 1.0
    ub[np.concatenate([ix.wp, ix.wm])] = 1.0
    integrality = np.zeros(ix.n)
    integrality[ix.z[0]:] = 1
    cost = np.zeros(ix.n)
    cost[ix.lam] = 1.0
    res = milp(cost, integrality=integrality, bounds=Bounds(lb, ub), constraints=LinearConstraint(A, lo, hi),
               options={"time_limit": float(time_limit), "mip_rel_gap": float(mip_gap), "presolve": True})
    if res.x is None:
        return None
    x = res.x
    near = lambda v, b: bool(np.any(np.abs(v) > 0.5 * b))  # noqa: E731
    tight = near(x[ix.N], fb) or near(x[ix.u], vb) or near(x[ix.d], vb) or near(x[ix.sp], vb) or near(x[ix.sm], vb)
    return x, tight, res, ix


def _polish(model: ContactModel, s: int, L: float, x: np.ndarray, ix: _Index):
    """The forces of the optimal pattern again, as an LP at the associative one's tolerances: the least
    ``lambda`` with the ends the pattern opens unloaded and its slipping joints at their friction limit."""
    nb, nj = len(model.mass), len(model.joint_names)
    nv = 4 * nj + 1
    eq, rhs = equilibrium_entries(model, L, s)
    A = _sparse(eq, (3 * nb, nv))
    z = np.round(x[ix.z]).astype(bool)
    wp = dict(zip(ix.fr, np.round(x[ix.wp]).astype(bool)))
    wm = dict(zip(ix.fr, np.round(x[ix.wm]).astype(bool)))
    bounds = [(0.0, 0.0) if z[e] else (0.0, None) for e in range(2 * nj)] + [(None, None)] * (2 * nj) + [(0.0, None)]
    ub: dict[tuple[int, int], float] = {}
    eqf: dict[tuple[int, int], float] = {}
    n_ub = n_eq = 0
    for j in ix.fr:
        mu = float(model.mu[j])
        for k in range(2):
            e = 2 * j + k
            if wp[j] or wm[j]:  # at the limit, against the slip
                eqf[n_eq, ix.V[e]] = 1.0
                eqf[n_eq, ix.N[e]] = mu if wp[j] else -mu
                n_eq += 1
                continue
            for sv in (1.0, -1.0):
                ub[n_ub, ix.V[e]] = sv
                ub[n_ub, ix.N[e]] = -mu
                n_ub += 1
    A_eq = A if not n_eq else vstack([A, _sparse(eqf, (n_eq, nv))]).tocsr()
    b_eq = np.concatenate([rhs, np.zeros(n_eq)])
    cost = np.zeros(nv)
    cost[ix.lam] = 1.0
    res = linprog(cost, A_ub=_sparse(ub, (n_ub, nv)) if n_ub else None, b_ub=np.zeros(n_ub) if n_ub else None,
                  A_eq=A_eq, b_eq=b_eq, bounds=bounds, method="highs",
                  options={"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10})
    return res if res.status == 0 else None


def _result(model, s, L, x, res, ix, assoc, fb, vb, seconds) -> NonAssociativeResult:
    nj = len(model.joint_names)
    W = float(model.mass.sum())
    pol = _polish(model, s, L, x, ix)
    forces_x = pol.x if pol is not None else x[:4 * nj + 1]
    lam = float(pol.x[ix.lam]) if pol is not None else float(x[ix.lam])
    bound = float(getattr(res, "mip_dual_bound", math.nan))
    bound = bound if math.isfinite(bound) else lam
    optimal = res.status == 0
    gap = max(0.0, (lam - bound) / abs(lam)) if lam else max(0.0, lam - bound)
    u = x[ix.u].reshape(-1, 3)
    vmax = max(1e-300, float(np.abs(u).max()))
    tol = 1e-5 * vmax
    F = G * W
    states: dict[str, str] = {}
    faces: dict[str, str] = {}
    forces: dict[str, dict[str, float]] = {}
    motion: dict[str, dict[str, float]] = {}
    for j, name in enumerate(model.joint_names):
        o1, o2 = float(x[ix.d[2 * j]]), float(x[ix.d[2 * j + 1]])
        slip = float(x[ix.sp[j]] - x[ix.sm[j]])
        motion[name] = {"open_intrados": o1, "open_extrados": o2, "slip": slip}
        forces[name] = {"N_intrados": float(forces_x[ix.N[2 * j]]) * F, "N_extrados": float(forces_x[ix.N[2 * j + 1]]) * F,
                        "V_intrados": float(forces_x[ix.V[2 * j]]) * F, "V_extrados": float(forces_x[ix.V[2 * j + 1]]) * F}
        sliding = abs(slip) > tol
        c1, c2 = o1 <= tol, o2 <= tol
        if c1 and c2:
            st, face = ("sliding" if sliding else "closed"), ""
        elif c1:
            st, face = ("hinge+sliding" if sliding else "hinge-intrados"), "intrados"
        elif c2:
            st, face = ("hinge+sliding" if sliding else "hinge-extrados"), "extrados"
        else:
            st, face = "open", ""
        states[name], faces[name] = st, face
    how = ("optimal (proven to a relative gap of {:.1e})".format(gap) if optimal
           else f"stopped at the time limit with a relative gap of {gap:.2%}")
    return NonAssociativeResult(lam, assoc.lam, optimal, gap, bound, states, faces, forces, motion,
                                int(getattr(res, "mip_node_count", 0) or 0), seconds, fb, vb, how, s,
                                assoc.mu_joint, assoc.mu_base)


def solve_non_associative(assembly: Assembly, mu_joint: float, mu_base: float, load_sign: int = +1,
                          time_limit: float = TIME_LIMIT, mip_gap: float = MIP_GAP) -> NonAssociativeResult:
    """The least collapse multiplier of an assembly's blocks with Coulomb friction without dilatancy,
    ``mu_joint`` between blocks and ``mu_base`` on the supports (``inf``: no sliding), beside the
    associative LP (its upper bound). Any assembly the LP takes: catalogue, parameters, drawings, piers."""
    model = contact_model(assembly, mu_joint, mu_base)
    r = solve_contact_non_associative(model, load_sign, length_scale=assembly.length_scale,
                                      time_limit=time_limit, mip_gap=mip_gap)
    return NonAssociativeResult(**{**r.__dict__, "mu_joint": float(mu_joint), "mu_base": float(mu_base)})
