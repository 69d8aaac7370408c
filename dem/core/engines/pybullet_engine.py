"""PyBullet backend (DIRECT mode; one physics client per instance).

Choices (the measurements behind them: docs/engines.md#2-pybullet-settings and
docs/decisions/006-solver-settings.md):

* every convex piece is a mesh shape loaded from its own OBJ file (unique temporary directory
  per instance) with ``URDF_INITIALIZE_SAT_FEATURES`` so that face-face contacts get polyhedral
  clipping (4 points per face, no ~1 mm hull margin), hulls offset outward by
  ``PyBulletOptions.inflate``; bodies of several pieces are compound shapes;
* body frame = principal frame at the centroid, mass and principal moments always passed
  together; linear/angular damping 0 (Bullet's default damping 0.04 is not physical here);
* Bullet combines the friction of a contact pair as the *product* of the two bodies'
  coefficients: blocks get ``sqrt(mu_joint)``, the base ``mu_base / sqrt(mu_joint)``;
* driven base (shake table): PyBullet has no kinematic bodies, so the base is a dynamic body
  10^6 times heavier than the arch, its weight cancelled by an external force every step and
  its velocity reset every step to the one that lands it on the prescribed position at the end
  of the step (docs/physics/dem.md#13-driven-base-or-inertial-field);
* bodies are PyBullet multibodies (``useMaximalCoordinates`` off, the default): maximal-coordinate
  bodies step about 2x faster but let a block stick past its friction angle or drift at rest
  (docs/decisions/006-solver-settings.md#pybullet-body-type);
* every number passed to Bullet (vertices, positions, principal frames, masses, moments, the
  gravity of every step) is first made machine-independent (:mod:`dem.core.engines.inputs`);
* joint faces on pads: Bullet's hull builder snaps hull vertices to a grid of its bounding box,
  which moves a joint's ends wherever they are no extreme of the block (a relieved face's, a large
  voussoir's) and tilts the joint's two faces against each other; every joint face collides
  instead on a thin pad built in its own frame, where its vertices stay exact
  (docs/engines.md#9-joint-faces-on-pads-in-pybullet), except a full joint's face on a side Bullet
  keeps exact (its vertices corners of the piece's bounding box); compliant joints' hulls are not offset
  (docs/engines.md#10-compliant-joints);
* planar option: after every step the out-of-plane velocity components (v_z, w_x, w_y) are
  zeroed and the pose is projected back on the plane (PyBullet has no planar constraint
  for free bodies).

The solver and contact parameters are :class:`dem.core.engines.options.PyBulletOptions`, given to
:func:`dem.core.engines.get_engine` (``Settings.engine_options``).
"""
from __future__ import annotations

import ctypes
import math
import os
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from dem.core.contact import body_point_stiffness, hull_offset, normal_stiffness, rayleigh_beta
from dem.core.engines.base import Contacts, Engine
from dem.core.engines.inputs import QUAT_GRID, accel, on_grid, principal_frame, significant
from dem.core.engines.options import PyBulletOptions
from dem.core.model import Model, is_relieved
from dem.core.provenance import package_version
from dem.core.settings import Settings
from dem.core.ties import TieForces
from specimens.mesh import prism


#: Prefix of the folders holding a run's meshes: ``archdem-pb-<pid>-<random>`` in the temporary folder.
MESH_DIR_PREFIX = "archdem-pb-"


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process
        return True
    return True


def mesh_dir() -> Path:
    """A new folder for one engine's meshes, named by this process; first the folders of processes
    that are gone are removed (a killed run, SIGKILL included, cannot remove its own)."""
    tmp = Path(tempfile.gettempdir())
    for d in tmp.glob(f"{MESH_DIR_PREFIX}*-*"):
        pid = d.name[len(MESH_DIR_PREFIX):].split("-")[0]
        if pid.isdigit() and int(pid) != os.getpid() and not _pid_alive(int(pid)):
            shutil.rmtree(d, ignore_errors=True)
    return Path(tempfile.mkdtemp(prefix=f"{MESH_DIR_PREFIX}{os.getpid()}-"))


def _rot_to_quat(R: np.ndarray) -> tuple[float, float, float, float]:
    q = Rotation.from_matrix(R).as_quat()  # x, y, z, w
    return tuple(float(x) for x in q)


def _quat_to_rot(q) -> np.ndarray:
    x, y, z, w = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def offset_polygon(poly: np.ndarray, d: float) -> np.ndarray:
    """Convex counter-clockwise polygon with every edge moved outward by ``d`` [m] along its
    normal (faces stay parallel to the original ones, unlike a radial scaling of the vertices)."""
    P = np.asarray(poly, float)
    if d == 0:
        return P.copy()
    e = np.roll(P, -1, axis=0) - P
    n = np.c_[e[:, 1], -e[:, 0]] / np.linalg.norm(e, axis=1, keepdims=True)  # outward for ccw
    n_prev = np.roll(n, 1, axis=0)
    return P + d * (n + n_prev) / (1.0 + (n * n_prev).sum(1, keepdims=True))


#: Depth of the collision pad of a relieved or compliant joint face [x the model's size, the joint depth of an
#: arch]: the recessed rest of the block stays beyond Bullet's contact distance (docs/engines.md#9-joint-faces-on-pads-in-pybullet).
RELIEF_PAD = 0.05
#: ... of a full rigid joint face: at 0.05 the thickest free catalogue ring collapsed 6 % below its LP, at 0.1
#: every catalogue ring is within 2 % (docs/decisions/013-tilt-on-any-arch.md)
JOINT_PAD = 0.1


def _clip(poly: np.ndarray, p0: np.ndarray, n_in: np.ndarray, h: float) -> np.ndarray:
    """The part ``(x - p0) . n_in >= h`` of a convex counter-clockwise polygon."""
    f = (poly - p0) @ n_in - h
    out = []
    for k in range(len(poly)):
        a, b, fa, fb = poly[k], poly[(k + 1) % len(poly)], f[k], f[(k + 1) % len(poly)]
        if fa >= 0:
            out.append(a)
        if (fa >= 0) != (fb >= 0):
            out.append(a + (b - a) * (fa / (fa - fb)))
    return np.array(out)


def _on_box_corners(piece: np.ndarray, ends: np.ndarray, R: np.ndarray, c: np.ndarray) -> bool:
    """True if ``ends`` (points of the 2-D ``piece``) are corners of the piece's bounding box in the body
    frame (principal axes ``R`` at ``c``), which Bullet's hull builder keeps exactly."""
    to_body = lambda q: (np.c_[q, np.full(len(q), c[2])] - c) @ R  # noqa: E731
    B, E = to_body(piece), to_body(ends)
    lo, hi = B.min(axis=0), B.max(axis=0)
    tol = 1e-9 * float(np.max(hi - lo))
    inplane = np.ptp(B, axis=0) > tol  # the mid-plane's flat axis (z) is no test
    return bool(np.all((np.abs(E - lo) <= tol) | (np.abs(E - hi) <= tol) | ~inplane))


def _face_exact(pieces, A_i: np.ndarray, A_e: np.ndarray, frame: tuple[np.ndarray, np.ndarray], size: float) -> bool:
    """True if the piece whose side holds the joint A_i A_e has that side's vertices on corners of its
    bounding box in the body frame: Bullet then builds the face where it is."""
    d = A_e - A_i
    L = float(np.linalg.norm(d))
    n = np.array([-d[1], d[0]]) / L
    for q in pieces:
        q = np.asarray(q, float)
        on = q[np.abs((q - A_i) @ n) <= 1e-9 * size]
        t = (on - A_i) @ d / L
        if len(on) >= 2 and t.max() > 1e-9 * size and t.min() < L - 1e-9 * size:  # the side overlaps the joint
            return _on_box_corners(q, on, *frame)
    return False


def relief_pieces(model: Model, k: int, pad: float = RELIEF_PAD, frame: tuple[np.ndarray, np.ndarray] | None = None,
                  ) -> list[tuple[np.ndarray, bool]]:
    """Collision polygons of body ``k``, each with a flag "own frame": its pieces recessed by h =
    ``pad`` x ``model.size`` behind each of its joint faces, plus one pad (rectangle A_i, A_e,
    A_e + h n, A_i + h n, n into the body) per joint face. ``frame`` (full joints: the body's
    principal axes R and centroid c): a face on a side whose vertices are corners of its piece's
    bounding box keeps its own piece, which Bullet builds exactly (a rectangular block's, a frame's)."""
    pieces = [np.asarray(p, float) for p in model.bodies[k].pieces]
    h = pad * float(model.size)
    slabs = []
    for j in model.joints:
        if k not in (j.a, j.b):
            continue
        A_i, A_e = np.asarray(j.p_i, float), np.asarray(j.p_e, float)  # the contact ends
        if frame is not None and _face_exact(model.bodies[k].pieces, A_i, A_e, frame, float(model.size)):
            continue
        n_in = np.asarray(j.normal, float) * (1.0 if k == j.b else -1.0)
        pieces = [q for q in (_clip(p, A_i, n_in, h) for p in pieces) if len(q) >= 3]
        slab = np.array([A_i, A_e, A_e + h * n_in, A_i + h * n_in])
        if (slab[1, 0] - slab[0, 0]) * (slab[2, 1] - slab[0, 1]) - (slab[1, 1] - slab[0, 1]) * (slab[2, 0] - slab[0, 0]) < 0:
            slab = slab[::-1].copy()
        slabs.append(slab)
    return [(p, False) for p in pieces] + [(p, True) for p in slabs]


def _write_obj(path: Path, vertices: np.ndarray, faces: np.ndarray) -> None:
    lines = [f"v {v[0]:.12g} {v[1]:.12g} {v[2]:.12g}" for v in vertices]
    lines += [f"f {f[0] + 1} {f[1] + 1} {f[2] + 1}" for f in faces]
    path.write_text("\n".join(lines) + "\n")


def _quiet(fn, fds: tuple[int, ...] = (1,)):
    """Call ``fn`` with the process's C-level ``fds`` (default stdout) sent to /dev/null (pybullet
    prints ``argv[0]=`` on every connection, which would corrupt JSON output)."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(fd) for fd in fds]
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        for fd in fds:
            os.dup2(devnull, fd)
        return fn()
    finally:
        try:  # C stdio may still hold the text in its buffer: out to /dev/null before the fds come back
            ctypes.CDLL(None).fflush(None)
        except (OSError, AttributeError):  # pragma: no cover - no C library to ask
            pass
        for fd, s in zip(fds, saved):
            os.dup2(s, fd)
            os.close(s)
        os.close(devnull)


def _import_pybullet():
    """``pybullet`` and its ``BulletClient``, imported without the "pybullet build time" banner its
    import writes to stderr (a campaign's workers would print it dozens of times)."""
    def load():
        # deferred: imported with the banner silenced, here and nowhere else
        import pybullet as pb
        from pybullet_utils.bullet_client import BulletClient

        return pb, BulletClient

    return _quiet(load, fds=(1, 2))


class PyBulletEngine(Engine):
    name = "pybullet"

    def __init__(self, options: PyBulletOptions | None = None) -> None:
        self.options = options or PyBulletOptions()
        self._p = None
        self._tmp: Path | None = None

    # -- construction ---------------------------------------------------------------------
    def build(self, model: Model, settings: Settings, driven_base: bool = False) -> None:
        pb, BulletClient = _import_pybullet()
        if self._p is not None:
            raise RuntimeError("engine already built")
        self._pb = pb
        self._p = p = _quiet(lambda: BulletClient(connection_mode=pb.DIRECT))
        self._tmp = mesh_dir()
        self.model, self.settings = model, settings
        opt = self.options
        p.setPhysicsEngineParameter(
            fixedTimeStep=settings.dt, numSolverIterations=opt.solver_iterations, numSubSteps=0,
            contactSlop=opt.contact_slop, warmStartingFactor=opt.warm_starting,
            contactERP=opt.contact_erp, frictionERP=opt.friction_erp, deterministicOverlappingPairs=1,
            restitutionVelocityThreshold=0.0 if settings.restitution > 0 else 0.2,
        )
        p.setGravity(0.0, -settings.g, 0.0)
        flags = pb.URDF_INITIALIZE_SAT_FEATURES if opt.sat_features else 0
        f_block = math.sqrt(settings.mu_joint)
        f_base = settings.mu_base / f_block
        n_files = [0]
        inflate = hull_offset(settings, opt.inflate)

        def shape(polys, width, R, c, z_off):
            files, frames = [], []
            for poly in polys:
                own = False
                if isinstance(poly, tuple):  # (polygon, own frame) of a relieved model
                    poly, own = poly
                if own:  # a pad: vertices in its own frame (x along its first edge), pushed out along the normals
                    e = poly[1] - poly[0]
                    ang = math.atan2(e[1], e[0])
                    o = on_grid(poly.mean(axis=0))
                    Rz = np.eye(3)
                    Rz[:2, :2] = [[math.cos(ang), -math.sin(ang)], [math.sin(ang), math.cos(ang)]]
                    m = prism(offset_polygon((poly - o) @ Rz[:2, :2], inflate), width + 2 * inflate)
                    vb = on_grid(np.asarray(m.vertices, float))
                    frames.append(([float(x) for x in on_grid((np.array([o[0], o[1], z_off]) - c) @ R)],
                                   tuple(float(x) for x in on_grid(_rot_to_quat(R.T @ Rz), QUAT_GRID))))
                else:
                    if opt.inflate_normal:
                        m = prism(offset_polygon(poly, inflate), width + 2 * inflate)
                    else:
                        m = prism(poly, width, inflate)
                    v = np.asarray(m.vertices, float).copy()
                    v[:, 2] += z_off
                    vb = on_grid((v - c) @ R)  # = R^T (v - c) row-wise, on the 1 nm grid (dem.core.engines.inputs)
                    frames.append(([0.0, 0.0, 0.0], (0.0, 0.0, 0.0, 1.0)))
                f = self._tmp / f"piece{n_files[0]}.obj"
                n_files[0] += 1
                _write_obj(f, vb, np.asarray(m.faces))
                files.append(str(f))
            if len(files) == 1:
                return p.createCollisionShape(pb.GEOM_MESH, fileName=files[0], flags=flags,
                                              collisionFramePosition=frames[0][0],
                                              collisionFrameOrientation=frames[0][1])
            return p.createCollisionShapeArray([pb.GEOM_MESH] * len(files), fileNames=files, flags=[flags] * len(files),
                                               collisionFramePositions=[f[0] for f in frames],
                                               collisionFrameOrientations=[f[1] for f in frames])

        # base: identity frame; static, or (driven) dynamic and heavy with its centre of mass at the origin
        bshape = shape(model.base.pieces, model.base.width, np.eye(3), np.zeros(3), 0.0)
        self._driven = bool(driven_base)
        self._base_mass = 1e6 * sum(b.mass for b in model.bodies) if driven_base else 0.0
        self._gravity = np.array([0.0, -settings.g, 0.0])
        self._base = p.createMultiBody(baseMass=self._base_mass, baseCollisionShapeIndex=bshape)
        p.changeDynamics(self._base, -1, lateralFriction=f_base, restitution=settings.restitution,
                         rollingFriction=0.0, spinningFriction=0.0, frictionAnchor=int(opt.friction_anchor))
        if driven_base:
            p.changeDynamics(self._base, -1, linearDamping=0.0, angularDamping=0.0,
                             activationState=pb.ACTIVATION_STATE_DISABLE_SLEEPING)
        self._ids: list[int] = []
        self._R0 = np.zeros((model.n_bodies, 3, 3))
        full = not (is_relieved(model) or settings.contact_law == "compliant")
        for k, b in enumerate(model.bodies):
            R, I, q = principal_frame(b.inertia)  # machine-independent (dem.core.engines.inputs)
            c = on_grid(b.centroid)
            mass = significant(b.mass)
            s = shape(relief_pieces(model, k, JOINT_PAD, (R, c)) if full else relief_pieces(model, k),
                      b.width, R, c, float(c[2]))
            bid = p.createMultiBody(baseMass=mass, baseCollisionShapeIndex=s, basePosition=c.tolist(),
                                    baseOrientation=q)
            p.changeDynamics(bid, -1, mass=mass, localInertiaDiagonal=[float(x) for x in I],
                             lateralFriction=f_block, restitution=settings.restitution,
                             rollingFriction=0.0, spinningFriction=0.0, linearDamping=0.0, angularDamping=0.0,
                             frictionAnchor=int(opt.friction_anchor),
                             activationState=pb.ACTIVATION_STATE_DISABLE_SLEEPING)
            self._ids.append(bid)
            self._R0[k] = R
        self._index = {bid: k for k, bid in enumerate(self._ids)}
        self._index[self._base] = -1
        if settings.contact_law == "compliant":
            self._compliant(model, settings)
        self._planar = settings.planar
        self._z0 = np.array([b.centroid[2] for b in model.bodies])
        self._ties = None
        if model.ties:
            self._ties = TieForces(model.ties, np.array([b.centroid for b in model.bodies]))

    def _compliant(self, model: Model, settings: Settings) -> None:
        """Springs and dashpots at the contact points (dem.core.contact): Bullet combines two bodies'
        stiffnesses in series and adds their dampings, so each body gets twice its point stiffness
        and half its point damping (exact for a joint between bodies of equal joints)."""
        beta = rayleigh_beta(settings, model)
        k_bodies, k_base = body_point_stiffness(model, normal_stiffness(settings, model))
        for bid, k in [*zip(self._ids, k_bodies), (self._base, k_base)]:
            self._p.changeDynamics(bid, -1, contactStiffness=float(significant(2.0 * k)),
                                   contactDamping=float(significant(0.5 * beta * k)))

    # -- running --------------------------------------------------------------------------
    def set_gravity(self, vec) -> None:
        self._gravity = vec = accel(vec)
        self._p.setGravity(float(vec[0]), float(vec[1]), float(vec[2]))

    def drive_base(self, x: float, v: float) -> None:
        if not self._driven:
            raise RuntimeError("the base is fixed: build the engine with driven_base=True")
        p = self._p
        pos, _ = p.getBasePositionAndOrientation(self._base)
        dt = self.settings.dt
        # the velocity that ends this step at x (it absorbs the drift of earlier steps; ~v), and
        # back to y = z = 0; contact impulses of the arch change it by ~1e-6 within the step
        p.resetBaseVelocity(self._base, ((x - pos[0]) / dt, -pos[1] / dt, -pos[2] / dt), (0.0, 0.0, 0.0))
        # external forces last one step in PyBullet: cancel the base's weight for this step
        f = (-self._base_mass * self._gravity).tolist()
        p.applyExternalForce(self._base, -1, f, pos, self._pb.WORLD_FRAME)

    def base_motion(self) -> tuple[float, float]:
        if not self._driven:
            return 0.0, 0.0
        pos, _ = self._p.getBasePositionAndOrientation(self._base)
        v, _ = self._p.getBaseVelocity(self._base)
        return float(pos[0]), float(v[0])

    def step(self, n: int = 1) -> None:
        p = self._p
        if self._ties is not None:  # the ties' forces, from the poses before each step (they last one step)
            for _ in range(n):
                pos, R = self.poses()
                for k, point, f in self._ties.update(pos, R):
                    p.applyExternalForce(self._ids[k], -1, f.tolist(), point.tolist(), self._pb.WORLD_FRAME)
                p.stepSimulation()
                if self._planar:
                    self._project()
            return
        if not self._planar:
            for _ in range(n):
                p.stepSimulation()
            return
        for _ in range(n):
            p.stepSimulation()
            self._project()

    def _project(self) -> None:
        p = self._p
        for k, bid in enumerate(self._ids):
            pos, q = p.getBasePositionAndOrientation(bid)
            v, w = p.getBaseVelocity(bid)
            R = _quat_to_rot(q) @ self._R0[k].T
            ang = math.atan2(R[1, 0], R[0, 0])
            Rp = np.array([[math.cos(ang), -math.sin(ang), 0], [math.sin(ang), math.cos(ang), 0], [0, 0, 1]])
            p.resetBasePositionAndOrientation(bid, (pos[0], pos[1], float(self._z0[k])), _rot_to_quat(Rp @ self._R0[k]))
            p.resetBaseVelocity(bid, (v[0], v[1], 0.0), (0.0, 0.0, w[2]))

    def poses(self) -> tuple[np.ndarray, np.ndarray]:
        p = self._p
        n = len(self._ids)
        pos = np.empty((n, 3))
        R = np.empty((n, 3, 3))
        for k, bid in enumerate(self._ids):
            x, q = p.getBasePositionAndOrientation(bid)
            pos[k] = x
            R[k] = _quat_to_rot(q) @ self._R0[k].T
        return pos, R

    def velocities(self) -> tuple[np.ndarray, np.ndarray]:
        p = self._p
        n = len(self._ids)
        v = np.empty((n, 3))
        w = np.empty((n, 3))
        for k, bid in enumerate(self._ids):
            v[k], w[k] = p.getBaseVelocity(bid)
        return v, w

    def contacts(self) -> Contacts:
        cps = self._p.getContactPoints()
        n = len(cps)
        idx = self._index

        def col(k: int, width: int = 3) -> np.ndarray:
            return np.array([c[k] for c in cps], dtype=float).reshape(n, width)

        a = np.array([idx.get(c[1], -1) for c in cps], dtype=int)
        b = np.array([idx.get(c[2], -1) for c in cps], dtype=int)
        # friction force: the two lateral friction forces along their directions
        ft = col(10, 1) * col(11) + col(12, 1) * col(13)
        return Contacts(a, b, col(6), col(7), col(9, 1).reshape(n), ft)

    def versions(self) -> dict:
        return {"engine": self.name, "pybullet": package_version("pybullet"),
                "pybullet_api": int(self._pb.getAPIVersion()) if self._p is not None else None,
                "pybullet_options": self.options.to_dict()}

    def close(self) -> None:
        if self._p is not None:
            try:
                self._p.disconnect()
            except Exception:  # pragma: no cover - already gone
                pass
            self._p = None
        if self._tmp is not None:
            shutil.rmtree(self._tmp, ignore_errors=True)
            self._tmp = None

    def __del__(self) -> None:  # pragma: no cover - safety net
        try:
            self.close()
        except Exception:
            pass
