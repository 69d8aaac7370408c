"""The mode map's case function: one threshold search per specimen and frequency of a one-cycle sine on a
speed-limited table, with the joint that slips first in the collapsing run (docs/validation.md#22).

A case is a dict (:meth:`dem.experiments.mode_map.run.ModeMapSpec.cases`): ``id``, ``freq`` [Hz],
``table_speed`` [m/s] (None: the ideal sine), ``tau`` [s] (None: a velocity command), ``mu_base``,
``contact`` (a fraction or ``"calibrated"``), ``restitution``, ``scan_over`` (the scan's top over the
reach), ``reach_speed`` [m/s] (whose reach caps the scan), ``slip_mm`` [mm].
"""
from __future__ import annotations

import math
import time
from functools import partial

import numpy as np

from analytic.motions.inputs import GroundMotion, SinePulse
from analytic.motions.table import servo_sine
from dem.common.joints import contact_fraction
from dem.core.detect import joint_kinematics
from dem.core.model import Model, as_model
from dem.core.settings import dynamics_settings
from dem.experiments.shake import ShakeResult, shake, static_onset, threshold
from specimens.catalogue import get_specimen
from specimens.constants import G

#: A joint slips when both its ends have moved along it by more than this [mm] (a hinge turns about one end).
SLIP_MM = 0.2


def servo_motion(a: float, f: float, v_max: float | None = None, tau: float | None = None) -> GroundMotion:
    """The table's motion for a commanded one-cycle sine ``a`` [m/s^2] at ``f`` [Hz]: the sine itself
    without a speed limit ``v_max`` [m/s], else the servo's (``tau`` [s] its position loop, None a
    velocity command). Module level: it reaches worker processes by reference."""
    return SinePulse(a, f) if v_max is None else servo_sine(a, f, v_max, tau)


def first_slip(model: Model, res: ShakeResult, slip_mm: float = SLIP_MM) -> tuple[str, float | None]:
    """The joint that slips first in a shake result ``res`` (both ends more than ``slip_mm`` [mm] along
    it) and when [s], read until the collapse criterion (a point moved one ring thickness: past it a
    falling arch's joints all move); ``("", None)`` when none does."""
    h = res.sim.history
    R = h.rotations()
    upto = model.size * res.settings.collapse_fraction
    for k in range(len(h.t)):
        if h.dmax[k] > upto:
            break
        d = joint_kinematics(model, h.pos[k], R[k])
        slip = np.minimum(np.abs(d["slip_i"]), np.abs(d["slip_e"])) * 1e3
        if slip.max() > slip_mm:
            return model.joints[int(np.argmax(slip))].name, float(h.t[k])
    return "", None


def reach_g(f: float, v_max: float) -> float:
    """Largest amplitude [g] of a one-cycle sine at ``f`` [Hz] a table of speed ``v_max`` [m/s] follows
    (its peak speed ``a / (pi f)``)."""
    return math.pi * f * v_max / G


def slip_half(t_slip: float | None, f: float) -> str:
    """The half cycle of a sine at ``f`` [Hz] a slip at ``t_slip`` [s] falls in: first, second, after, or ""."""
    if t_slip is None:
        return ""
    return "first" if t_slip <= 0.5 / f else "second" if t_slip <= 1 / f else "after"


def mode_case(case: dict) -> dict:
    """One cell of the map (a sweep case): glued, the dynamics defaults; the commanded amplitude scanned
    from the static onset lambda g by 1.15 up to ``scan_over`` x the reach, bisected to 1 %; the
    collapsing run at the threshold run again to read the joint that slips first. Amplitudes in g."""
    t0 = time.perf_counter()
    sp = get_specimen(case["id"])
    contact = contact_fraction(case["contact"], sp.arch)
    model = as_model(sp, config="glued", contact=contact)
    st = dynamics_settings(mu_base=case["mu_base"], restitution=case["restitution"])
    f = case["freq"]
    motion_fn = partial(servo_motion, v_max=case["table_speed"], tau=case["tau"])
    lam = static_onset(model, st)
    top = case["scan_over"] * reach_g(f, case["reach_speed"])
    out = {"lambda": lam, "contact_fraction": contact, "scan_top_g": top, "amplitude_g": None, "mode": "none",
           "phase": "", "joint": "", "t_slip_s": math.nan, "slip_half": "", "n_sims": 0, "bands": ""}
    if lam >= top:
        out["wall_s"] = time.perf_counter() - t0
        return out
    th = threshold(model, f, st, a_min_g=lam, a_max_g=top, workers=1, motion_fn=motion_fn)
    out.update(n_sims=th.n_sims, bands=" ".join(f"{b['outcome'][0].upper()}{b['from_g']:.3f}" for b in th.bands))
    if th.amplitude_g is not None:
        r = shake(model, motion_fn(th.amplitude_g * G, f), st, friction_work=False)
        joint, t_slip = first_slip(model, r, case["slip_mm"])
        out.update(amplitude_g=th.amplitude_g, mode=th.mode, phase=th.phase or "", joint=joint,
                   within_reach=bool(th.amplitude_g <= reach_g(f, case["reach_speed"]) * (1 + 1e-9)),
                   t_slip_s=math.nan if t_slip is None else t_slip, slip_half=slip_half(t_slip, f),
                   slid=" ".join(j.joint for j in r.sim.joints if "slide" in j.state))
    out["wall_s"] = time.perf_counter() - t0
    return out
