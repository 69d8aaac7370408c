"""Friction-threshold maps: the DEM tilt test swept over the joint friction ``mu`` (docs/physics/dem.md#12-friction-map-and-mu).

For each specimen (a catalogue arch or any :class:`~specimens.geometry.PointedArch`) a
**study** (:mod:`dem.studies.sweep`) runs one tilt test per friction value of a grid; each case gives
the collapse multiplier ``lambda``, the failure mode and the joint states. The rocking/sliding
threshold ``mu*`` is then refined by bisection on ``mu`` inside the grid interval that brackets
the mode change; every bisection round is one more :func:`dem.studies.sweep.run_study` call on the
**same study file**, so ``resume=True`` skips every case (grid or bisection) already stored —
the bisection midpoints follow deterministically from the stored results.

Definitions (recorded with every result):

* A DEM point *slides* when its mode is ``sliding`` or ``mixed`` (some joint slips at
  collapse), *rocks* when it is ``rocking``; other outcomes (``none``, failed cases) are ignored.
* **DEM mu\\***: as in the reference study, friction is raised until the mode switches from
  sliding to rocking: ``hi`` = the smallest friction at which the specimen rocks, ``lo`` = the
  largest smaller friction at which it slides; after refinement ``mu* = (lo + hi) / 2`` with the
  bracket ``[lo, hi]`` stored beside it. A sliding/mixed point above ``hi`` (non-monotonic
  outcome near the threshold, or a mixed mechanism with a little slip) is flagged
  (``monotonic = False``) and listed with the points. ``status``: ``bracketed``,
  ``all_rocking`` (the smallest friction of the grid already rocks: ``mu* <= `` it; ``mu*`` is
  ``None``), ``all_sliding`` (``mu* >`` the largest friction) or ``no_data``.
* **LP mu\\***: the static LP (:func:`analytic.limit.limit_discrete.solve_lp`, associative friction)
  gives ``lambda_LP(mu)``, non-decreasing in ``mu``; its no-sliding value is the LP with
  ``mu_joint = inf`` at the same ``mu_base`` (equal to the kinematic enumeration when the base
  does not slide). ``mu*_LP`` = the least ``mu`` with ``lambda_LP(mu) >= (1 - 1e-6) lambda_no_sliding``,
  found by bisection (to ``1e-4``). Below it the LP mechanism has a joint that slides (checked:
  the LP joint states just below and just above ``mu*_LP`` are stored).
* **Non-associative mu\\***: the same definition, tolerances and bisection with the least collapse
  multiplier of Coulomb friction without dilatancy
  (:func:`analytic.limit.non_associative.solve_non_associative`, a mixed-integer program; its value is
  ``<=`` the LP's, so it is short of ``lambda_no_sliding`` wherever the LP is and its mu* is ``>=``
  mu*_LP: the bisection starts from the LP's final bracket, its upper end doubled while short). Its
  lambda(mu) is computed on the map's grid only: about 1 s a friction value for a catalogue arch.
* **Two-bar mu\\***: :func:`analytic.limit.two_bar.mu_star` with the rocking multiplier of the
  *discrete* arch (kinematic enumeration, the arch the DEM simulates); the value against the
  continuous-profile multiplier is stored too (``mu_star_two_bar_continuous``).

Scale: a parametric arch larger than the catalogue's (``Rc_ref = 0.2 m``) has its tilt-protocol
times (ramp, hold, scan rate) and the time step / record interval scaled by
``s = sqrt(Rc / Rc_ref)`` (``time_scale="auto"``): rigid blocks with Coulomb friction are
similar under ``t -> s t`` when lengths scale by ``s^2``, so geometrically similar arches run
the same dimensionless simulation and the same number of steps.

Case functions are importable ``"module:function"`` names: :func:`tilt_case` (the DEM) and
:func:`synthetic_case` (a closed-form stand-in with a known ``mu*``, for tests and dry runs of
the map machinery).
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, ClassVar, Mapping, Sequence

import numpy as np

from analytic.search import midpoint, search, wide
from dem.core.settings import MAX_FRICTION, MIN_FRICTION
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.tilt import DEM_CASE, MAP_PROTOCOL, MAP_TILT_TOL, RC_REF, make_case, scaled_protocol
from specimens.blocks import DEFAULT_VOUSSOIRS, check_contact, discretise
from specimens.catalogue import get_specimen, select_specimens
from specimens.constants import REFERENCE_MU_BASE
from specimens.drawn import DrawnAssembly
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from foundation.io import parse_grid

SLIDING_MODES = ("sliding", "mixed")
ROCKING_MODES = ("rocking",)
LP_REL_TOL = 1e-6  # lambda_LP(mu) counts as the no-sliding value within this relative tolerance
LP_MU_TOL = 1e-4  # bisection tolerance of mu*_LP
STUDY_KIND = "friction_map"


# ----------------------------------------------------------------------------- parameters
def parse_mu_grid(text: str) -> list[float]:
    """``"start:stop:step"`` (stop included) or ``"a,b,c"`` -> sorted friction values
    (:func:`foundation.io.parse_grid`)."""
    return check_mus(parse_grid(str(text).strip(), "friction grid"))


def check_mus(mus: Sequence[float]) -> list[float]:
    """Sorted, de-duplicated friction values rounded to 1e-9 (stable case keys), each within the
    simulator's range (``Settings``: MIN_FRICTION to MAX_FRICTION)."""
    out = sorted({round(float(m), 9) for m in mus})
    if not out:
        raise ArchdemInputError("the friction grid is empty")
    for m in out:
        if not (math.isfinite(m) and MIN_FRICTION <= m <= MAX_FRICTION):
            raise ArchdemInputError(f"friction coefficients must be {MIN_FRICTION:g} to {MAX_FRICTION:g}, got {m!r}")
    return out


def _specimen_list(specimens) -> list:
    """Specimen objects (``.id``, ``.arch``) from objects, ids, or a selection string."""
    if isinstance(specimens, str):
        return select_specimens(specimens)
    out = []
    for s in specimens:
        out.append(get_specimen(s) if isinstance(s, str) else s)
    if not out:
        raise ArchdemInputError("no specimens selected")
    ids = [s.id for s in out]
    if len(set(ids)) != len(ids):
        raise ArchdemInputError(f"duplicate specimen ids: {ids}")
    return out


# ----------------------------------------------------------------------------- bracketing
@dataclass(frozen=True)
class Threshold:
    """DEM threshold from the points of one specimen: bracket ``[lo, hi]`` (``None`` where open),
    ``mu_star`` (midpoint, or ``None``), ``status`` and ``monotonic`` (see module docstring)."""

    lo: float | None
    hi: float | None
    status: str
    monotonic: bool

    @property
    def mu_star(self) -> float | None:
        return 0.5 * (self.lo + self.hi) if self.status == "bracketed" else None

    @property
    def width(self) -> float:
        return (self.hi - self.lo) if self.status == "bracketed" else math.inf


def threshold_bracket(mus: Sequence[float], modes: Sequence[str]) -> Threshold:
    """The rocking/sliding bracket of ``(mu, mode)`` points (see the module docstring)."""
    pts = sorted((float(m), str(md)) for m, md in zip(mus, modes))
    slide = [m for m, md in pts if md in SLIDING_MODES]
    rock = [m for m, md in pts if md in ROCKING_MODES]
    if not slide and not rock:
        return Threshold(None, None, "no_data", True)
    if not rock:
        return Threshold(max(slide), None, "all_sliding", True)
    if not slide or min(rock) < min(slide):
        return Threshold(None, min(rock), "all_rocking", not slide)
    hi = min(rock)
    lo = max(m for m in slide if m < hi)
    return Threshold(lo, hi, "bracketed", not any(m > hi for m in slide))


def bisection_point(th: Threshold, min_width: float = 0.0) -> float | None:
    """The next friction to simulate inside the bracket (its midpoint, rounded to 1e-9), or None."""
    if th.status != "bracketed" or not wide(th.lo, th.hi, min_width, "width"):
        return None
    mid = round(midpoint(th.lo, th.hi), 9)
    return mid if th.lo < mid < th.hi else None


# ----------------------------------------------------------------------------- analytic curves
@dataclass(frozen=True)
class AnalyticCurves:
    """Analytic references of one specimen at base friction ``mu_base``.

    ``mu``: the friction values of the curves; ``lam_lp``: LP lambda(mu) (associative);
    ``lam_two_bar``: two-bar lambda_slide(mu); ``lam_no_sliding``: LP with ``mu_joint = inf``;
    ``lam_kinematic``: discrete four-hinge enumeration (no sliding anywhere); ``lam_continuous``:
    continuous-profile four-hinge multiplier; ``lam_two_bar_0``: frictionless two-bar;
    ``mu_star_lp``, ``mu_star_two_bar`` (against ``lam_kinematic``), ``mu_star_two_bar_continuous``;
    ``lp_states_below`` / ``lp_states_above``: LP joint states (non-closed) just below/above ``mu_star_lp``;
    ``mu_star_na``: mu* without dilatancy (non-associative); ``mu_na`` / ``lam_na``: its lambda(mu), on
    the map's grid (empty when not computed); ``seconds_na``: wall time of these two [s].
    """

    mu: np.ndarray
    lam_lp: np.ndarray
    lam_two_bar: np.ndarray
    lam_no_sliding: float
    lam_kinematic: float
    lam_continuous: float
    lam_two_bar_0: float
    mu_star_lp: float | None
    mu_star_two_bar: float | None
    mu_star_two_bar_continuous: float | None
    lp_states_below: dict = field(default_factory=dict)
    lp_states_above: dict = field(default_factory=dict)
    mu_star_na: float | None = None
    mu_na: np.ndarray = field(default_factory=lambda: np.empty(0))
    lam_na: np.ndarray = field(default_factory=lambda: np.empty(0))
    seconds_na: float = 0.0


def _finite_or_none(x: float) -> float | None:
    return float(x) if x is not None and math.isfinite(x) else None


def lp_mu_star(assembly, mu_base: float, lam_ns: float, mu_max: float = 10.0, associative: bool = True) -> float | None:
    """Least joint friction at which the limit-analysis multiplier reaches ``lam_ns`` (module docstring):
    of the associative LP (``associative``), or of Coulomb friction without dilatancy
    (:func:`analytic.limit.non_associative.solve_non_associative`, about 1 s a friction; searched from the
    LP's bracket up). None: still short of it at ``mu_max``; 0: reached at any friction."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import solve_lp
    from analytic.limit.non_associative import solve_non_associative

    def reaches(solve) -> Callable[[float], bool]:
        return lambda mu: solve(assembly, mu, mu_base).lam >= (1 - LP_REL_TOL) * lam_ns

    full = reaches(solve_lp)
    if not math.isfinite(lam_ns) or not full(mu_max):
        return None  # without dilatancy the multiplier is at most the LP's: short of lam_ns too
    lp = None if full(1e-6) else search(full, 0.0, mu_max, LP_MU_TOL, rule="width", lo_run=False, hi_run=True)
    if associative:
        return 0.0 if lp is None else lp.hi
    full = reaches(solve_non_associative)
    if lp is None and full(1e-6):
        return 0.0
    # short wherever the LP is (at most its multiplier), so from the LP's bracket; its upper end is a guess,
    # doubled up to mu_max while short: one solve where the two thresholds meet, not twenty
    lo, hi = (lp.lo, lp.hi) if lp is not None else (0.0, mu_max)
    na = search(full, lo, hi, LP_MU_TOL, rule="width", lo_run=False, limit=mu_max,
                up=lambda m: min(2 * m, mu_max) if m < mu_max else math.inf)
    return na.hi if na.bracketed else None


def analytic_curves(arch: PointedArch | DrawnAssembly, config: str, mu_base: float, mus: Sequence[float],
                    n_voussoirs: int = 8, contact: float = 1.0, piers=None, non_associative: bool = True,
                    mus_na: Sequence[float] | None = None) -> AnalyticCurves:
    """LP, two-bar and no-sliding references of ``arch`` on the friction values ``mus``; the LP,
    enumeration and continuous ones at effective ``contact`` (the two-bar model has none: full joints).
    On ``piers`` the continuous one has hinges anywhere along ring and piers, and the two-bar ones
    (a ring on a rigid base) are NaN. A drawing's blocks have the LP curves only (and the four-hinge
    enumeration when they form one chain): the continuous ring and the two-bar need an arch.
    ``non_associative``: also mu* and lambda(mu) without dilatancy, the curve on ``mus_na`` (default
    ``mus``, empty: none; about 1 s a value, so the map gives its grid, not the dense ``mus``)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
    from analytic.limit.limit_piers import continuous_on_piers
    from analytic.limit.non_associative import solve_non_associative
    from analytic.limit.two_bar import lambda_slide, lambda_two_bar, mu_star

    drawn = isinstance(arch, DrawnAssembly)
    asm = arch.with_contact(contact) if drawn else discretise(arch, n_voussoirs=n_voussoirs, config=config,
                                                               contact=contact, piers=piers)
    mu = np.asarray(sorted(set(float(m) for m in mus)), dtype=float)
    lam_lp = np.array([solve_lp(asm, m, mu_base).lam for m in mu])
    lam_ns = float(solve_lp(asm, math.inf, mu_base).lam)
    lam_k = float(enumerate_mechanisms(asm).lam) if not drawn or asm.chain else math.nan
    if drawn:
        lam_c, lam_tb, lam_tb0, ms_tb, ms_tbc = math.nan, np.full(len(mu), math.nan), math.nan, None, None
    elif piers is not None:
        lam_c = float(continuous_on_piers(arch, piers, density=asm.density, contact=contact).lam)
        lam_tb, lam_tb0, ms_tb, ms_tbc = np.full(len(mu), math.nan), math.nan, None, None
    else:
        lam_c = float(continuous_collapse(arch, contact=contact).lam)
        lam_tb, lam_tb0 = np.array([lambda_slide(arch, m) for m in mu]), float(lambda_two_bar(arch))
        ms_tb = _finite_or_none(mu_star(arch, lam_rock=lam_k))
        ms_tbc = _finite_or_none(mu_star(arch, lam_rock=lam_c))
    ms_lp = lp_mu_star(asm, mu_base, lam_ns)
    below = above = {}
    if ms_lp is not None and ms_lp > 0:
        def states(m):
            return {k: v for k, v in solve_lp(asm, m, mu_base).joint_states.items() if v != "closed"}
        below, above = states(max(ms_lp - 5 * LP_MU_TOL, 1e-6)), states(ms_lp + 5 * LP_MU_TOL)
    ms_na, mu_na, lam_na, t_na = None, np.empty(0), np.empty(0), 0.0
    if non_associative:
        t0 = time.perf_counter()
        ms_na = lp_mu_star(asm, mu_base, lam_ns, associative=False)
        mu_na = np.asarray(sorted(set(float(m) for m in (mus if mus_na is None else mus_na))), dtype=float)
        lam_na = np.array([solve_non_associative(asm, m, mu_base).lam for m in mu_na])
        t_na = time.perf_counter() - t0
    return AnalyticCurves(mu, lam_lp, lam_tb, lam_ns, lam_k, lam_c, lam_tb0, ms_lp, ms_tb, ms_tbc, below, above,
                          ms_na, mu_na, lam_na, t_na)


# ----------------------------------------------------------------------------- results
@dataclass(frozen=True)
class MapPoint:
    """One tilt of the map: friction, multiplier, mode, and where it came from."""

    mu: float
    lam: float
    mode: str  # rocking | sliding | mixed | none | failed
    kind: str  # grid | refine
    n_sims: int
    wall_s: float
    key: str
    joints: dict = field(default_factory=dict)  # joint name -> state (non-closed only)
    error: str = ""


@dataclass
class SpecimenMap(Result):
    """The map of one specimen: DEM points, DEM threshold, analytic curves. Its row of the map's summary
    table is declared once in ``SCHEMA``, the rows of its tilts in ``POINTS_SCHEMA``."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("id", "str"), Column("Sh", "float"), Column("Sd", "float"), Column("span_m", "float", "m"),
        Column("config", "str"), Column("mu_base", "float"), Column("mu_star_dem", "float"),
        Column("mu_star_dem_lo", "float"), Column("mu_star_dem_hi", "float"), Column("dem_status", "str"),
        Column("dem_monotonic", "bool"), Column("mu_star_lp", "float"), Column("mu_star_na", "float"),
        Column("mu_star_two_bar", "float"), Column("mu_star_two_bar_continuous", "float"),
        Column("lambda_no_sliding", "float"), Column("lambda_kinematic", "float"), Column("lambda_continuous", "float"),
        Column("lambda_two_bar_frictionless", "float"), Column("seconds_na", "float", "s"), Column("n_tilts", "int"),
        Column("n_failed", "int"),
    ))
    POINTS_SCHEMA: ClassVar[Schema] = Schema((
        Column("id", "str"), Column("mu", "float"), Column("lambda", "float"), Column("mode", "str"), Column("kind", "str"),
        Column("n_sims", "int"), Column("wall_s", "float", "s"), Column("joints", "str"), Column("error", "str"),
    ))

    id: str
    arch: PointedArch
    config: str
    mu_base: float
    points: list[MapPoint]
    threshold: Threshold
    analytic: AnalyticCurves

    @property
    def mu_star_dem(self) -> float | None:
        return self.threshold.mu_star

    @property
    def drawn(self) -> bool:
        """The blocks of a drawing (no arch parameters), not a two-centred arch."""
        return isinstance(self.arch, DrawnAssembly)

    def shape(self) -> dict:
        """``Sh``, ``Sd`` and ``span`` [m] of the arch (None for a drawing)."""
        if self.drawn:
            return {"Sh": None, "Sd": None, "span": None}
        return {"Sh": self.arch.Sh, "Sd": self.arch.Sd, "span": self.arch.span}

    def rows(self) -> list[dict]:
        """Its row of the map's summary table (``SCHEMA``)."""
        a, th = self.analytic, self.threshold
        shape = {k: None if v is None else round(v, 6) for k, v in self.shape().items()}
        return [{
            "id": self.id, "Sh": shape["Sh"], "Sd": shape["Sd"], "span_m": shape["span"],
            "config": self.config, "mu_base": self.mu_base,
            "mu_star_dem": self.mu_star_dem, "mu_star_dem_lo": th.lo, "mu_star_dem_hi": th.hi,
            "dem_status": th.status, "dem_monotonic": th.monotonic,
            "mu_star_lp": a.mu_star_lp, "mu_star_na": a.mu_star_na, "mu_star_two_bar": a.mu_star_two_bar,
            "mu_star_two_bar_continuous": a.mu_star_two_bar_continuous,
            "lambda_no_sliding": a.lam_no_sliding, "lambda_kinematic": a.lam_kinematic,
            "lambda_continuous": a.lam_continuous, "lambda_two_bar_frictionless": a.lam_two_bar_0,
            "seconds_na": round(a.seconds_na, 1),
            "n_tilts": len(self.points), "n_failed": sum(p.mode == "failed" for p in self.points),
        }]

    def point_rows(self) -> list[dict]:
        """The rows of its tilts (``POINTS_SCHEMA``)."""
        return [{"id": self.id, "mu": p.mu, "lambda": _finite_or_none(p.lam), "mode": p.mode, "kind": p.kind,
                 "n_sims": p.n_sims, "wall_s": p.wall_s, "joints": " ".join(f"{k}:{v}" for k, v in p.joints.items()),
                 "error": p.error} for p in self.points]

    def line(self) -> str:
        """Its line of the table ``archdem map`` prints (:meth:`MapResult.lines`)."""
        def f(v):
            return "   -  " if v is None else f"{v:6.3f}"

        th, a = self.threshold, self.analytic
        br = f"[{f(th.lo)},{f(th.hi)}]"
        sh, sd = ("    -", "    -") if self.drawn else (f"{self.arch.Sh:5.2f}", f"{self.arch.Sd:5.2f}")
        return (f"{self.id:<22} {sh} {sd}  {f(self.mu_star_dem)}  {br:<15} {f(a.mu_star_lp)}  {f(a.mu_star_na)}  "
                f"{f(a.mu_star_two_bar)}   {a.lam_no_sliding:6.3f}  {th.status}{'' if th.monotonic else ' (non-monotonic)'}")

    def to_json(self) -> dict:
        """Per-specimen JSON of ``archdem map --json``."""
        a = self.analytic
        th = self.threshold
        return {
            "id": self.id, **self.shape(), "config": self.config,
            "mu_base": self.mu_base,
            "mu_star_dem": self.mu_star_dem, "mu_star_dem_bracket": [th.lo, th.hi], "mu_star_dem_status": th.status,
            "mu_star_dem_monotonic": th.monotonic,
            "mu_star_two_bar": a.mu_star_two_bar, "mu_star_two_bar_continuous": a.mu_star_two_bar_continuous,
            "mu_star_lp": a.mu_star_lp, "mu_star_na": a.mu_star_na,
            "lambda_no_sliding": a.lam_no_sliding, "lambda_kinematic": a.lam_kinematic,
            "lambda_two_bar_frictionless": a.lam_two_bar_0,
            "points": [{"mu": p.mu, "lambda": _finite_or_none(p.lam), "mode": p.mode, "kind": p.kind,
                        "n_sims": p.n_sims, "joints": p.joints} for p in self.points],
        }


@dataclass
class MapResult:
    """A friction map over several specimens (one study file)."""

    study_path: Path
    config: str
    mu_base: float
    mus: list[float]
    specimens: list[SpecimenMap]
    n_cases: int
    n_failed: int
    wall_s: float
    case_wall_s: list[float]
    rounds: int
    definitions: dict = field(default_factory=dict)

    def to_json(self) -> list[dict]:
        return [s.to_json() for s in self.specimens]

    def to_rows(self, kind: str = "summary") -> list[dict]:
        """Flat rows for CSV tables: ``summary`` (one per specimen, :attr:`SpecimenMap.SCHEMA`) or ``points``
        (one per tilt, :attr:`SpecimenMap.POINTS_SCHEMA`)."""
        if kind == "summary":
            return [r for s in self.specimens for r in s.rows()]
        if kind == "points":
            return [r for s in self.specimens for r in s.point_rows()]
        raise ArchdemInputError(f"row kind must be 'summary' or 'points', got {kind!r}")

    def lines(self, path: str | os.PathLike | None = None) -> list[str]:
        """The map as ``archdem map`` prints it: the study (``path``: its file as the user named it, default
        :attr:`study_path`), then a line per specimen."""
        return [f"friction map ({self.config}, mu_base {self.mu_base:g}, {len(self.mus)} friction values, "
                f"{self.rounds} bisection rounds): {self.n_cases} tilts, {self.n_failed} failed, {self.wall_s:.0f} s "
                f"-> {self.study_path if path is None else path}",
                f"{'id':<22} {'Sh':>5} {'Sd':>5}  mu*DEM  bracket         mu*LP   mu*NA  mu*2bar  lambda_ns  status",
                *(s.line() for s in self.specimens)]

    def figures(self, out_dir: str | os.PathLike) -> list[Path]:
        """Write the map figures into ``out_dir`` (see :mod:`dem.experiments.friction_map.figure`); their paths."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.friction_map.figure import save_map_figures

        return save_map_figures(self, out_dir)


def _point(rec, kind: str) -> MapPoint:
    mu = float(rec.params["mu_joint"])
    if not rec.ok:
        last = rec.error.strip().splitlines()[-1] if rec.error.strip() else "failed"
        return MapPoint(mu, math.nan, "failed", kind, 0, rec.wall, rec.key, {}, last)
    r = rec.results
    names, states = r.get("joint_names") or [], r.get("joint_states") or []
    joints = {n: s for n, s in zip(names, states) if s != "closed"}
    lam = r.get("lambda")
    return MapPoint(mu, float(lam) if lam is not None else math.nan, str(r.get("mode", "none")), kind,
                    int(r.get("n_sims", 0)), float(r.get("wall_s", rec.wall)), rec.key, joints)


# ----------------------------------------------------------------------------- the map
def catalogue_map(specimens, config: str = "glued", mus: Sequence[float] | str = "0.3:1.5:0.1",
                  mu_base: float = REFERENCE_MU_BASE, out_path: str | os.PathLike = "runs/map/map.h5", workers: int | None = None,
                  scheduler: str | None = None, resume: bool = False, progress: bool = True, refine: int = 3,
                  protocol: dict | None = None, settings: dict | None = None, func: Callable[[dict], dict] = DEM_CASE,
                  n_voussoirs: int = DEFAULT_VOUSSOIRS, time_scale: float | str = "auto", extra: dict | None = None,
                  contact: float | Mapping[str, float] = 1.0, piers=None,
                  law: Mapping[str, dict] | None = None, definition: dict | None = None,
                  non_associative: bool = True) -> MapResult:
    """Friction map of ``specimens`` (Specimen objects with ``.id`` / ``.arch``, ids, or ``"all"``).

    Round 0 runs the grid ``mus`` for every specimen; rounds 1..``refine`` bisect each
    specimen's bracket once per round (one case per bracketed specimen per round). Every round
    is a :func:`dem.studies.sweep.run_study` on ``out_path``; ``resume=True`` continues an interrupted
    map without recomputing stored cases. ``protocol`` / ``settings``: overrides (catalogue
    scale) of the tilt protocol / simulation settings (default protocol: ``hold`` with
    ``tol = MAP_TILT_TOL``, LP-started, ``MAP_PROTOCOL``). ``func``: the case function (``DEM_CASE`` or ``SYNTHETIC_CASE``);
    ``extra``: additional parameters merged into every case (e.g. ``{"synthetic": {...}}``);
    ``contact``: the effective contact of every joint (DEM cases and the LP / continuous references),
    or specimen id -> contact; ``piers``: every specimen stands on these
    :class:`~specimens.piers.Piers` (the same sizes for all); ``law``: specimen id -> the contact-law
    settings of its joints (``dem.core.contact.study_joints``), merged into ``settings``; ``definition``:
    the command line's options, stored with a new study (``dem.studies.sweep.stored_definition``);
    ``non_associative``: also the references without dilatancy (mu* and lambda on the grid, about 1 s a grid
    value for a catalogue arch: :func:`analytic_curves`).
    Raises :class:`ArchdemInputError`, :class:`dem.studies.sweep.StudyInterrupted`, ``KeyboardInterrupt``.
    """
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import load_study, run_study

    t0 = time.perf_counter()
    specs = _specimen_list(specimens)
    grid = parse_mu_grid(mus) if isinstance(mus, str) else check_mus(mus)

    if not (isinstance(mu_base, (int, float)) and math.isfinite(mu_base) and MIN_FRICTION <= mu_base <= MAX_FRICTION):
        raise ArchdemInputError(f"mu_base must be {MIN_FRICTION:g} to {MAX_FRICTION:g}, got {mu_base!r}")
    if not (isinstance(refine, int) and 0 <= refine <= 20):
        raise ArchdemInputError(f"refine (bisection steps) must be an integer in 0..20, got {refine!r}")
    contact_of = ({str(k): check_contact(v) for k, v in contact.items()} if isinstance(contact, Mapping)
                  else {s.id: check_contact(contact) for s in specs})
    if set(contact_of) != {s.id for s in specs}:
        raise ArchdemInputError("give the effective contact of every specimen of the map")
    if piers is not None:
        for s in specs:
            if isinstance(s.arch, DrawnAssembly):
                raise ArchdemInputError(f"{s.id}: a drawing holds its piers as blocks: draw them instead of --pier-*")
            piers.check(s.arch)
    protocol = dict(protocol if protocol is not None else MAP_PROTOCOL)
    scaled_protocol(protocol, 1.0)  # validate in the main process
    study_attrs = {"study": STUDY_KIND, "config": config, "mu_base": float(mu_base), "protocol": protocol,
                   "settings": dict(settings or {}), "n_voussoirs": int(n_voussoirs),
                   **({"law": {k: dict(v) for k, v in law.items()}} if law else {}),
                   **({} if set(contact_of.values()) == {1.0} else {"contact": contact_of}),
                   **({} if piers is None else {"piers": piers.describe()})}

    def case(s, mu: float) -> dict:
        c = make_case(s.id, s.arch, config, mu, mu_base, protocol, {**(settings or {}), **(law or {}).get(s.id, {})} or None,
                      n_voussoirs, time_scale, contact_of[s.id], piers)
        if extra:
            c.update(extra)
        return c

    kinds: dict[str, dict[str, str]] = {s.id: {} for s in specs}  # specimen -> case key -> kind
    cases_of: dict[str, list[dict]] = {s.id: [] for s in specs}
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import case_key

    round_cases = []
    for s in specs:
        for m in grid:
            c = case(s, m)
            cases_of[s.id].append(c)
            kinds[s.id][case_key(c)] = "grid"
            round_cases.append(c)
    run_study(round_cases, func, out_path, workers=workers, scheduler=scheduler, resume=resume,
              progress=progress, study_attrs=study_attrs, definition=definition)
    rounds = 0
    for _ in range(refine):
        res = load_study(out_path, [c for s in specs for c in cases_of[s.id]])
        by_key = res.by_key
        new = []
        for s in specs:
            pts = [_point(by_key[case_key(c)], "grid") for c in cases_of[s.id] if case_key(c) in by_key]
            mid = bisection_point(threshold_bracket([p.mu for p in pts], [p.mode for p in pts]))
            if mid is None:
                continue
            c = case(s, mid)
            k = case_key(c)
            if k in kinds[s.id]:
                continue
            kinds[s.id][k] = "refine"
            cases_of[s.id].append(c)
            new.append(c)
        if not new:
            break
        run_study(new, func, out_path, workers=workers, scheduler=scheduler, resume=True, progress=progress,
                  study_attrs=study_attrs)
        rounds += 1

    all_cases = [c for s in specs for c in cases_of[s.id]]
    res = load_study(out_path, all_cases)
    by_key = res.by_key
    smaps = []
    for s in specs:
        pts = sorted((_point(by_key[case_key(c)], kinds[s.id][case_key(c)]) for c in cases_of[s.id]
                      if case_key(c) in by_key), key=lambda p: p.mu)
        th = threshold_bracket([p.mu for p in pts], [p.mode for p in pts])
        curve_mus = sorted(set(grid) | set(np.round(np.linspace(min(grid), max(grid), 49), 9).tolist()))
        smaps.append(SpecimenMap(s.id, s.arch, config, float(mu_base), pts, th,
                                 analytic_curves(s.arch, config, mu_base, curve_mus, n_voussoirs, contact_of[s.id],
                                                 piers, non_associative, grid)))
    recs = [by_key[case_key(c)] for c in all_cases if case_key(c) in by_key]
    return MapResult(Path(out_path), config, float(mu_base), grid, smaps, len(recs), sum(not r.ok for r in recs),
                     time.perf_counter() - t0, [r.wall for r in recs if r.ok], rounds, definitions())


@dataclass(frozen=True)
class MapSpec:
    """What a friction map runs: :func:`catalogue_map`'s arguments that make its answer (the specimens, their
    configuration, the friction grid, the base friction, the bisection rounds, the tilt protocol and settings
    overrides, the voussoirs, the time scale, the contact fraction, the piers, the joints' law, the references
    without dilatancy); where it is stored and how it is run are :func:`run`'s."""

    specimens: Any
    config: str = "glued"
    mus: Sequence[float] | str = "0.3:1.5:0.1"
    mu_base: float = REFERENCE_MU_BASE
    refine: int = 3
    protocol: dict | None = None
    settings: dict | None = None
    n_voussoirs: int = DEFAULT_VOUSSOIRS
    time_scale: float | str = "auto"
    contact: float | Mapping[str, float] = 1.0
    piers: Any = None
    law: Mapping[str, dict] | None = None
    non_associative: bool = True


def run(spec: MapSpec, out_path: str | os.PathLike = "runs/map/map.h5", workers: int | None = None,
        scheduler: str | None = None, resume: bool = False, progress: bool = True, definition: dict | None = None,
        func: Callable[[dict], dict] = DEM_CASE, extra: dict | None = None) -> MapResult:
    """The friction map of ``spec`` into the study file ``out_path`` (:func:`catalogue_map`, whose other
    arguments these are)."""
    return catalogue_map(spec.specimens, spec.config, spec.mus, spec.mu_base, out_path, workers=workers,
                         scheduler=scheduler, resume=resume, progress=progress, refine=spec.refine,
                         protocol=spec.protocol, settings=spec.settings, func=func, n_voussoirs=spec.n_voussoirs,
                         time_scale=spec.time_scale, extra=extra, contact=spec.contact, piers=spec.piers, law=spec.law,
                         definition=definition, non_associative=spec.non_associative)


def definitions() -> dict:
    """The threshold definitions and parameters, stored with every map."""
    return {
        "sliding_modes": list(SLIDING_MODES), "rocking_modes": list(ROCKING_MODES),
        "mu_star_dem": "midpoint of [largest mu that slides below the smallest mu that rocks, smallest mu that "
                       "rocks] after bisection (first switch from sliding to rocking as mu rises)",
        "mu_star_lp": f"least mu_joint with lambda_LP >= (1 - {LP_REL_TOL:g}) lambda_LP(mu_joint = inf), "
                      f"bisection to {LP_MU_TOL:g}",
        "mu_star_na": "as mu_star_lp, with the least collapse multiplier of Coulomb friction without dilatancy "
                      "(non-associative, mixed-integer program) in place of the associative LP's",
        "mu_star_two_bar": "two-bar lambda_slide(mu) = discrete kinematic (no-sliding) multiplier",
        "time_scale": f"protocol times, dt and record interval x sqrt(Rc / {RC_REF} m) above the catalogue scale",
        "map_tilt_tol": MAP_TILT_TOL,
    }
