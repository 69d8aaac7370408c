"""Tilt ensembles: the same specimen cut N times with seeded imperfect joints, like N repetitions
in the laboratory (docs/physics/dem.md#16-tilt-ensembles).

Realisation ``k`` of seed ``S`` draws its joints' contact bands from
:class:`specimens.imperfection.Imperfection` (the same on every machine); each realisation is one
tilt test (the campaign's protocol: LP start, bisection to 0.5 %), run as a case of a study
(:func:`dem.studies.sweep.run_study`: all local cores or a Dask cluster, stored as it finishes,
resumable).
"""
from __future__ import annotations

import dataclasses
import math
import os
import time
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from dem.experiments.tilt.case import DEM_CASE, make_case
from dem.studies.sweep import case_key, run_studies
from specimens.blocks import discretise
from foundation.errors import ArchdemInputError

#: The tilt protocol of every realisation (the campaign's tilt test: LP start, 0.5 %).
ENSEMBLE_PROTOCOL = {"kind": "hold", "tol": 0.005, "start": "lp"}
STUDY_KIND = "tilt-ensemble"


@dataclass(frozen=True)
class EnsembleResult:
    """The multipliers and modes of an ensemble; ``seeds``: (seed, realisation) of each run."""

    label: str
    contact: float
    edge_loss_sd: float  # [m]
    lambdas: np.ndarray
    modes: tuple[str, ...]
    seeds: tuple[tuple[int, int], ...]
    failed: tuple[str, ...] = ()
    result_file: str = ""
    wall_s: float = math.nan
    extra: dict = field(default_factory=dict)
    config: str = ""  # the blocks' configuration (glued or free)
    seed: int | None = None  # the seed of the realisations
    mu_joint: float | None = None  # the friction coefficients and the engine every realisation ran with
    mu_base: float | None = None
    engine: str | None = None

    @property
    def lambda_mean(self) -> float:
        return float(np.mean(self.lambdas)) if len(self.lambdas) else math.nan

    @property
    def lambda_sd(self) -> float:
        return float(np.std(self.lambdas, ddof=1)) if len(self.lambdas) > 1 else math.nan

    def summary(self) -> dict:
        return {"id": self.label, "contact": self.contact, "edge_loss_sd_mm": self.edge_loss_sd * 1e3,
                "n": len(self.seeds), "lambda_mean": self.lambda_mean, "lambda_sd": self.lambda_sd,
                "lambda_cov": self.lambda_sd / self.lambda_mean if len(self.lambdas) > 1 else math.nan,
                "lambdas": [float(x) for x in self.lambdas], "modes": dict(Counter(self.modes)),
                "seeds": [list(s) for s in self.seeds], "failed": list(self.failed),
                "wall_s": self.wall_s, "result_file": self.result_file, **self.extra}

    def describe(self) -> dict:
        """The ensemble as ``archdem tilt --ensemble --json`` prints it: :meth:`summary` and what it ran with."""
        return self.summary() | {"config": self.config, "mu_joint": self.mu_joint, "mu_base": self.mu_base,
                                 "engine": self.engine, "seed": self.seed}

    def lines(self) -> list[str]:
        """The ensemble as ``archdem tilt --ensemble`` prints it: the mean and spread of lambda, the modes, then
        each failed realisation."""
        modes = ", ".join(f"{m} {k}" for m, k in Counter(self.modes).items())
        return [f"{self.label} ({self.config}, contact {self.contact:.3f}, edge-loss scatter {self.edge_loss_sd * 1e3:g} mm, "
                f"seed {self.seed}): lambda {self.lambda_mean:.4f} +- {self.lambda_sd:.4f} over {len(self.lambdas)} "
                f"realisations ({modes}); {self.wall_s:.0f} s -> {self.result_file}",
                *(f"  failed: {f}" for f in self.failed)]


def tilt_ensemble(label: str, arch, imperfection, n: int, seed: int, out_path: str | os.PathLike,
                  config: str = "glued", mu_joint: float = 0.577, mu_base: float = 1.0, engine: str = "pybullet",
                  workers: int | None = None, scheduler: str | None = None, resume: bool = False,
                  progress: bool = True, n_voussoirs: int = 8, law: dict | None = None) -> EnsembleResult:
    """``n`` tilt tests of ``arch`` (``n_voussoirs`` per side) with the joints of realisations
    ``0..n-1`` of ``seed`` (``law``: their contact-law settings, ``dem.core.contact.study_joints``; rigid
    by default); the study is stored in ``out_path``."""
    study = ensemble_study(label, arch, imperfection, n, seed, out_path, config, mu_joint, mu_base, engine,
                           n_voussoirs, law)
    (res,) = tilt_ensembles([study], workers, scheduler, resume, progress)
    return dataclasses.replace(res, mu_joint=mu_joint, mu_base=mu_base, engine=engine)


@dataclass(frozen=True)
class EnsembleStudy:
    """The cases of an ensemble, to be run (:func:`tilt_ensembles`) into ``out_path``."""

    label: str
    contact: float
    edge_loss_sd: float  # [m]
    seed: int
    cases: tuple
    attrs: dict
    out_path: str


def ensemble_study(label: str, arch, imperfection, n: int, seed: int, out_path: str | os.PathLike,
                   config: str = "glued", mu_joint: float = 0.577, mu_base: float = 1.0, engine: str = "pybullet",
                   n_voussoirs: int = 8, law: dict | None = None) -> EnsembleStudy:
    """The study of :func:`tilt_ensemble` (its arguments), not run."""
    if not (isinstance(n, int) and 1 <= n <= 10_000):
        raise ArchdemInputError(f"an ensemble has 1 to 10000 realisations, got {n!r}")
    if not (isinstance(seed, int) and 0 <= seed < 2**63):
        raise ArchdemInputError(f"the seed must be an integer >= 0, got {seed!r}")
    nominal = discretise(arch, n_voussoirs=n_voussoirs, config=config, contact=imperfection.contact(arch))
    settings = ({} if engine == "pybullet" else {"engine": engine}) | (law or {}) or None
    base = make_case(label, arch, config, mu_joint, mu_base, ENSEMBLE_PROTOCOL, settings, n_voussoirs,
                     contact=nominal.contact)
    cases = []
    for k in range(n):
        bands = imperfection.bands(nominal, seed, k) if imperfection.edge_loss_sd > 0 else None
        cases.append({**base, "seed": int(seed), "realisation": k,
                      **({"bands": {j: list(b) for j, b in bands.items()}} if bands else {})})
    attrs = {"study": STUDY_KIND, "label": label, "config": config, "contact": nominal.contact,
             "edge_loss_mm": imperfection.edge_loss * 1e3, "edge_loss_sd_mm": imperfection.edge_loss_sd * 1e3,
             "seed": int(seed), "n": n}
    return EnsembleStudy(label, nominal.contact, imperfection.edge_loss_sd, int(seed), tuple(cases), attrs,
                         str(out_path))


def tilt_ensembles(studies: list[EnsembleStudy], workers: int | None = None, scheduler: str | None = None,
                   resume: bool = False, progress: bool = True) -> list[EnsembleResult]:
    """Run ensembles (:func:`ensemble_study`) on one pool of workers, each into its own study file
    (:func:`dem.studies.sweep.run_studies`); their results in order (``wall_s``: of them all)."""
    t0 = time.perf_counter()
    done = run_studies([(st.cases, st.out_path, st.attrs, st.seed) for st in studies], DEM_CASE, workers=workers,
                       scheduler=scheduler, resume=resume, progress=progress)
    wall = time.perf_counter() - t0
    out = []
    for st, res in zip(studies, done):
        by_key = res.by_key
        lams, modes, seeds, failed = [], [], [], []
        for c in st.cases:
            rec = by_key.get(case_key(c))
            if rec is not None and rec.ok:
                lams.append(float(rec.results["lambda"]))
                modes.append(str(rec.results["mode"]))
                seeds.append((st.seed, c["realisation"]))
            else:
                failed.append(f"realisation {c['realisation']}: {rec.error if rec is not None else 'not run'}")
        out.append(EnsembleResult(st.label, st.contact, st.edge_loss_sd, np.array(lams), tuple(modes), tuple(seeds),
                                  tuple(failed), st.out_path, wall, config=st.attrs["config"], seed=st.seed))
    return out


__all__ = ["tilt_ensemble", "tilt_ensembles", "ensemble_study", "EnsembleStudy", "EnsembleResult", "ENSEMBLE_PROTOCOL"]
