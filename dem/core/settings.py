"""All physical, contact, solver and detection settings of a simulation — one frozen object.

Every field has a default that passes the validation against exact limit analysis
(``benchmarks/validate_dem.py``; its figures with these defaults are in docs/validation.md, the
measurements behind the engine settings in docs/decisions/006-solver-settings.md). Nothing in it is
one engine's own: those options sit in ``engine_options``, one frozen object per engine
(:mod:`dem.core.engines.options`). The object, with the options of its engine, is stored in every
result file.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field, fields, replace

from dem.core.engines.options import EngineOptions, engine_options, legacy_options
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT, G
from foundation.errors import ArchdemInputError

#: Friction coefficients a simulation takes: below 0.01 (ice on ice) a block slides at any tilt,
#: and 10 already prevents any sliding of the catalogue.
MIN_FRICTION, MAX_FRICTION = 0.01, 1e3
#: Joint models: as stiff as the engine makes them, or springs of a given stiffness per unit area.
CONTACT_LAWS = ("rigid", "compliant")
#: Largest damping ratio of the joints at omega_r (the study's Table 5.1 is 0.5 there, docs/physics/dem.md#17):
#: at 2 every mode above omega_r / 2 is already overdamped, more only slows the blocks down.
MAX_DAMPING_XI = 2.0
#: The engine of shakes, thresholds, failure domains, fragility and records unless one is named: its
#: shake answers hold under the time step and match LMGC90's, PyBullet's do neither
#: (docs/decisions/011-dynamics-engine.md).
DYNAMICS_ENGINE = "mujoco"
#: Protocol step [s] of a shake on DYNAMICS_ENGINE unless one is given: MuJoCo integrates with it
#: (0.125 ms, half its own default), where its shake answers are converged in the step (decision 011).
DYNAMICS_DT = 1.25e-4


@dataclass(frozen=True)
class Settings:
    """Simulation settings (SI units)."""

    # an option's help and unit sit in its field's metadata (foundation.fields.option_help); "shown": the
    # default the help says instead of the field's (None: none)

    # physics
    mu_joint: float = field(default=REFERENCE_MU_JOINT, metadata={"help": "block-block friction"})  # tan 30 deg
    mu_base: float = field(default=REFERENCE_MU_BASE, metadata={"help": "block-base friction"})  # tan 45 deg
    restitution: float = 0.0  # normal restitution; 0 = plastic impacts (masonry)
    g: float = G  # gravity magnitude [m/s^2]; the tilt rotates it at constant magnitude
    # True: out-of-plane velocities zeroed after every step (2D comparison)
    planar: bool = field(default=False, metadata={"help": "constrain the blocks to the arch plane"})

    # engine and step: 0.5 ms with PyBullet's 100 iterations is the cheapest pair that keeps the no-sliding
    # lambda within 3 % of the LP and the hinge layouts (docs/decisions/006-solver-settings.md)
    # the tilt's and the statics'; shakes default to DYNAMICS_ENGINE (dynamics_settings)
    engine: str = field(default="pybullet", metadata={"help": "physics engine, see docs/engines.md §5"})
    # the no-sliding lambda bias shrinks with dt
    dt: float = field(default=5e-4, metadata={"help": "time step", "unit": "s"})
    # the engine's own solver and contact options (dem.core.engines.options; a dict of their fields is read
    # too); None: the engine's defaults, which is what the field holds after construction
    engine_options: EngineOptions | None = None

    # joints: "rigid" is as stiff as each engine's solver makes it (the validated default); "compliant" puts
    # springs and dashpots of these per-unit-area values at the engines' contact points (dem.core.contact)
    contact_law: str = field(default="rigid", metadata={
        "help": "joints: as stiff as the engine makes them, or springs (compliant with --kn)"})
    kn: float = field(default=0.0, metadata={  # 0: none given
        "help": "normal joint stiffness per unit area (compliant)", "unit": "Pa/m", "shown": None})
    youngs: float = field(default=0.0, metadata={  # k_n = E / (the blocks' length across their joints)
        "help": "or the blocks' Young's modulus: kn = E / the blocks' length across their joints", "unit": "Pa",
        "shown": None})
    damping_beta: float = field(default=0.0, metadata={
        "help": "stiffness-proportional Rayleigh damping beta_R of the joints", "unit": "s"})
    damping_xi: float = field(default=0.0, metadata={  # beta_R = 2 xi / omega_r
        "help": f"or the joints' damping ratio at the rotational-impact frequency, 0-{MAX_DAMPING_XI:g}",
        "shown": None})

    # detection (docs/physics/dem.md#5-collapse-criterion)
    collapse_fraction: float = 0.06  # collapse: any body point moved > this x size (ring thickness)
    collapse_speed: float = 1e-3  # ... while that body still moves faster than this [m/s]
    mode_window: tuple[float, float] = (0.015, 0.06)  # mode read between these displacements / size
    hinge_fraction: float = 0.05  # joint opens (hinge) if its opening increment > this x window increment
    slide_fraction: float = 0.05  # joint slides if its slip increment > this x window increment
    record_every: float = 0.01  # [s] time-history sampling (and collapse check) interval
    collapse_confirm: float | None = None  # arches come back: confirm at this x size (docs/decisions/012-collapse-confirmed.md)

    def __post_init__(self) -> None:
        # resolved once here, so that equal settings compare equal and result files store what ran
        object.__setattr__(self, "engine_options", engine_options(self.engine, self.engine_options))
        pos = {"mu_joint": self.mu_joint, "mu_base": self.mu_base, "g": self.g, "dt": self.dt,
               "collapse_fraction": self.collapse_fraction, "record_every": self.record_every}
        for k, v in pos.items():
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ArchdemInputError(f"setting {k} must be a positive number, got {v!r}")
        if not (0.0 <= self.restitution <= 1.0):
            raise ArchdemInputError(f"restitution must be in [0, 1], got {self.restitution!r}")
        if self.record_every < self.dt:
            raise ArchdemInputError(f"record interval {self.record_every:g} s is shorter than dt {self.dt:g} s")
        if self.dt > 0.01:
            raise ArchdemInputError(f"time step dt = {self.dt:g} s is too large (use <= 0.01 s; default 5e-4)")
        if self.dt < 1e-6:  # a million steps per simulated second: a typo, not a setting
            raise ArchdemInputError(f"time step dt = {self.dt:g} s is too small (use >= 1e-6 s; default 5e-4)")
        for name in ("mu_joint", "mu_base"):
            if not MIN_FRICTION <= getattr(self, name) <= MAX_FRICTION:
                raise ArchdemInputError(f"{name} = {getattr(self, name):g} is outside {MIN_FRICTION:g}-{MAX_FRICTION:g} "
                                        "(no sliding: 10)")
        self._check_contact_law()
        lo, hi = self.mode_window
        if not (0 < lo < hi <= self.collapse_fraction):
            raise ArchdemInputError("mode window must satisfy 0 < lo < hi <= collapse_fraction")
        c = self.collapse_confirm
        if c is not None and (isinstance(c, bool) or not (isinstance(c, (int, float)) and math.isfinite(c)
                                                        and c > self.collapse_fraction)):
            raise ArchdemInputError(f"collapse_confirm must be None or a number > collapse_fraction "
                                    f"{self.collapse_fraction:g}, got {c!r}")

    def _check_contact_law(self) -> None:
        if self.contact_law not in CONTACT_LAWS:
            raise ArchdemInputError(f"contact law {self.contact_law!r} is not one of {', '.join(CONTACT_LAWS)}")
        for name in ("kn", "youngs", "damping_beta", "damping_xi"):
            v = getattr(self, name)
            if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                raise ArchdemInputError(f"{name} must be a number >= 0, got {v!r}")
        if self.contact_law == "rigid":
            given = [n for n in ("kn", "youngs", "damping_beta", "damping_xi") if getattr(self, n)]
            if given:
                raise ArchdemInputError(f"{', '.join(given)} belong to the compliant contact law (contact_law 'compliant')")
            return
        if not (self.kn > 0 or self.youngs > 0):
            raise ArchdemInputError("the compliant contact law needs the normal joint stiffness kn > 0 [Pa/m] "
                                    "or the blocks' Young's modulus youngs > 0 [Pa]")
        if self.kn and self.youngs:
            raise ArchdemInputError("give the joints' stiffness as kn or as the blocks' Young's modulus, not both")
        if self.damping_xi > MAX_DAMPING_XI:
            raise ArchdemInputError(f"damping ratio xi = {self.damping_xi:g} is outside 0-{MAX_DAMPING_XI:g}")
        if self.damping_beta and self.damping_xi:
            raise ArchdemInputError("give the joints' damping as beta_R or as xi at omega_r, not both")

    @property
    def record_steps(self) -> int:
        """Steps between records."""
        return max(1, int(round(self.record_every / self.dt)))

    def to_dict(self) -> dict:
        """The settings as JSON values, the engine's options (all of them) under ``engine_options``."""
        d = asdict(self)
        d["mode_window"] = list(self.mode_window)
        d["engine_options"] = self.engine_options.to_dict()
        return d

    @classmethod
    def from_dict(cls, d: dict) -> "Settings":
        """The settings :meth:`to_dict` wrote; a file written before the engine options keeps PyBullet's as
        flat keys, which are read into ``engine_options`` (:func:`dem.core.engines.options.legacy_options`)."""
        d = dict(d)
        engine = d.get("engine", cls.engine)
        engine = engine.decode() if isinstance(engine, bytes) else engine
        old = legacy_options(engine, d)
        names = {f.name for f in fields(cls)}
        kw = {k: v for k, v in d.items() if k in names}
        if "mode_window" in kw:
            kw["mode_window"] = tuple(float(x) for x in kw["mode_window"])
        if "planar" in kw:
            kw["planar"] = bool(kw["planar"])
        for k in ("engine", "contact_law"):
            if k in kw and isinstance(kw[k], bytes):
                kw[k] = kw[k].decode()
        if kw.get("engine_options") is None and old:
            kw["engine_options"] = old
        return cls(**kw)

    def with_(self, **kw) -> "Settings":
        """These settings with the fields of ``kw``; another engine without its options gets its defaults."""
        if kw.get("engine", self.engine) != self.engine and "engine_options" not in kw:
            kw["engine_options"] = None
        return replace(self, **kw)


def dynamics_settings(**kw) -> Settings:
    """:class:`Settings` of a dynamic experiment: ``kw`` over the defaults, the engine
    :data:`DYNAMICS_ENGINE` unless ``kw`` names one, which then runs at :data:`DYNAMICS_DT` unless
    ``kw`` gives ``dt``. Study files written before the engine options keep PyBullet's options as
    flat keys of ``kw``: they are read into ``engine_options``."""
    kw = {"engine": DYNAMICS_ENGINE, **kw}
    old = legacy_options(kw["engine"], kw)
    if old and kw.get("engine_options") is None:
        kw["engine_options"] = old
    if kw["engine"] == DYNAMICS_ENGINE and kw.get("dt") is None:
        kw["dt"] = DYNAMICS_DT
    return Settings(**kw)
