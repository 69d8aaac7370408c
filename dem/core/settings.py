"""All physical, contact, solver and detection settings of a simulation — one frozen object.

Every field has a default that passes the validation of spec §3.4; the comment next to each
gives the measurement behind it (PyBullet 3.2.7, catalogue specimens, see
``benchmarks/validate_dem.py`` and spec 04 §4.1). The object is stored in every result file.

Measured with these defaults (benchmarks/validate_dem.py, 11 specimens x glued/free, dt 0.5 ms,
100 solver iterations, levels ramped 0.5 s and held 1 s or ended at rest from 0.5 s into the hold
(TiltProtocol.rest_after), bisection from (0.972, 1.01) x the LP (TiltProtocol.guess_bracket)
whose ends are simulated only if the bisection ends on one (TiltProtocol.probe_ends),
machine-independent engine inputs): rest drift in 5 s 0.017-0.097 mm (largest point displacement
of any body); single block lambda within 0.4 % of mu and of b/h; no-sliding tilt lambda from 2.8 %
below to 0.05 % above the discrete LP, mean |error| 0.63 %, 22 of 22 within 3 %, 20 of 22 within
2 % (free Sh06-Sd010 -2.8 %, glued -2.3 %); hinge layout equal to the LP's or within 0.5 % of its
lambda on 19 of 22; reference friction at or below the no-sliding lambda + 1 % on 21 of 22 (free
Sh06-Sd010, 1.5 % above it: see GUESS_BRACKET in dem.experiments.tilt). With both ends simulated first
the same run read free Sh1-Sd025 at -3.1 % (its 0.972 x LP level collapsed at rest: see
PROBE_ENDS), everything else identical. The bisection from (0.95, 1.01) x the LP gave, on the same
machine: 5.0 % below to 0.1 % below, mean 0.86 %, 21 of 22 within 3 % (free Sh1-Sd025 -5.0 %), 20
within 2 %, hinge layouts 20, reference 22 of 22. Near the threshold PyBullet's outcome is not
monotonic in lambda, so which case misses changes with any last-bit change of the inputs or of the
protocol: seven runs of the same 22 cases (LP or scan start, ramp 0.5 or 1 s, before and after
dem.core.engines.inputs, i.e. with different last bits, either first bracket, either order of its ends)
gave 19-22 of 22 within 3 % and mean errors 0.63-1.63 %, and one case moved from +0.14 % to -5.5 %. Since
dem.core.engines.inputs the same run gives the same numbers on an AVX-512 and an AVX2-only CPU. The previous defaults (dt 1 ms, 200 iterations, about the same cost per
simulated second) were 0.3-5.1 % low, 8 of 22 beyond 3 %.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, fields, replace

from specimens.constants import G
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from specimens.errors import ArchdemInputError


@dataclass(frozen=True)
class Settings:
    """Simulation settings (SI units)."""

    # --- physics -------------------------------------------------------------------------
    mu_joint: float = REFERENCE_MU_JOINT  # block-block Coulomb friction (tan 30 deg)
    mu_base: float = REFERENCE_MU_BASE  # block-base Coulomb friction (tan 45 deg)
    restitution: float = 0.0  # normal restitution; 0 = plastic impacts (masonry)
    g: float = G  # gravity magnitude [m/s^2]; the tilt rotates it at constant magnitude
    planar: bool = False  # True: out-of-plane velocities zeroed after every step (2D comparison)
    # --- engine --------------------------------------------------------------------------
    engine: str = "pybullet"
    dt: float = 5e-4  # [s]; the no-sliding lambda bias shrinks with dt (spec 04 §4.1). Full validation:
    #   1 ms/200 iterations 0.3-5.1 % low (8 of 22 beyond 3 %, mean 2.5 %); 0.5 ms/100 see above (mean
    #   1.2 %); 0.5 ms/50 (1.5x cheaper) mean 1.4 %, 2 beyond 3 % and 6 of 22 hinge layouts wrong (joints
    #   read as sliding at mu = 10); 0.5 ms/30 -3.2 and -3.6 % on the two worst. All drift < 0.11 mm/5 s.
    solver_iterations: int = 100  # per step; 0.5 ms/100 costs about what 1 ms/200 did per simulated second.
    #   0.5 ms/200 with the current protocol (validate_dem.py --iterations 200; 187 s against 117 s):
    #   mean error 0.70 % against 0.63 %, 21 of 22 within 3 % (free Sh1-Sd025 -3.7 %), hinge layouts 18
    #   against 19, reference 22 of 22 against 21. The misses move: free Sh06-Sd010's reference rule and
    #   free Sh06-Sd015's hinges pass, glued Sh06-Sd010's and free Sh06-Sd020's hinges miss
    contact_slop: float = 0.0  # PyBullet default 1e-5 m sinks every joint 10 um (~0.1 mm crown drop)
    warm_starting: float = 1.0  # PyBullet default 0.1 creeps; 1.0 lets contact impulses persist at rest
    friction_anchor: bool = True  # anchors static friction: no creep of blocks at rest
    sat_features: bool = True  # polyhedral contact (4 points per face) instead of a ~1 mm hull margin
    inflate: float = 1e-6  # hulls offset outward [m] so touching faces are in contact at step 0
    inflate_normal: bool = False  # False: vertices pushed 1 um radially from the piece centroid
    #   (specimens.mesh.prism); True: faces offset along their normals. Full validation of both:
    #   same lambda bias within run-to-run scatter (+-1-2 %), but the normal offset let 5 free
    #   specimens drift 0.10-1.0 mm in 5 s at rest against <= 0.102 mm for the radial one.
    contact_erp: float = 0.2  # PyBullet default; 0.5-0.8 made the rest drift worse (0.16-0.25 mm in 5 s)
    friction_erp: float = 1.0  # friction drift correction; default left free Sh06-Sd010 creeping 0.7 mm
    #   in 5 s at its crown joints (near the friction limit at rest), 0.8 -> 0.14 mm, 1.0 -> 0.09 mm (plateau)
    # --- detection (spec §3.3) -----------------------------------------------------------
    collapse_fraction: float = 0.06  # collapse: any body point moved > this x size (ring thickness)
    collapse_speed: float = 1e-3  # ... while that body still moves faster than this [m/s]
    mode_window: tuple[float, float] = (0.015, 0.06)  # mode read between these displacements / size
    hinge_fraction: float = 0.05  # joint opens (hinge) if its opening increment > this x window increment
    slide_fraction: float = 0.05  # joint slides if its slip increment > this x window increment
    record_every: float = 0.01  # [s] time-history sampling (and collapse check) interval

    def __post_init__(self) -> None:
        pos = {"mu_joint": self.mu_joint, "mu_base": self.mu_base, "g": self.g, "dt": self.dt,
               "collapse_fraction": self.collapse_fraction, "record_every": self.record_every}
        for k, v in pos.items():
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ArchdemInputError(f"setting {k} must be a positive number, got {v!r}")
        if not (0.0 <= self.restitution <= 1.0):
            raise ArchdemInputError(f"restitution must be in [0, 1], got {self.restitution!r}")
        if not (isinstance(self.solver_iterations, int) and self.solver_iterations >= 1):
            raise ArchdemInputError(f"solver iterations must be an integer >= 1, got {self.solver_iterations!r}")
        if self.record_every < self.dt:
            raise ArchdemInputError(f"record interval {self.record_every:g} s is shorter than dt {self.dt:g} s")
        if self.dt > 0.01:
            raise ArchdemInputError(f"time step dt = {self.dt:g} s is too large (use <= 0.01 s; default 5e-4)")
        lo, hi = self.mode_window
        if not (0 < lo < hi <= self.collapse_fraction):
            raise ArchdemInputError("mode window must satisfy 0 < lo < hi <= collapse_fraction")

    @property
    def record_steps(self) -> int:
        """Steps between records."""
        return max(1, int(round(self.record_every / self.dt)))

    def to_dict(self) -> dict:
        d = asdict(self)
        d["mode_window"] = list(self.mode_window)
        return d

    @classmethod
    def from_dict(cls, d: dict) -> "Settings":
        names = {f.name for f in fields(cls)}
        kw = {k: v for k, v in d.items() if k in names}
        if "mode_window" in kw:
            kw["mode_window"] = tuple(float(x) for x in kw["mode_window"])
        for k in ("planar", "friction_anchor", "sat_features", "inflate_normal"):
            if k in kw:
                kw[k] = bool(kw[k])
        if "solver_iterations" in kw:
            kw["solver_iterations"] = int(kw["solver_iterations"])
        if "engine" in kw and isinstance(kw["engine"], bytes):
            kw["engine"] = kw["engine"].decode()
        return cls(**kw)

    def with_(self, **kw) -> "Settings":
        return replace(self, **kw)


