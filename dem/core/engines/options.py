"""Each engine's own options, one frozen dataclass per engine, importable without the engines' libraries.

``Settings.engine_options`` carries the options of ``Settings.engine`` (its defaults unless given);
``get_engine(name, options)`` hands them to the backend, and every result file stores them with the
settings. The measurements behind the defaults: docs/engines.md and docs/decisions/006-solver-settings.md.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from typing import Any, ClassVar

from foundation.errors import ArchdemInputError


def _number(owner: str, name: str, v: Any, lo: float, hi: float = math.inf, lo_open: bool = False) -> None:
    """Refuse in one line an option that is no finite number in ``[lo, hi]`` (``(lo, hi]`` if ``lo_open``)."""
    ok = isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and lo <= v <= hi
    if not ok or (lo_open and v == lo):
        span = f"{'(' if lo_open else '['}{lo:g}, {hi:g}]"
        raise ArchdemInputError(f"{owner} option {name} must be a number in {span}, got {v!r}")


def _integer(owner: str, name: str, v: Any, lo: int) -> None:
    if isinstance(v, bool) or not isinstance(v, int) or v < lo:
        raise ArchdemInputError(f"{owner} option {name} must be an integer >= {lo}, got {v!r}")


def _choice(owner: str, name: str, v: Any, choices: tuple) -> None:
    if v not in choices:
        raise ArchdemInputError(f"{owner} option {name} must be one of {', '.join(map(str, choices))}, got {v!r}")


def _flag(owner: str, name: str, v: Any) -> None:
    if not isinstance(v, bool):
        raise ArchdemInputError(f"{owner} option {name} must be true or false, got {v!r}")


@dataclass(frozen=True)
class EngineOptions:
    """What every engine's options share: ``with_``, ``to_dict`` (stored in result files) and ``from_dict``."""

    engine: ClassVar[str] = ""

    def with_(self, **kw) -> "EngineOptions":
        """These options with the fields of ``kw`` (checked as any)."""
        return replace(self, **kw)

    def to_dict(self) -> dict:
        """The options as JSON values (tuples as lists)."""
        return {f.name: list(v) if isinstance(v, tuple) else (dict(v) if isinstance(v, dict) else v)
                for f in fields(self) for v in [getattr(self, f.name)]}

    @classmethod
    def from_dict(cls, d: Mapping) -> "EngineOptions":
        """The options of ``d`` (as :meth:`to_dict` wrote them, or any of their fields): unknown names are
        refused in one line; values read from a file get their field's type back (lists -> tuples, 0/1 -> bools)."""
        known = {f.name: f for f in fields(cls)}
        unknown = sorted(set(d) - set(known))
        if unknown:
            raise ArchdemInputError(f"unknown option(s) {', '.join(unknown)} of the {cls.engine} engine; "
                                    f"its options: {', '.join(known)}")
        kw = {}
        for k, v in d.items():
            default = known[k].default
            if isinstance(v, bytes):
                v = v.decode()
            if isinstance(default, tuple) and isinstance(v, list):
                v = tuple(v)
            elif isinstance(default, bool) and not isinstance(v, bool) and v in (0, 1):
                v = bool(v)
            elif type(default) is int and isinstance(v, float) and v.is_integer():
                v = int(v)
            kw[k] = v
        return cls(**kw)


@dataclass(frozen=True)
class PyBulletOptions(EngineOptions):
    """PyBullet's solver and contact options (docs/engines.md#2-pybullet-settings): its own defaults creep
    or sink at rest; these are the validated ones (docs/decisions/006-solver-settings.md)."""

    engine: ClassVar[str] = "pybullet"

    solver_iterations: int = field(default=100, metadata={"help": "PyBullet's solver iterations per step"})
    """Default 100 per step: 200 is no better on the validation, 50 reads joints as sliding at mu = 10."""
    contact_slop: float = 0.0
    """Default 0 m: PyBullet's own 1e-5 m lets every joint sink 10 um (about 0.1 mm of crown drop)."""
    warm_starting: float = 1.0
    """Default 1.0: contact impulses persist from step to step at rest; PyBullet's own 0.1 lets blocks creep."""
    friction_anchor: bool = True
    """Default on: static friction anchored at its contact point, no creep at rest; off lets blocks under static friction
    drift."""
    sat_features: bool = True
    """Default on: polyhedral contact with 4 points per face pair at the real faces; off, a hull keeps a ~1 mm margin and
    blocks float that far."""
    inflate: float = 1e-6
    """Default 1e-6 m: hulls offset outward so that touching faces are in contact at step 0 (rigid joints); 0 lets blocks
    fall free for a few steps, more preloads the joints."""
    inflate_normal: bool = False
    """Default off: the offset pushes vertices radially from the piece centroid; on, faces move along their normals,
    which let free arches drift more at rest."""
    contact_erp: float = 0.2
    """Default 0.2 (PyBullet's): the share of a penetration corrected per step; 0.5-0.8 made the drift at rest worse."""
    friction_erp: float = 1.0
    """Default 1.0: friction drift corrected within a step; lower values let blocks near their friction limit creep."""

    def __post_init__(self) -> None:
        o = "PyBullet"
        _integer(o, "solver_iterations", self.solver_iterations, 1)
        for name, hi in (("contact_slop", 1e-3), ("inflate", 1e-3), ("warm_starting", 1.0), ("contact_erp", 1.0),
                         ("friction_erp", 1.0)):
            _number(o, name, getattr(self, name), 0.0, hi)
        for name in ("friction_anchor", "sat_features", "inflate_normal"):
            _flag(o, name, getattr(self, name))


@dataclass(frozen=True)
class MuJoCoOptions(EngineOptions):
    """MuJoCo's solver and contact options (docs/engines.md#3-mujoco-settings): its default contacts are
    soft enough that an arch sinks at rest, hence a stiff ``solref``/``solimp`` and no-slip iterations."""

    engine: ClassVar[str] = "mujoco"

    max_dt: float = 2.5e-4
    """Default 0.25 ms, the largest internal step (a protocol step is split into equal ones): 0.5 ms is not converged
    with friction, 1 ms breaks solref (tc >= 2 dt)."""
    solref: tuple[float, float] = (0.001, 1.0)
    """Default (1 ms, 1): contact time constant [s] and damping ratio; MuJoCo's own 0.02 s lets an arch collapse at rest."""
    solimp: tuple[float, float, float] = (0.99, 0.999, 0.0001)
    """Default (0.99, 0.999, 1e-4 m): impedance near 1, stiff contacts with little penetration; lower values soften the
    joints."""
    noslip_iterations: int = 10
    """Default 10: a post-solve no-slip pass that removes the creep of blocks under static friction; 0 saves its cost and
    lets them creep."""
    iterations: int = 100
    """Default 100 (MuJoCo's): Newton iterations per step, a cap that Newton's few iterations never reach."""
    tolerance: float = 1e-10
    """Default 1e-10 (MuJoCo's own 1e-8): the solver stops there; larger values end earlier with less converged contact
    forces."""
    condim: int = 3
    """Default 3: sliding friction only; 4 and 6 add torsional and rolling friction, which are no masonry physics."""
    cone: str = "elliptic"
    """Default elliptic: the Coulomb cone itself; pyramidal (MuJoCo's own default) approximates it by facets."""
    solver: str = "Newton"
    """Default Newton: converges in a few iterations; CG and PGS take many more on stiff contacts."""
    integrator: str = "implicitfast"
    """Default implicitfast: velocity-dependent forces integrated implicitly, stable where Euler's explicit ones are not."""
    margin: float = 0.0
    """Default 0 m: contacts start at touch; a margin would create contacts (and forces) before faces meet."""
    inflate: float = 1e-6
    """Default 1e-6 m: hulls offset outward so that touching faces are in contact at step 0 (rigid joints); 0 lets blocks
    fall free for a few steps."""
    compliant_impedance: float = 0.001
    """Default 0.001: impedance d of compliant joints, whose contact is then a spring of stiffness -solref[0] / ((1 - d)
    A); 0.01 put a block's frequencies 1-2 % low."""
    compliant_impratio: float = 1e4
    """Default 1e4: friction-to-normal impedance ratio with compliant joints, friction rows nearly hard while the normal
    ones are soft; lower lets joints slip."""
    extra: dict = field(default_factory=dict, hash=False)
    """Default none: other attributes of MJCF's ``<option>``, written verbatim (MuJoCo refuses unknown ones)."""

    def __post_init__(self) -> None:
        o = "MuJoCo"
        _number(o, "max_dt", self.max_dt, 0.0, 0.01, lo_open=True)
        for name, n in (("solref", 2), ("solimp", 3)):
            v = getattr(self, name)
            if not (isinstance(v, tuple) and len(v) == n):
                raise ArchdemInputError(f"{o} option {name} must be {n} numbers, got {v!r}")
            for x in v:
                _number(o, name, x, -math.inf)
        _integer(o, "noslip_iterations", self.noslip_iterations, 0)
        _integer(o, "iterations", self.iterations, 1)
        _choice(o, "condim", self.condim, (1, 3, 4, 6))
        _choice(o, "cone", self.cone, ("pyramidal", "elliptic"))
        _choice(o, "solver", self.solver, ("PGS", "CG", "Newton"))
        _choice(o, "integrator", self.integrator, ("Euler", "RK4", "implicit", "implicitfast"))
        for name, hi in (("tolerance", 1.0), ("margin", 1e-2), ("inflate", 1e-3), ("compliant_impratio", math.inf)):
            _number(o, name, getattr(self, name), 0.0, hi)
        _number(o, "compliant_impedance", self.compliant_impedance, 0.0, 1.0, lo_open=True)
        if not isinstance(self.extra, dict):
            raise ArchdemInputError(f"{o} option extra must be a dict of <option> attributes, got {self.extra!r}")


@dataclass(frozen=True)
class LMGC90Options(EngineOptions):
    """LMGC90's settable parameters (docs/engines.md#11-lmgc90); the NLGS tolerance, norm and iteration
    counts are fixed inside compas_lmgc90."""

    engine: ClassVar[str] = "lmgc90"

    max_dt: float = 2.5e-4
    """Default 0.25 ms, the largest LMGC90 step (a protocol step is split into equal ones): at 0.5 ms a block's first
    impact of a 5 Hz shake is missed (docs/engines.md#11-lmgc90)."""
    theta: float = 0.5
    """Default 0.5 (midpoint) of the Moreau-Jean integrator: no numerical damping; 1 (implicit Euler) damps the motion
    numerically (the tilts and block shakes measured came out the same)."""
    alert: float = 1e-3
    """Default 1e-3 m (the binding's): contact detection distance; smaller misses contacts of fast blocks, larger costs
    detection time."""
    law: str = "IQS_CLB"
    """Default IQS_CLB: inelastic shock and Coulomb friction, masonry's plastic impacts."""

    def __post_init__(self) -> None:
        o = "LMGC90"
        _number(o, "max_dt", self.max_dt, 0.0, 0.01, lo_open=True)
        _number(o, "theta", self.theta, 0.0, 1.0, lo_open=True)
        _number(o, "alert", self.alert, 0.0, 1.0, lo_open=True)
        if not (isinstance(self.law, str) and self.law):
            raise ArchdemInputError(f"{o} option law must be the name of an LMGC90 contact law, got {self.law!r}")


#: Each engine's options class, by engine name.
OPTIONS: dict[str, type[EngineOptions]] = {c.engine: c for c in (PyBulletOptions, MuJoCoOptions, LMGC90Options)}
#: The PyBullet options ``Settings`` held as fields of its own before they moved into ``engine_options``:
#: files written then keep them as flat keys (:func:`legacy_options`).
LEGACY_KEYS = ("solver_iterations", "contact_slop", "warm_starting", "friction_anchor", "sat_features", "inflate",
               "inflate_normal", "contact_erp", "friction_erp")


def _known(engine: str) -> type[EngineOptions]:
    if engine not in OPTIONS:
        raise ArchdemInputError(f"unknown engine {engine!r}; available: {', '.join(sorted(OPTIONS))}")
    return OPTIONS[engine]


def engine_options(engine: str, options: EngineOptions | Mapping | None = None) -> EngineOptions:
    """The options of ``engine``: its defaults for None, the options of a dict of their fields (as files store
    them), ``options`` itself if they are that engine's; another engine's are refused in one line."""
    cls = _known(engine)
    if options is None:
        return cls()
    if isinstance(options, Mapping):
        return cls.from_dict(options)
    if not isinstance(options, cls):
        other = getattr(options, "engine", "") or type(options).__name__
        raise ArchdemInputError(f"the {engine} engine takes {cls.__name__}, not the options of {other}")
    return options


def legacy_options(engine: str, kw: dict) -> dict:
    """Remove the flat keys of :data:`LEGACY_KEYS` from ``kw`` and return the options they set on ``engine``:
    all of them on PyBullet, ``inflate`` on MuJoCo (which offset its hulls by it too), none on LMGC90
    (which never read them)."""
    old = {k: kw.pop(k) for k in LEGACY_KEYS if k in kw}
    if engine == "pybullet":
        return old
    return {"inflate": old["inflate"]} if engine == "mujoco" and "inflate" in old else {}


__all__ = ["EngineOptions", "PyBulletOptions", "MuJoCoOptions", "LMGC90Options", "OPTIONS",
           "engine_options", "legacy_options"]
