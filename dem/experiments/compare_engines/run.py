"""Engine cross-check: the tilt test of a specimen run with each engine, at no sliding and at
the reference friction, next to the discrete limit analysis (LP) of the same blocks.

At no sliding the LP is exact for the discretised arch
(docs/validation.md#4-no-sliding-tilt-against-the-lp), so each engine's error is measured against
it. With Coulomb friction the associative LP is no bound
(docs/physics/limit-analysis.md#6-discrete-arch-static-lp-with-friction); its value is reported
for orientation only, and the engines are compared with each other.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

from dem.core.engines import available_engines
from dem.core.provenance import engine_version
from dem.core.model import from_assembly
from dem.core.progress import Progress
from dem.core.settings import Settings
from dem.experiments.tilt import TiltCheck, check_result, reference_lp, tilt
from specimens.blocks import discretise
from specimens.catalogue import get_specimen, select_specimens
from specimens.constants import NO_SLIDING_MU, REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from foundation.errors import ArchdemInputError
from foundation.processes import worker_pool

#: Friction cases (joint, base): no sliding; the reference frictions; the joints' own on a base that does not slide.
FRICTIONS = {"none": (NO_SLIDING_MU, NO_SLIDING_MU), "reference": (REFERENCE_MU_JOINT, REFERENCE_MU_BASE),
             "joints": (REFERENCE_MU_JOINT, NO_SLIDING_MU)}

#: The two engines compared by default.
ENGINES = ("pybullet", "mujoco")
#: ``archdem compare-engines --friction``: the friction cases of each choice.
FRICTION_CHOICES = {"both": ("none", "reference"), "none": ("none",), "reference": ("reference",)}


@dataclass(frozen=True)
class ComparisonRow:
    """A specimen at one friction case: the LP of its blocks and each engine's tilt test
    (:class:`dem.experiments.tilt.check.TiltCheck`), with the engines' versions.

    ``rel_diff`` = (lambda of the second engine - first) / first; ``err_vs_lp`` per engine =
    (lambda - lambda_LP) / lambda_LP (meaningful as an error at no sliding only).
    """

    id: str
    config: str
    friction: str
    mu_joint: float
    mu_base: float
    lp_lam: float
    lp_hinges: tuple
    results: dict = field(default_factory=dict)
    versions: dict = field(default_factory=dict)

    @property
    def engines(self) -> list[str]:
        return list(self.results)

    @property
    def rel_diff(self) -> float:
        e = self.engines
        if len(e) < 2:
            return float("nan")
        a, b = self.results[e[0]].lam, self.results[e[1]].lam
        return (b - a) / a

    def err_vs_lp(self, engine: str) -> float:
        return self.results[engine].rel_err

    def to_dict(self) -> dict:
        d = {k: getattr(self, k) for k in ("id", "config", "friction", "mu_joint", "mu_base", "lp_lam")}
        d["lp_hinges"] = [list(h) for h in self.lp_hinges]
        d["engines"] = {}
        for name, r in self.results.items():
            d["engines"][name] = {"engine": name, "lam": r.lam, "mode": r.mode, "hinges": [list(h) for h in r.hinges],
                                  "slides": list(r.slides), "n_sims": r.n_sims, "wall_s": r.wall_s,
                                  "version": self.versions.get(name, ""), "err_vs_lp": r.rel_err,
                                  "hinges_match_lp": r.hinges_match_lp}
        d["rel_diff"] = self.rel_diff
        return d


def engine_tilt(model, settings: Settings, protocol=None, assembly=None) -> TiltCheck:
    """The hold-protocol tilt test of ``model`` with ``settings.engine`` beside the LP of its blocks
    (``assembly``: default the model's own)."""
    assembly = model.assembly if assembly is None else assembly
    return check_result(tilt(model, settings, protocol, assembly=assembly), assembly)


def compare_specimen(sid: str, config: str = "glued", engines: tuple[str, ...] = ENGINES,
                     frictions: tuple[str, ...] = ("none", "reference"), base: Settings | None = None,
                     protocol=None) -> list[ComparisonRow]:
    """Rows (one per friction case) for catalogue specimen ``sid``; ``base`` settings other than
    friction and engine (e.g. ``dt``) apply to every run."""
    for f in frictions:
        if f not in FRICTIONS:
            raise ArchdemInputError(f"friction case must be one of {', '.join(FRICTIONS)}, got {f!r}")
    if len(engines) < 1:
        raise ArchdemInputError("give at least one engine")
    base = base or Settings()
    asm = discretise(get_specimen(sid).arch, config=config)
    model = from_assembly(asm, name=sid)
    rows = []
    for f in frictions:
        mj, mb = FRICTIONS[f]
        lp = reference_lp(asm, mj, mb)
        res = {e: check_result(tilt(model, base.with_(engine=e, mu_joint=mj, mu_base=mb), protocol, assembly=asm), asm, lp)
               for e in engines}
        rows.append(ComparisonRow(sid, config, f, mj, mb, float(lp.lam), tuple(tuple(h) for h in lp.hinges), res,
                                  {e: engine_version(e) for e in engines}))
    return rows


def _one(args) -> list[ComparisonRow]:
    return compare_specimen(*args)


def compare(ids: list[str], config: str = "glued", engines: tuple[str, ...] = ENGINES,
            frictions: tuple[str, ...] = ("none", "reference"), base: Settings | None = None,
            workers: int = 1, progress: Progress | None = None) -> list[ComparisonRow]:
    """:func:`compare_specimen` for each id (in ``workers`` processes), rows in input order.
    ``progress(done, total, note)``: called as each specimen is done, in input order (:mod:`dem.core.progress`)."""
    jobs = [(sid, config, tuple(engines), tuple(frictions), base) for sid in ids]
    out: list = []

    def done(rows: list) -> None:
        out.append(rows)
        if progress is not None:
            progress(len(out), len(jobs), f"{jobs[len(out) - 1][0]} done")

    if progress is not None:
        progress(0, len(jobs), f"{len(engines) * len(frictions)} tilts each")
    if workers <= 1 or len(jobs) <= 1:
        for j in jobs:
            done(_one(j))
    else:
        with worker_pool(min(workers, len(jobs))) as ex:
            for rows in ex.map(_one, jobs):
                done(rows)
    return [r for rows in out for r in rows]


def summary(rows: list[ComparisonRow]) -> dict:
    """Aggregates: per engine the largest and mean |error vs LP| at no sliding, and the largest
    |relative difference| between engines per friction case."""
    out: dict = {"no_sliding_err_vs_lp": {}, "max_abs_rel_diff": {}}
    ns = [r for r in rows if r.friction == "none"]
    for e in (ns[0].engines if ns else []):
        errs = [abs(r.err_vs_lp(e)) for r in ns]
        out["no_sliding_err_vs_lp"][e] = {"max_abs": max(errs), "mean_abs": sum(errs) / len(errs),
                                          "hinges_match": sum(tuple(r.results[e].hinges) == tuple(r.lp_hinges)
                                                              for r in ns), "n": len(ns)}
    for f in FRICTIONS:
        d = [abs(r.rel_diff) for r in rows if r.friction == f and math.isfinite(r.rel_diff)]
        if d:
            out["max_abs_rel_diff"][f] = max(d)
    return out


# ------------------------------------------------------------------ the comparison as archdem compare-engines runs it
@dataclass(frozen=True)
class CompareSpec:
    """The comparison as ``archdem compare-engines`` takes it: the specimens (``all`` or comma-separated ids),
    two engines (comma-separated), the friction cases (a key of :data:`FRICTION_CHOICES`), the blocks cut in
    ``config``, every run at step ``dt`` [s] (None: the default). Checked on construction."""

    specimens: str = field(default="all", metadata={"help": "all or comma-separated ids"})
    engines: str = field(default=",".join(ENGINES), metadata={"help": "two engines"})
    friction: str = field(default="both", metadata={
        "help": "no sliding, reference friction " + "/".join(f"{m:g}" for m in FRICTIONS["reference"])
                + ", or both (default)", "choices": tuple(FRICTION_CHOICES), "shown": None})
    config: str = "glued"
    dt: float | None = None

    def __post_init__(self) -> None:
        self.ids  # noqa: B018 (built here: the refusals in the command's order)
        self.engine_names  # noqa: B018
        if self.friction not in FRICTION_CHOICES:
            raise ArchdemInputError(f"friction must be one of {', '.join(FRICTION_CHOICES)}, got {self.friction!r}")
        self.base  # noqa: B018

    @cached_property
    def ids(self) -> list[str]:
        return [s.id for s in select_specimens(self.specimens)]

    @cached_property
    def engine_names(self) -> tuple[str, str]:
        engines = tuple(e.strip() for e in self.engines.split(",") if e.strip())
        for e in engines:
            if e not in available_engines():
                raise ArchdemInputError(f"unknown engine {e!r}; available: {', '.join(available_engines())}")
        if len(set(engines)) != 2 or len(engines) != 2:
            raise ArchdemInputError(f"give two different engines to compare, got {self.engines!r}")
        return engines

    @cached_property
    def base(self) -> Settings:
        """The settings every run starts from (its step checked)."""
        return Settings() if self.dt is None else Settings(dt=self.dt)

    def run(self, workers: int = 1, progress: Progress | None = None) -> EngineComparison:
        """:func:`compare` of the spec's specimens (``workers`` processes; ``progress`` as there)."""
        rows = compare(self.ids, self.config, self.engine_names, FRICTION_CHOICES[self.friction], self.base,
                       workers=workers, progress=progress)
        return EngineComparison(rows, self.engine_names, self.config, self.base.dt)


@dataclass(frozen=True)
class EngineComparison:
    """The rows of a comparison (:func:`compare`) of ``engines`` on blocks cut in ``config`` at step ``dt`` [s]."""

    rows: list[ComparisonRow]
    engines: tuple[str, str]
    config: str
    dt: float

    def describe(self) -> dict[str, Any]:
        """The JSON of ``archdem compare-engines``: the rows, their :func:`summary`, the configuration and step."""
        return {"rows": [r.to_dict() for r in self.rows], "summary": summary(self.rows), "config": self.config,
                "dt": self.dt}

    def lines(self) -> list[str]:
        """The table ``archdem compare-engines`` prints: per row the LP, each engine's lambda and error against
        it, their difference and modes; then what err and diff are."""
        e1, e2 = self.engines
        out = [f"{'id':<12} {'friction':<9} {'LP':>7} {e1:>9} {'err':>7} {e2:>9} {'err':>7} {'diff':>7}  modes"]
        for r in self.rows:
            a, b = r.results[e1], r.results[e2]
            out.append(f"{r.id:<12} {r.friction:<9} {r.lp_lam:7.4f} {a.lam:9.4f} {100 * r.err_vs_lp(e1):+6.2f}% "
                       f"{b.lam:9.4f} {100 * r.err_vs_lp(e2):+6.2f}% {100 * r.rel_diff:+6.2f}%  {a.mode}/{b.mode}")
        return out + ["err = (lambda - LP) / LP (an error at no sliding only); diff = (e2 - e1) / e1"]
