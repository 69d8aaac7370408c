"""Collapse and failure-mode detection from body poses alone (docs/physics/dem.md#5-collapse-criterion, #6-failure-mode).

Collapse criterion (no per-specimen tuning): some material point of some body has moved more
than ``collapse_fraction x size`` (size = ring thickness of an arch, height of a block) from its
initial position while that body still moves faster than ``collapse_speed``. With
``collapse_confirm`` (the shakes') a firing is only an excursion: the collapse is confirmed once a
point moved more than ``collapse_confirm x size``, or when the run ends still past the criterion;
an arch that comes back below it has survived (:func:`dem.core.simulate.simulate`). The
parameters live in :class:`dem.core.settings.Settings` and are stored with every result.

Joint kinematics: each joint's intrados and extrados end points are carried by both bodies
from the initial pose; their separation splits into opening along the joint normal (carried by
body ``a``), in-plane tangential slip and out-of-plane slip; the relative in-plane rotation is
the difference of the bodies' rotations about z, the twist the out-of-plane part of the
relative rotation. States are read on the increments between the instants when the largest
displacement first reaches ``mode_window[0] x size`` and ``mode_window[1] x size``: this removes
pre-collapse creep and stops before the mechanism drifts to a neighbouring one.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from dem.core.model import Model
from dem.core.settings import Settings


def criterion(settings: Settings, model: Model) -> dict:
    """The collapse criterion and mode-reading parameters, as stored with each result."""
    c = settings.collapse_confirm
    confirm = ("" if c is None else
               "; confirmed once any body point moved > collapse_confirm * size, or when the run ends (at rest or "
               "not) still past the criterion; an excursion that came back below it is survived")
    return {
        "definition": "max displacement of any body point > collapse_fraction * size while that body moves "
                      f"faster than collapse_speed{confirm}; mode from increments between mode_window displacements",
        "size_m": model.size, "collapse_fraction": settings.collapse_fraction,
        "collapse_displacement_m": settings.collapse_fraction * model.size,
        "collapse_speed_m_s": settings.collapse_speed, "collapse_confirm": c,
        "confirm_displacement_m": None if c is None else c * model.size, "mode_window": list(settings.mode_window),
        "hinge_fraction": settings.hinge_fraction, "slide_fraction": settings.slide_fraction,
    }


def _points(model: Model) -> list[np.ndarray]:
    return [b.points() + np.array([0.0, 0.0, b.centroid[2]]) for b in model.bodies]


class PointTracker:
    """Displacements of the bodies' outline points (both z faces) relative to the initial pose."""

    def __init__(self, model: Model) -> None:
        self.model = model
        self.c0 = np.array([b.centroid for b in model.bodies])
        self.pts = _points(model)
        self.radius = np.array([np.linalg.norm(p - c, axis=1).max() for p, c in zip(self.pts, self.c0)])
        # every tracked point in one array (body index, offset from its centroid): one vectorised
        # evaluation per record instead of a Python loop over the bodies
        self._body = np.concatenate([np.full(len(p), i) for i, p in enumerate(self.pts)])
        self._all = np.concatenate(self.pts)
        self._rel = np.concatenate([p - c for p, c in zip(self.pts, self.c0)])
        self._starts = np.cumsum([0] + [len(p) for p in self.pts[:-1]])

    def all_displacements(self, pos: np.ndarray, R: np.ndarray) -> np.ndarray:
        """(m, 3) displacements of every tracked point [m], bodies one after the other; ``pos``
        (..., n, 3) and ``R`` (..., n, 3, 3) may carry leading (time) axes: then (..., m, 3)."""
        b = self._body
        return pos[..., b, :] + np.einsum("...kij,kj->...ki", R[..., b, :, :], self._rel) - self._all

    def max_displacement(self, pos: np.ndarray, R: np.ndarray) -> tuple[float, int]:
        """Largest point displacement [m] and the body it belongs to."""
        d = np.maximum.reduceat(np.linalg.norm(self.all_displacements(pos, R), axis=1), self._starts)
        i = int(np.argmax(d))
        return float(d[i]), i

    def body_speed(self, v: np.ndarray, w: np.ndarray, i: int) -> float:
        """Upper bound of the speed of any point of body ``i`` [m/s]."""
        return float(np.linalg.norm(v[i]) + np.linalg.norm(w[i]) * self.radius[i])


def in_plane_angle(R: np.ndarray) -> np.ndarray:
    """Rotation about z [rad] of rotation matrices (..., 3, 3)."""
    return np.arctan2(R[..., 1, 0], R[..., 0, 0])


def out_of_plane_angle(R: np.ndarray) -> np.ndarray:
    """Angle [rad] by which the body's z axis has tilted out of the z direction."""
    return np.arccos(np.clip(R[..., 2, 2], -1.0, 1.0))


def joint_kinematics(model: Model, pos: np.ndarray, R: np.ndarray) -> dict[str, np.ndarray]:
    """Per joint (arrays of length n_joints) [m, rad]: ``open_i``, ``open_e`` (opening at the
    intrados / extrados end, + = gap), ``slip_i``, ``slip_e`` (in-plane tangential), ``oop``
    (largest out-of-plane slip of the two ends), ``rot`` (relative in-plane rotation b - a),
    ``twist`` (out-of-plane part of the relative rotation)."""
    c0 = np.array([b.centroid for b in model.bodies])
    I = np.eye(3)
    out = {k: np.zeros(len(model.joints)) for k in ("open_i", "open_e", "slip_i", "slip_e", "oop", "rot", "twist")}
    for k, j in enumerate(model.joints):
        body = j.b if j.a < 0 else j.a
        z = c0[body, 2]

        def carry(idx: int, p2: np.ndarray) -> np.ndarray:
            p = np.array([p2[0], p2[1], z])
            return p if idx < 0 else pos[idx] + R[idx] @ (p - c0[idx])

        Ra = I if j.a < 0 else R[j.a]
        Rb = I if j.b < 0 else R[j.b]
        n = Ra @ np.array([j.normal[0], j.normal[1], 0.0])
        t = Ra @ np.array([-j.normal[1], j.normal[0], 0.0])
        ez = Ra @ np.array([0.0, 0.0, 1.0])
        oop = 0.0
        for end, p2 in (("i", j.p_i), ("e", j.p_e)):
            d = carry(j.b, p2) - carry(j.a, p2)
            out[f"open_{end}"][k] = d @ n
            out[f"slip_{end}"][k] = d @ t
            oop = max(oop, abs(d @ ez))
        out["oop"][k] = oop
        Rrel = Ra.T @ Rb
        out["rot"][k] = float(np.arctan2(Rrel[1, 0], Rrel[0, 0]))
        out["twist"][k] = float(np.arccos(np.clip(Rrel[2, 2], -1.0, 1.0)))
    return out


@dataclass(frozen=True)
class JointState:
    """State of one joint over the mode window: ``hinge``, ``slide``, ``hinge+slide``, ``closed``,
    or ``open`` (both ends opened: the joint parted, as in a disordered collapse).

    ``face``: the pivot end of a hinge (``intrados``/``extrados``) or ``""``; increments [m, rad].
    """

    joint: str
    state: str
    face: str
    opening: float
    slip: float
    rotation: float

    def to_dict(self) -> dict:
        return {"joint": self.joint, "state": self.state, "face": self.face, "opening": self.opening,
                "slip": self.slip, "rotation": self.rotation}


def classify(model: Model, settings: Settings, pos0, R0, pos1, R1, window: float) -> tuple[list[JointState], str]:
    """Joint states and specimen mode from the increment between poses 0 and 1.

    ``window``: increment of the largest point displacement between the two poses [m].
    Mode: ``rocking`` (no joint slides), ``sliding`` (some joint slides and slip makes up at
    least half of the summed slip + opening increments), ``mixed`` otherwise.
    """
    k0 = joint_kinematics(model, pos0, R0)
    k1 = joint_kinematics(model, pos1, R1)
    d = {k: k1[k] - k0[k] for k in k0}
    s = max(window, 1e-12)
    states = []
    sum_open = sum_slip = 0.0
    any_slide = any_hinge = False
    for k, j in enumerate(model.joints):
        oi, oe = d["open_i"][k], d["open_e"][k]
        opening = max(oi, oe, 0.0)
        pivot_e = oi > oe  # intrados opens -> rotation about the extrados end
        slip = d["slip_e"][k] if pivot_e else d["slip_i"][k]
        hinge = opening > settings.hinge_fraction * s
        slide = abs(slip) > settings.slide_fraction * s
        separated = min(oi, oe) > settings.hinge_fraction * s  # both ends open: the joint has parted
        state = "hinge+slide" if hinge and slide else "hinge" if hinge else "slide" if slide else "closed"
        if separated:
            state = "open"
        face = ("extrados" if pivot_e else "intrados") if hinge and not separated else ""
        any_slide |= slide and not separated
        any_hinge |= hinge
        sum_open += opening
        sum_slip += abs(slip)
        states.append(JointState(j.name, state, face, float(opening), float(slip), float(d["rot"][k])))
    if not any_slide:
        mode = "rocking" if any_hinge else "none"
    elif sum_slip >= 0.5 * (sum_slip + sum_open):
        mode = "sliding"
    else:
        mode = "mixed"
    return states, mode


def out_of_plane(model: Model, pos: np.ndarray, R: np.ndarray) -> dict:
    """Out-of-plane motion at one instant: largest |z| displacement of any point [m], largest
    tilt of a body's z axis [rad], largest out-of-plane joint slip [m] and twist [rad]."""
    dz = float(np.abs(PointTracker(model).all_displacements(pos, R)[:, 2]).max())
    kin = joint_kinematics(model, pos, R)
    return {"max_dz_m": dz, "max_tilt_rad": float(out_of_plane_angle(R).max()),
            "max_joint_oop_slip_m": float(kin["oop"].max()), "max_joint_twist_rad": float(kin["twist"].max())}
