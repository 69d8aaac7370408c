"""LMGC90 backend (``compas_lmgc90`` 0.1.x): non-smooth contact dynamics, the masonry field's reference.

Moreau–Jean time stepping (theta method) with Signorini contact, Coulomb friction and an inelastic
impact law (``IQS_CLB``), solved by non-linear Gauss–Seidel (NLGS), on rigid convex polyhedra.

What the binding allows, and how the model is mapped (the measurements: docs/engines.md#11-lmgc90):

* **one simulation per process** (LMGC90's state is Fortran module data): every built engine runs
  its simulation in a worker process of its own (:mod:`dem.core.engines.lmgc90_worker`), so two
  engines may be alive at once and a sweep's workers each start their own;
* **one convex polyhedron per body** (one POLYR contactor per RBDY3): a body of several pieces is
  built as their convex hull (:func:`convex_outline`). The key block of a pointed arch is not convex
  (its intrados has a cusp), free or glued: its hull adds a sliver under the cusp (free Sh06-Sd015
  +5.2 % of the key's area, glued crown +23 %), built with the body's mass (the density scaled), so
  only its centre of mass (lower) and inertia differ (:func:`hull_assembly` is that arch); relieved
  joints are refused (their collision pieces are not the body's mass);
* **one contact law for every pair** as wrapped (``set_see_tables`` writes one see-table row, every
  contactor the same colour): the worker writes the see table itself through LMGC90's procedures the
  extension exports, the base's contactors in a colour of their own: ``mu_joint`` between blocks,
  ``mu_base`` on the base, as in the other engines;
* the gravity is fixed by the binding; it is written into LMGC90's gravity at every change
  (see the worker), which makes the tilt's turning field exact;
* a driven base (shake table) is the equivalent inertial field: the base stays fixed and the ground
  acceleration of each step, recovered from the prescribed velocities, is added to the gravity;
  poses, velocities and contacts are reported in the laboratory frame (the table frame moved by
  the prescribed displacement), as the interface asks;
* the frame: LMGC90's gravity is along -z; archdem's (x, y up, z) is mapped by the proper rotation ``M``;
* velocities: the difference of the last two internal steps' poses (the binding gives no velocities);
* the NLGS tolerance, norm and iteration counts and the contact detection are fixed inside the
  binding (not settable in 0.1.11); ``theta``, the time step and the alert distance are.

``step(n)`` advances ``n * settings.dt`` in ``ceil(settings.dt / max_dt)`` equal LMGC90 steps.
"""
from __future__ import annotations

import math
import pickle
import subprocess
import sys

import numpy as np

from dem.core.engines.base import Contacts, Engine
from dem.core.engines.inputs import accel, on_grid, significant
from dem.core.engines.options import LMGC90Options
from dem.core.model import Model, is_relieved
from dem.core.settings import Settings
from foundation.errors import ArchdemInputError

#: archdem (x, y up, z out of plane) -> LMGC90 (x, y, z up): a proper rotation, x_lmgc = M x_arch.
M = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


#: The options an LMGC90 engine runs with unless given others.
DEFAULT_OPTIONS = LMGC90Options()


def substeps(dt: float, max_dt: float) -> int:
    """Number of equal LMGC90 steps per protocol step ``dt`` so that each is <= ``max_dt``."""
    return max(1, math.ceil(dt / max_dt - 1e-9))


def convex_outline(body) -> tuple[np.ndarray, float]:
    """The one convex counter-clockwise polygon LMGC90 builds body ``body`` as, and the relative area it
    adds: the body's own piece if it has one, otherwise the convex hull of its pieces (0 if they are
    convex together; the key block of a pointed arch, free or glued, is not: its intrados has a cusp)."""
    from scipy.spatial import ConvexHull

    if len(body.pieces) == 1:
        return np.asarray(body.pieces[0], float), 0.0
    pts = np.vstack([np.asarray(p, float) for p in body.pieces])
    hull = ConvexHull(pts)
    area = sum(ConvexHull(np.asarray(p, float)).volume for p in body.pieces)
    return pts[hull.vertices], max(0.0, float(hull.volume / area - 1.0))


def _area_centroid(poly: np.ndarray) -> np.ndarray:
    x, y = poly[:, 0], poly[:, 1]
    cr = x * np.roll(y, -1) - np.roll(x, -1) * y
    a = cr.sum() / 2
    return np.array([((x + np.roll(x, -1)) * cr).sum(), ((y + np.roll(y, -1)) * cr).sum()]) / (6 * a)


def hull_assembly(assembly):
    """``assembly`` as LMGC90 simulates it: every body one convex polyhedron (:func:`convex_outline`), of the
    body's mass (the density is scaled), its centre of mass at the hull's centroid. The limit analysis of
    this assembly is that of the blocks LMGC90 runs (docs/validation.md#17-lmgc90)."""
    from dataclasses import replace as dc_replace

    bodies = []
    for b in assembly.bodies:
        poly, extra = convex_outline(b)
        bodies.append(dc_replace(b, pieces=(poly,), com=_area_centroid(poly)) if extra > 0 else b)
    return dc_replace(assembly, bodies=tuple(bodies))


def _polyhedron(poly: np.ndarray, width: float, z: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Vertices (LMGC90 frame, on the 1 nm grid), triangles and volume of the prism of ``poly``."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.mesh import prism

    m = prism(poly, width)
    v = np.asarray(m.vertices, float).copy()
    v[:, 2] += z
    return on_grid(v @ M.T), np.asarray(m.faces, int), float(m.volume)


def build_message(model: Model, settings: Settings, options: LMGC90Options) -> dict:
    """The worker's ``build`` message: the bodies (archdem's first, then the base pads as supports)."""
    if settings.contact_law != "rigid":
        raise ArchdemInputError("the lmgc90 engine runs rigid joints only (contact law 'rigid'); compliant joints "
                                "need a law and its parameters per contact pair, which compas_lmgc90 does not set")
    if settings.restitution != 0:
        raise ArchdemInputError("the lmgc90 engine runs plastic impacts only (restitution 0, law IQS_CLB)")
    if settings.planar:
        raise ArchdemInputError("the lmgc90 engine has no planar option (compas_lmgc90 exposes no planar constraint)")
    if is_relieved(model):
        raise ArchdemInputError("the lmgc90 engine takes full joints only: relieved joints collide on pieces that are "
                                "not the bodies' mass, and LMGC90 computes mass and inertia from the one polyhedron")
    h = settings.dt / substeps(settings.dt, options.max_dt)
    bodies = []
    for b in model.bodies:
        c = on_grid(np.asarray(b.centroid, float))
        v, f, vol = _polyhedron(convex_outline(b)[0], b.width, float(c[2]))
        bodies.append({"vertices": v, "triangles": f, "centroid": on_grid(M @ c), "support": False,
                       "density": float(significant(b.mass / vol))})
    for poly in model.base.pieces:
        v, f, vol = _polyhedron(np.asarray(poly, float), model.base.width, 0.0)
        bodies.append({"vertices": v, "triangles": f, "centroid": on_grid(v.mean(axis=0)), "support": True,
                       "density": bodies[0]["density"]})
    return {"dt": h, "theta": options.theta, "law": options.law, "joint_params": [float(settings.mu_joint)],
            "base_params": [float(settings.mu_base)], "alert": options.alert, "bodies": bodies}


def _rotvec(R: np.ndarray) -> np.ndarray:
    """Rotation vectors (n, 3) of rotation matrices (n, 3, 3) [rad]."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_matrix(R).as_rotvec()


class LMGC90Engine(Engine):
    name = "lmgc90"

    def __init__(self, options: LMGC90Options | None = None) -> None:
        self.options = options or DEFAULT_OPTIONS
        self._proc = None

    # -- the worker -------------------------------------------------------------------------------
    def _send(self, *msg, flush: bool = False) -> None:
        try:
            pickle.dump(msg, self._proc.stdin, protocol=pickle.HIGHEST_PROTOCOL)
            if flush:
                self._proc.stdin.flush()
        except BrokenPipeError:
            self._died()

    def _died(self):
        rc = self._proc.poll()
        raise RuntimeError(f"the LMGC90 worker process ended (exit code {rc}); its messages are above") from None

    def _ask(self, *msg):
        self._send(*msg, flush=True)
        try:
            status, data = pickle.load(self._proc.stdout)
        except (EOFError, pickle.UnpicklingError):
            self._died()
        if status != "ok":
            raise RuntimeError(f"LMGC90: {data}")
        return data

    def build(self, model: Model, settings: Settings, driven_base: bool = False) -> None:
        import os

        if self._proc is not None:
            raise RuntimeError("engine already built")
        msg = build_message(model, settings, self.options)  # input errors before any process starts
        env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
        self._proc = subprocess.Popen([sys.executable, "-m", "dem.core.engines.lmgc90_worker"],
                                      stdin=subprocess.PIPE, stdout=subprocess.PIPE, env=env)
        self.model, self.settings = model, settings
        self._n = model.n_bodies
        self._h = msg["dt"]
        self._nsub = substeps(settings.dt, self.options.max_dt)
        self._driven = bool(driven_base)
        self._x = self._v = self._a = 0.0  # prescribed base displacement [m], velocity [m/s], acceleration [m/s^2]
        self._g = np.array([0.0, -settings.g, 0.0])
        self._g_sent = None
        self._send("build", msg)
        st = self._ask("state")
        self._frame0 = st["frame"][: self._n].copy()
        # body centroid minus LMGC90's centre of inertia (not zero for a hull body), carried by the rotation
        self._lever = np.array([b.centroid for b in model.bodies], float) - st["coor"][: self._n] @ M
        self._cache = None
        self._field()

    def _field(self) -> None:
        """Send the gravity of the next steps: archdem's, minus the ground acceleration when driven."""
        g = self._g.copy()
        if self._driven:
            g[0] -= self._a
        g_lm = M @ g
        if self._g_sent is None or not np.array_equal(g_lm, self._g_sent):
            self._send("gravity", [float(x) for x in g_lm])
            self._g_sent = g_lm

    # -- running ----------------------------------------------------------------------------------
    def set_gravity(self, vec) -> None:
        self._g = np.asarray(accel(vec), float)
        self._field()

    def drive_base(self, x: float, v: float) -> None:
        if not self._driven:
            raise RuntimeError("the base is fixed: build the engine with driven_base=True")
        # the ground acceleration of this step, recovered from the prescribed velocities (on ACCEL_GRID,
        # as the caller integrated it); the bodies feel it as an inertial field over the fixed base
        self._a = float(accel((v - self._v) / self.settings.dt))
        self._x, self._v = float(x), float(v)
        self._field()

    def base_motion(self) -> tuple[float, float]:
        return (self._x, self._v) if self._driven else (0.0, 0.0)

    def step(self, n: int = 1) -> None:
        # waits for the worker, so that a step's cost and errors land in the call that made it
        self._send("step", int(n) * self._nsub)
        self._ask("sync")
        self._cache = None

    def _state(self) -> dict:
        if self._cache is None:
            self._cache = self._ask("state")
        return self._cache

    def _rotations(self, frame: np.ndarray) -> np.ndarray:
        # the binding's flattened inertia frames F: a body turns by F(t)^T F(0) in LMGC90's frame
        R_lm = np.einsum("nji,njk->nik", frame[: self._n], self._frame0)
        return np.einsum("ij,njk,kl->nil", M.T, R_lm, M)

    def poses(self) -> tuple[np.ndarray, np.ndarray]:
        st = self._state()
        R = self._rotations(st["frame"])
        pos = st["coor"][: self._n] @ M + np.einsum("nij,nj->ni", R, self._lever)
        pos[:, 0] += self._x
        return pos, R

    def velocities(self) -> tuple[np.ndarray, np.ndarray]:
        st = self._state()
        R1, R0 = self._rotations(st["frame"]), self._rotations(st["prev_frame"])
        w = _rotvec(np.einsum("nij,nkj->nik", R1, R0)) / self._h
        v = (st["coor"][: self._n] - st["prev_coor"][: self._n]) @ M / self._h
        v += np.cross(w, np.einsum("nij,nj->ni", R1, self._lever))  # of the body centroid
        v[:, 0] += self._v
        return v, w

    def contacts(self) -> Contacts:
        c = self._ask("contacts")
        idx = c["bodies"] - 1
        idx[idx >= self._n] = -1  # the base pads
        n = c["normal"] @ M  # LMGC90: from the antagonist to the candidate body
        f = c["force"] @ M  # on the candidate body
        ft = f - np.sum(f * n, axis=1, keepdims=True) * n
        pt = c["coor"] @ M
        pt[:, 0] += self._x
        return Contacts(idx[:, 0].copy(), idx[:, 1].copy(), pt, n, c["rloc"][:, 1].copy(), ft)

    def versions(self) -> dict:
        from dem.core.provenance import package_version

        return {"engine": self.name, "compas_lmgc90": package_version("compas_lmgc90"),
                "lmgc90_options": {**self.options.to_dict(),
                                   "nlgs": "tolerance, norm and iterations fixed by compas_lmgc90 (not settable)"}}

    def close(self) -> None:
        p, self._proc = self._proc, None
        if p is None:
            return
        try:
            self._send_to(p, ("close",))
            p.stdin.close()
            p.wait(timeout=10)
        except Exception:  # pragma: no cover - the worker is already gone or stuck
            p.kill()
            p.wait()
        finally:
            if p.stdout is not None:
                p.stdout.close()

    @staticmethod
    def _send_to(p, msg) -> None:
        pickle.dump(msg, p.stdin, protocol=pickle.HIGHEST_PROTOCOL)
        p.stdin.flush()

    def __del__(self) -> None:  # pragma: no cover - safety net
        try:
            self.close()
        except Exception:
            pass
