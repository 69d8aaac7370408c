"""The compliant contact law: joint springs per unit area, lumped at the engines' contact points
(docs/physics/dem.md#17-compliant-joints).

A joint of contact length ``L`` and width ``w`` (area ``A = L w``) carries a normal stiffness
``k_n A`` [N/m]. Both engines touch a flat face-to-face joint at the four corners of its face, so
each contact point gets ``k_n A / 4`` — the joint's stiffness lumped at its two ends, as a rigid-block
DEM's corner sub-contacts do; the damping of a point is ``beta_R`` times its stiffness
(stiffness-proportional Rayleigh damping). The shear direction stays Coulomb friction, rigid until it slips.
"""
from __future__ import annotations

import math

import numpy as np

from dem.core.model import Model
from dem.core.settings import MAX_DAMPING_XI, Settings
from specimens.catalogue import STUDY_JOINTS
from foundation.errors import ArchdemInputError

#: Contact points of a flat face-to-face joint in both engines: the four corners of the face.
POINTS_PER_JOINT = 4


def hull_offset(settings: Settings, inflate: float) -> float:
    """Outward offset of the collision hulls [m]: the engine's ``inflate`` option [m], so that rigid faces touch at
    step 0; none on compliant joints, whose springs start unloaded at the drawn blocks (1 µm preloads each by 2 µm)."""
    return 0.0 if settings.contact_law == "compliant" else inflate


def joint_width(model: Model, joint) -> float:
    """Out-of-plane width [m] of a joint: the narrower of its two bodies."""
    return min(model.bodies[k].width for k in (joint.a, joint.b) if k >= 0)


def point_stiffness(model: Model, kn: float) -> np.ndarray:
    """Normal stiffness of one contact point of each joint [N/m]: ``kn A / 4``, (n_joints,)."""
    return np.array([kn * j.length * joint_width(model, j) / POINTS_PER_JOINT for j in model.joints])


def rotational_impact_frequency(model: Model, kn: float) -> float:
    """``omega_r = sqrt(k_n A L^2 / J_o)`` [rad/s]: the left half of the structure (bodies left of
    mid-span; a single body whole) turning about the intrados end of its base joint on that joint's
    stiffness — the frequency at which the reference study set its joints' damping."""
    base = [j for j in model.joints if j.is_base]
    j = min(base, key=lambda jt: min(jt.p_i[0], jt.p_e[0]))
    pivot = np.asarray(j.p_i, float)
    half = [b for b in model.bodies if b.centroid[0] < -1e-9] or list(model.bodies)
    J_o = sum(b.inertia[2, 2] + b.mass * float(np.sum((b.centroid[:2] - pivot) ** 2)) for b in half)
    A = j.length * joint_width(model, j)
    return math.sqrt(kn * A * j.length ** 2 / J_o)


def block_length(model: Model) -> float:
    """The blocks' mean length across their joints [m]: per body with two or more joints, the distance
    between the middles of its first two; a body on one joint (a single block), twice its centroid's
    distance from it."""
    mids: dict[int, list[np.ndarray]] = {}
    for j in model.joints:
        for k in (j.a, j.b):
            if k >= 0:
                mids.setdefault(k, []).append(0.5 * (np.asarray(j.p_i, float) + np.asarray(j.p_e, float)))
    lengths = []
    for k, m in mids.items():
        c = model.bodies[k].centroid[:2]
        lengths.append(float(np.linalg.norm(m[1] - m[0])) if len(m) > 1 else 2.0 * float(np.linalg.norm(c - m[0])))
    return float(np.mean(lengths))


def normal_stiffness(settings: Settings, model: Model) -> float:
    """The joints' k_n [Pa/m]: given, or ``E / L`` from the blocks' Young's modulus — a joint as the two
    half-blocks it joins, in series, each ``E / (L / 2)`` per unit area (``L``: :func:`block_length`)."""
    return float(settings.kn) if settings.kn else float(settings.youngs) / block_length(model)


def study_joints(specimen_id: str) -> dict:
    """The contact-law settings of the reference study's joints of a catalogue specimen (its Table 5.1:
    ``k_n`` and ``beta_R`` as printed)."""
    if specimen_id not in STUDY_JOINTS:
        what = "an arch by its parameters or a block (give a specimen id)" if specimen_id is None else repr(specimen_id)
        raise ArchdemInputError(f"--joints table-5.1 has the joints of the catalogue specimens only, not {what}")
    kn, _, beta = STUDY_JOINTS[specimen_id]
    return {"contact_law": "compliant", "kn": kn, "damping_beta": beta}


def rayleigh_beta(settings: Settings, model: Model) -> float:
    """The joints' stiffness-proportional damping coefficient beta_R [s]: given, or ``2 xi / omega_r``
    (a damping ratio ``xi`` at ``omega_r``: ``xi(omega) = beta_R omega / 2``)."""
    if settings.damping_xi:
        return 2.0 * settings.damping_xi / rotational_impact_frequency(model, normal_stiffness(settings, model))
    beta = float(settings.damping_beta)
    # a beta_R far above critical glues the joints: every tilt level holds and the search ran out of levels
    xi = 0.5 * beta * rotational_impact_frequency(model, normal_stiffness(settings, model)) if beta else 0.0
    if xi > MAX_DAMPING_XI:
        raise ArchdemInputError(f"damping beta_R = {beta:g} s is a damping ratio xi = {xi:.3g} at the joints' "
                                f"rotational-impact frequency, outside 0-{MAX_DAMPING_XI:g}; give a smaller "
                                "--damping-beta or the ratio as --damping-xi")
    return beta


def body_point_stiffness(model: Model, kn: float) -> tuple[np.ndarray, float]:
    """Per body (and for the base) the mean point stiffness of its joints [N/m]: engines that set the
    stiffness per body (PyBullet) combine two bodies' values in series, so each body gets twice this."""
    kp = point_stiffness(model, kn)
    per = [[kp[i] for i, j in enumerate(model.joints) if k in (j.a, j.b)] for k in range(model.n_bodies)]
    base = [kp[i] for i, j in enumerate(model.joints) if j.is_base]
    return np.array([np.mean(v) if v else float(np.mean(kp)) for v in per]), float(np.mean(base) if base else np.mean(kp))


def highest_frequency(model: Model, kn: float) -> float:
    """An upper estimate of the joints' highest natural frequency [rad/s]: per body, every spring at its
    joints' ends pushing alone on the body's inverse mass at that point (``1/m + r^2 / I``), summed."""
    kp = point_stiffness(model, kn)
    w2 = 0.0
    for k, b in enumerate(model.bodies):
        s = 0.0
        for kj, j in zip(kp, model.joints):
            if k in (j.a, j.b):
                for p in (j.p_i, j.p_e):
                    r2 = float(np.sum((np.asarray(p, float) - b.centroid[:2]) ** 2))
                    s += 2 * kj * (1.0 / b.mass + r2 / b.inertia[2, 2])  # two corners across the width
        w2 = max(w2, s)
    return math.sqrt(w2)

