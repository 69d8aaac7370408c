"""MuJoCo backend (``mujoco`` >= 3.x; measured with 4.0). One ``MjModel``/``MjData`` per instance.

The model is built in memory as an MJCF string from the engine-neutral :class:`dem.core.model.Model`:

* one body per rigid body, body frame = the arch frame translated to the centroid (so the
  rotation of a body is directly the rotation from its as-built orientation), a ``freejoint``
  (or, with ``settings.planar``, two slides x, y and a hinge z: an exact planar constraint),
  an explicit ``<inertial>`` with the mass and the full centroidal inertia tensor;
* one convex mesh geom per convex piece (inline vertices of the prism, offset outward by
  ``MuJoCoOptions.inflate`` as for PyBullet so that touching faces are in contact at step 0; on compliant
  joints not offset, the joints' springs on small spheres at their corners, ``_corner_spheres``); the
  base pads are static geoms of the world body, or, with a driven base (shake table), geoms of
  a body 10^6 times heavier than the arch on a horizontal slide joint whose velocity is set
  every step to the one that lands it on the prescribed position;
* friction: MuJoCo combines a contact pair's friction as the *maximum* of the two geoms'
  values unless their ``priority`` differs, in which case the higher-priority geom's value is
  used. Blocks carry ``mu_joint`` at priority 0, the base ``mu_base`` at priority 1: any pair of
  values is reproduced exactly (block-block ``mu_joint``, block-base ``mu_base``);
* condim 3 (sliding friction only; rolling/torsional friction are not masonry physics),
  elliptic cone, Newton solver, ``implicitfast`` integrator, multi-point convex collision
  (``multiccd``, on by default in 4.x) so a face-face contact gets several points.

Options (:class:`dem.core.engines.options.MuJoCoOptions`, given to :func:`dem.core.engines.get_engine`;
why: docs/engines.md#3-mujoco-settings): MuJoCo's default contacts are soft enough that an arch sinks
at rest, hence a stiff ``solref``/``solimp`` and no-slip iterations. ``step(n)`` advances
``n * settings.dt`` in ``ceil(settings.dt / max_dt)`` equal sub-steps per step, so protocols written
for ``settings.dt`` are unchanged and a smaller ``settings.dt`` refines MuJoCo's step too.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from dem.core.contact import (
    highest_frequency,
    hull_offset,
    joint_width,
    normal_stiffness,
    point_stiffness,
    rayleigh_beta,
)
from dem.core.engines.base import Contacts, Engine
from dem.core.engines.inputs import accel, on_grid, significant
from dem.core.engines.options import MuJoCoOptions
from dem.core.model import Model
from dem.core.settings import Settings
from dem.core.ties import TieForces
from foundation.errors import ArchdemInputError

#: The options a MuJoCo engine runs with unless given others.
DEFAULT_OPTIONS = MuJoCoOptions()


def _f(x) -> str:
    return " ".join(repr(float(v)) for v in np.ravel(x))


def substeps(dt: float, max_dt: float) -> int:
    """Number of equal MuJoCo steps per protocol step ``dt`` so that each is <= ``max_dt``."""
    return max(1, math.ceil(dt / max_dt - 1e-9))


def largest_step(model: Model, settings: Settings, options: MuJoCoOptions) -> float:
    """MuJoCo's largest internal step [s]: ``options.max_dt``, and with compliant joints at most
    ``1 / omega_max`` and ``1 / (beta_R omega_max^2)`` — MuJoCo integrates the contact springs and
    dashpots explicitly, stable only below twice these (stiffness-proportional damping of stiff joints
    costs many steps: at the study's joints, beta_R omega_max ~ 30)."""
    if settings.contact_law != "compliant":
        return options.max_dt

    w = highest_frequency(model, normal_stiffness(settings, model))
    return min(options.max_dt, 1.0 / w, 1.0 / max(rayleigh_beta(settings, model) * w * w, 1e-30))


def mjcf(model: Model, settings: Settings, options: MuJoCoOptions = DEFAULT_OPTIONS, driven_base: bool = False) -> str:
    """The MJCF text of ``model`` (bodies, convex mesh pieces, base, options); ``driven_base``:
    the base is a heavy body on an x slide joint named ``table``."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.mesh import prism

    o = options
    n_sub = substeps(settings.dt, largest_step(model, settings, o))
    h = settings.dt / n_sub
    opt_extra = "".join(f' {k}="{v}"' for k, v in o.extra.items())
    assets, world, bodies = [], [], []
    sol = f'solref="{_f(o.solref)}" solimp="{_f(o.solimp)}" condim="{o.condim}" margin="{_f(o.margin)}"'

    compliant = settings.contact_law == "compliant"
    spheres = _corner_spheres(model) if compliant else []

    def mesh(name: str, poly, width: float, z: float, c: np.ndarray) -> None:
        m = prism(poly, width, hull_offset(settings, o.inflate))
        v = np.asarray(m.vertices, float).copy()
        v[:, 2] += z
        assets.append(f'<mesh name="{name}" vertex="{_f(on_grid(v - c))}"/>')

    for k, poly in enumerate(model.base.pieces):
        mesh(f"base{k}", poly, model.base.width, 0.0, np.zeros(3))
        world.append(f'<geom name="base{k}" type="mesh" mesh="base{k}" friction="{_f(settings.mu_base)} 0 0" '
                     f'priority="1" {sol}/>')
    if driven_base:
        m_base = 1e6 * sum(b.mass for b in model.bodies)
        world[:] = ['<body name="table" pos="0 0 0"><joint name="table" type="slide" axis="1 0 0" damping="0"/>'
                    f'<inertial pos="0 0 0" mass="{_f(m_base)}" diaginertia="{_f([m_base] * 3)}"/>'
                    + "".join(world) + '</body>']
    for i, b in enumerate(model.bodies):
        c = on_grid(b.centroid)  # machine-independent inputs (dem.core.engines.inputs)
        I = significant(np.asarray(b.inertia, float))
        geoms = []
        for k, poly in enumerate(b.pieces):
            nm = f"b{i}p{k}"
            mesh(nm, poly, b.width, float(c[2]), c)
            geoms.append(f'<geom name="{nm}" type="mesh" mesh="{nm}" friction="{_f(settings.mu_joint)} 0 0" '
                         f'priority="0" {sol}/>')
        geoms += [f'<geom name="{sp.name}" type="sphere" size="{_f(CORNER_SPHERE)}" pos="{_f(on_grid(sp.pos - c))}" '
                  'contype="0" conaffinity="0"/>' for sp in spheres if sp.body == i]
        if settings.planar:
            joints = ('<joint name="j{i}x" type="slide" axis="1 0 0" damping="0"/>'
                      '<joint name="j{i}y" type="slide" axis="0 1 0" damping="0"/>'
                      '<joint name="j{i}r" type="hinge" axis="0 0 1" damping="0"/>').format(i=i)
        else:
            joints = f'<freejoint name="j{i}"/>'
        inertial = (f'<inertial pos="0 0 0" mass="{_f(significant(b.mass))}" '
                    f'fullinertia="{_f([I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]])}"/>')
        bodies.append(f'<body name="body{i}" pos="{_f(c)}">{joints}{inertial}{"".join(geoms)}</body>')
    contact = _compliant_pairs(model, settings, o, driven_base, h, spheres) if compliant else ""
    if contact:
        opt_extra += f' impratio="{_f(o.compliant_impratio)}"'
    g = settings.g
    return (
        f'<mujoco model="{model.name}">'
        '<compiler boundmass="0" boundinertia="0" balanceinertia="false" inertiafromgeom="false"/>'
        f'<option timestep="{_f(h)}" gravity="0 {_f(-g)} 0" integrator="{o.integrator}" cone="{o.cone}" '
        f'solver="{o.solver}" iterations="{o.iterations}" tolerance="{_f(o.tolerance)}" '
        f'noslip_iterations="{o.noslip_iterations}"{opt_extra}/>'
        f'<asset>{"".join(assets)}</asset>'
        f'<worldbody>{"".join(world)}{"".join(bodies)}</worldbody>'
        f'{contact}</mujoco>'
    )


#: Radius of the spheres that carry a compliant joint's corners [m]: MuJoCo's convex collision of two faces
#: puts its points where its search lands (some inside the face), a sphere on a face touches it at one point.
CORNER_SPHERE = 1e-4


@dataclass(frozen=True)
class _Corner:
    body: int  # the body carrying the sphere
    other: int  # the body (or base, -1) whose faces it touches
    name: str
    pos: np.ndarray  # centre [m], arch frame: the corner moved by the radius into its body
    joint: int
    share: int  # spheres at this corner: 2 on a joint between blocks (one on each), 1 on the base


def _corner_spheres(model: Model) -> list[_Corner]:
    """A small sphere at each of the four corners of every joint's contact, on each of its blocks."""
    out = []
    for jn, j in enumerate(model.joints):
        sides = [k for k in (j.a, j.b) if k >= 0]
        w, z0 = joint_width(model, j), float(model.bodies[sides[0]].centroid[2])
        n = np.array([j.normal[0], j.normal[1], 0.0])
        for k in sides:
            inward = -n if k == j.a else n  # the normal runs from a to b
            for ci, p in enumerate((j.p_i, j.p_e)):
                for zi, z in enumerate((-0.5 * w, 0.5 * w)):
                    pos = np.array([p[0], p[1], z0 + z]) + CORNER_SPHERE * inward
                    out.append(_Corner(k, j.b if k == j.a else j.a, f"c{jn}b{k}p{ci}{zi}", pos, jn, len(sides)))
    return out


def _compliant_pairs(model: Model, settings: Settings, o: MuJoCoOptions, driven_base: bool, h: float,
                     spheres: list[_Corner]) -> str:
    """``<contact>``: every joint corner's sphere paired with the faces it touches, carrying its share of
    the corner's spring and dashpot (dem.core.contact), and the joints' body pairs excluded from MuJoCo's
    own contacts.

    With impedance ``d`` MuJoCo's contact force is ``-(k r + c v) / ((1 - d) A)`` in the soft limit
    (``A`` the pair's inverse mass, ``1/m_a + 1/m_b``), so ``solref = -(k_pt, c_pt) (1 - d) A``. The friction
    rows get the damping ``d / h`` (``h`` the internal step), which takes a sticking joint's slip velocity out
    within one step: with the normal rows' small damping instead, a tilted arch slides apart."""
    d = o.compliant_impedance
    beta = rayleigh_beta(settings, model)
    base_body = "table" if driven_base else "world"
    geoms = [[f"b{i}p{k}" for k in range(len(b.pieces))] for i, b in enumerate(model.bodies)]
    base_geoms = [f"base{k}" for k in range(len(model.base.pieces))]
    kp = point_stiffness(model, normal_stiffness(settings, model))
    pairs, excl = [], {}
    for sp in spheres:
        j = model.joints[sp.joint]
        inv_mass = sum(1.0 / model.bodies[k].mass for k in (sp.body, sp.other) if k >= 0)
        k_pt = kp[sp.joint] / sp.share
        k_mj, c_mj = significant(k_pt * (1.0 - d) * inv_mass), significant(beta * k_pt * (1.0 - d) * inv_mass)
        mu = settings.mu_base if j.is_base else settings.mu_joint
        for g in base_geoms if sp.other < 0 else geoms[sp.other]:
            pairs.append(f'<pair geom1="{sp.name}" geom2="{g}" condim="{o.condim}" friction="{_f([mu, mu, 0, 0, 0])}" '
                         f'solref="{_f([-k_mj, -c_mj])}" solreffriction="{_f([-0.0, -d / h])}" '
                         f'solimp="{_f([d, d, 0.001, 0.5, 2])}" margin="{_f(o.margin)}"/>')
        lo, hi = min(j.a, j.b), max(j.a, j.b)
        excl[(lo, hi)] = f'<exclude body1="{base_body if lo < 0 else f"body{lo}"}" body2="body{hi}"/>'
    return f'<contact>{"".join(pairs)}{"".join(excl.values())}</contact>'


class MuJoCoEngine(Engine):
    name = "mujoco"

    def __init__(self, options: MuJoCoOptions | None = None) -> None:
        self.options = options or DEFAULT_OPTIONS
        self._m = None
        self._d = None

    def build(self, model: Model, settings: Settings, driven_base: bool = False) -> None:
        # deferred: an optional extra (docs/architecture.md#imports)
        import mujoco

        if self._m is not None:
            raise RuntimeError("engine already built")
        if settings.restitution != 0:  # its soft contacts have no restitution coefficient: refused, not dropped
            raise ArchdemInputError("the mujoco engine runs plastic impacts only (restitution 0); restitution > 0 "
                                    "runs on pybullet")
        self._mj = mujoco
        self.model, self.settings = model, settings
        self._m = mujoco.MjModel.from_xml_string(mjcf(model, settings, self.options, driven_base))
        self._d = mujoco.MjData(self._m)
        self._table = None
        if driven_base:
            j = mujoco.mj_name2id(self._m, mujoco.mjtObj.mjOBJ_JOINT, "table")
            self._table = (int(self._m.jnt_qposadr[j]), int(self._m.jnt_dofadr[j]))
        self._nsub = substeps(settings.dt, largest_step(model, settings, self.options))
        self._bid = np.array([mujoco.mj_name2id(self._m, mujoco.mjtObj.mjOBJ_BODY, f"body{i}")
                              for i in range(model.n_bodies)])
        # body index (-1 = base / world) of each MuJoCo body id
        self._index = np.full(self._m.nbody, -1, int)
        self._index[self._bid] = np.arange(model.n_bodies)
        self._c0 = np.array([b.centroid for b in model.bodies], float)
        self._planar = bool(settings.planar)
        ndof = 3 if self._planar else 6
        adr = self._m.jnt_dofadr[self._m.body_jntadr[self._bid]]
        self._dof = (adr[:, None] + np.arange(ndof)[None, :]).ravel()
        self._ties = None
        if model.ties:
            self._ties = TieForces(model.ties, self._c0)
        mujoco.mj_forward(self._m, self._d)

    def set_gravity(self, vec) -> None:
        self._m.opt.gravity[:] = accel(vec)

    def step(self, n: int = 1) -> None:
        if self._ties is None:
            self._mj.mj_step(self._m, self._d, nstep=n * self._nsub)
            return
        d = self._d
        for _ in range(n * self._nsub):  # the ties' forces, from the poses before each sub-step, at the bodies' centres of mass
            pos, R = self.poses()
            d.xfrc_applied[:] = 0.0
            for k, point, f in self._ties.update(pos, R):
                bid = self._bid[k]
                d.xfrc_applied[bid, :3] += f
                d.xfrc_applied[bid, 3:] += np.cross(point - d.xipos[bid], f)
            self._mj.mj_step(self._m, d, nstep=1)

    def drive_base(self, x: float, v: float) -> None:
        if self._table is None:
            raise RuntimeError("the base is fixed: build the engine with driven_base=True")
        qa, da = self._table
        # the velocity that ends this step at x (absorbing earlier drift; ~v); the heavy table
        # keeps it through the sub-steps to within the arch's contact impulses / 1e6
        self._d.qvel[da] = (x - float(self._d.qpos[qa])) / self.settings.dt

    def base_motion(self) -> tuple[float, float]:
        if self._table is None:
            return 0.0, 0.0
        qa, da = self._table
        return float(self._d.qpos[qa]), float(self._d.qvel[da])

    def poses(self) -> tuple[np.ndarray, np.ndarray]:
        d = self._d
        # xpos/xmat are of the last mj_step's forward pass start; recompute kinematics for the
        # current qpos (cheap) so that poses are those at the end of the step
        self._mj.mj_kinematics(self._m, d)
        pos = d.xpos[self._bid].copy()
        R = d.xmat[self._bid].reshape(-1, 3, 3).copy()
        return pos, R

    def velocities(self) -> tuple[np.ndarray, np.ndarray]:
        d = self._d
        qv = d.qvel[self._dof].reshape(-1, 6) if not self._planar else d.qvel[self._dof].reshape(-1, 3)
        n = len(self._bid)
        if self._planar:  # slide x, slide y, hinge z
            v = np.zeros((n, 3))
            w = np.zeros((n, 3))
            v[:, :2] = qv[:, :2]
            w[:, 2] = qv[:, 2]
            return v, w
        # free joint: linear velocity of the body origin (= centroid) in the world frame, angular
        # velocity in the body frame
        _, R = self.poses()
        return qv[:, :3].copy(), np.einsum("nij,nj->ni", R, qv[:, 3:])

    def contacts(self) -> Contacts:
        m, d = self._m, self._d
        nc = int(d.ncon)
        a = np.empty(nc, int)
        b = np.empty(nc, int)
        pt = np.empty((nc, 3))
        nrm = np.empty((nc, 3))
        fn = np.empty(nc)
        ft = np.empty((nc, 3))
        f6 = np.zeros(6)
        for k in range(nc):
            c = d.contact[k]
            self._mj.mj_contactForce(m, d, k, f6)
            fr = np.asarray(c.frame).reshape(3, 3)
            # MuJoCo: normal frame[0] points from geom1 to geom2; the force is the one geom1
            # exerts on geom2. Interface convention: normal from b to a, friction force on a.
            b[k] = self._index[m.geom_bodyid[c.geom1]]
            a[k] = self._index[m.geom_bodyid[c.geom2]]
            pt[k] = c.pos - 0.5 * c.dist * fr[0]
            nrm[k] = fr[0]
            fn[k] = f6[0]
            ft[k] = f6[1] * fr[1] + f6[2] * fr[2]
        return Contacts(a, b, pt, nrm, fn, ft)

    def versions(self) -> dict:
        # deferred: an optional extra (docs/architecture.md#imports)
        import mujoco

        return {"engine": self.name, "mujoco": mujoco.__version__, "mujoco_options": self.options.to_dict()}

    def close(self) -> None:
        self._m = None
        self._d = None
