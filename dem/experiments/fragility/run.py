"""Fragility from ensembles: stripes of intensity x realisations, each one DEM shake run, stored as
a study (docs/physics/fragility.md).

A **realisation** ``k`` of seed ``S`` is the structure with seeded perturbations of stated size: the
joints' contact bands of :class:`specimens.imperfection.Imperfection` (edge loss mean and scatter)
for an arch, the dimensions (scatter ``size_sd``) for a block, and the friction coefficients scaled
by a lognormal factor of coefficient of variation ``friction_cov``. Realisation ``k`` is the same
structure at every intensity (common random numbers: a stripe differs from the next by the
intensity only). With no perturbation a realisation is the nominal structure and its run is the
deterministic run (``archdem shake``) bit for bit.

Every run is a case of :func:`dem.studies.sweep.run_study` (all local cores or a Dask cluster;
stored as it finishes; ``resume`` runs only what is missing). :func:`fragility` groups the stored
runs into stripes and fits them (:mod:`analytic.codes.fragility`).
"""
from __future__ import annotations

import dataclasses
import hashlib
import math
import os
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Callable, ClassVar

import numpy as np

from analytic.motions.inputs import SampledMotion, SinePulse
from analytic.motions.records import baseline_correct, read_record
from dem.common.arch import arch_from_params, arch_params
from dem.core.model import from_assembly, single_block
from dem.core.settings import dynamics_settings
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.shake import ShakeProtocol, shake
from specimens.blocks import DEFAULT_DENSITY, DEFAULT_VOUSSOIRS, discretise
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.drawn import from_dict as drawn_from_dict
from specimens.imperfection import Imperfection, realise_drawn
from specimens.piers import Piers

STUDY_KIND = "fragility"
#: Most realisations per stripe and most runs per study (a typo, not a study, beyond them).
MAX_REALISATIONS, MAX_RUNS = 10_000, 200_000
#: Default scatter of an arch's joint edge loss and of a block's dimensions [m]: a sub-millimetre
#: cutting tolerance (0.5 % of a catalogue joint), small enough to leave the nominal threshold.
DEFAULT_EDGE_LOSS_SD = DEFAULT_SIZE_SD = 0.25e-3
#: Default coefficient of variation of the friction coefficients (repeat tests of one interface).
DEFAULT_FRICTION_COV = 0.1


@dataclass(frozen=True)
class Perturbation:
    """Perturbations of one realisation: joint ``edge_loss`` mean and ``edge_loss_sd`` [m] (arches),
    dimension scatter ``size_sd`` [m] (a block's base and height), friction ``friction_cov`` [-]."""

    edge_loss: float = 0.0
    edge_loss_sd: float = 0.0
    size_sd: float = 0.0
    friction_cov: float = 0.0

    def __post_init__(self) -> None:
        for name in ("edge_loss", "edge_loss_sd", "size_sd"):
            v = getattr(self, name)
            if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and 0 <= v <= 0.1):
                raise ArchdemInputError(f"{name.replace('_', ' ')} must be a length from 0 to 0.1 m, got {v!r}")
        v = self.friction_cov
        if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and 0 <= v <= 1):
            raise ArchdemInputError(f"friction coefficient of variation must be from 0 to 1, got {v!r}")

    def describe(self) -> dict:
        """The perturbation as a case and the study file hold it: every field, as a float."""
        return {k: float(v) for k, v in asdict(self).items()}


# ------------------------------------------------------------------------------------------ structures
def arch_structure(arch, config: str = "glued", n_voussoirs: int | None = None, contact: float = 1.0,
                   piers=None, density: float | None = None) -> dict:
    """The structure entry of a case: an arch cut as ``archdem shake`` cuts it."""
    return {"kind": "arch", "arch": arch_params(arch), "config": config,
            "n_voussoirs": int(n_voussoirs or DEFAULT_VOUSSOIRS), "contact": float(contact),
            "density": float(density or DEFAULT_DENSITY), **({} if piers is None else {"piers": piers.describe()})}


def drawing_structure(assembly) -> dict:
    """The structure entry of a case: a drawn assembly (:mod:`specimens.drawn`), carried whole."""
    return {"kind": "drawing", "assembly": assembly.to_dict()}


def block_structure(b: float, h: float, width: float = 0.1, density: float = 500.0) -> dict:
    """The structure entry of a case: a rectangular block ``b`` x ``h`` [m] on a flat base."""
    return {"kind": "block", "b": float(b), "h": float(h), "width": float(width), "density": float(density)}


def _model(structure: dict, pert: dict, seed: int, k: int):
    if structure["kind"] == "block":
        rng = np.random.default_rng([int(seed), int(k), 2])
        db, dh = rng.normal(0.0, pert["size_sd"], 2) if pert["size_sd"] > 0 else (0.0, 0.0)
        return single_block(structure["b"] + db, structure["h"] + dh, structure["width"], structure["density"])
    if structure["kind"] == "drawing":
        imp = Imperfection(pert["edge_loss"], pert["edge_loss_sd"])
        return from_assembly(realise_drawn(drawn_from_dict(structure["assembly"]), imp, seed, k))

    arch = arch_from_params(structure["arch"])
    kw = dict(n_voussoirs=structure["n_voussoirs"], config=structure["config"], density=structure["density"],
              piers=Piers(**structure["piers"]) if structure.get("piers") else None)
    imp = Imperfection(pert["edge_loss"], pert["edge_loss_sd"])
    contact = structure["contact"] if pert["edge_loss"] == 0 else imp.contact(arch)
    nominal = discretise(arch, contact=contact, **kw)
    if pert["edge_loss_sd"] == 0:
        return from_assembly(nominal)
    return from_assembly(discretise(arch, contact=contact, bands=imp.bands(nominal, seed, k), **kw))


def _friction(settings: dict, pert: dict, seed: int, k: int) -> dict:
    base = dynamics_settings(**settings)
    cov = pert["friction_cov"]
    if cov == 0:
        return {}
    s = math.sqrt(math.log(1.0 + cov * cov))
    f = np.exp(np.random.default_rng([int(seed), int(k), 1]).normal(-0.5 * s * s, s, 2))
    return {"mu_joint": float(base.mu_joint * f[0]), "mu_base": float(base.mu_base * f[1])}


# ------------------------------------------------------------------------------------------ motions
def sine_spec(freq: float, amplitude_g: float) -> dict:
    return {"kind": "sine", "freq": float(freq), "amplitude_g": float(amplitude_g)}


def record_spec(path: str, scale: float, window: tuple[int, int]) -> dict:
    """A record (read, baseline-corrected, samples ``window``) times ``scale``; the file's hash keeps a
    resumed study from mixing two files of one name."""
    p = os.path.abspath(path)
    with open(p, "rb") as fh:
        digest = hashlib.sha256(fh.read()).hexdigest()[:16]
    return {"kind": "record", "path": p, "sha256": digest, "window": [int(window[0]), int(window[1])],
            "scale": float(scale)}


def prepared_record(path: str):
    """A record as the fragility runs it: baseline-corrected and cut to its significant duration;
    returns the motion and its sample window."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.motions.matching import arias_window, significant_window

    m = baseline_correct(read_record(path))
    return significant_window(m), arias_window(m)


def _motion(spec: dict):
    if spec["kind"] == "sine":
        return SinePulse(spec["amplitude_g"] * G, spec["freq"])
    m = baseline_correct(read_record(spec["path"]))
    i0, i1 = spec["window"]
    return SampledMotion(m.values[i0:i1], m.dt, spec["scale"], name=m.name, source=m.source)


# ------------------------------------------------------------------------------------------ case
def shake_case(case: dict) -> dict:
    """Case function (DEM): one shake run of one realisation at one intensity. Returns ``collapsed``,
    ``mode``, ``peak_displacement`` [m] (largest point displacement), ``t_collapse`` [s], the frictions
    of the realisation and ``wall_s``."""
    seed, k = int(case["seed"]), int(case["realisation"])
    model = _model(case["structure"], case["perturbation"], seed, k)
    settings = dynamics_settings(**{**case["settings"], **_friction(case["settings"], case["perturbation"], seed, k)})
    t0 = time.perf_counter()
    r = shake(model, _motion(case["motion"]), settings, ShakeProtocol(), friction_work=False)
    return {"collapsed": bool(r.collapsed), "mode": str(r.mode),
            "peak_displacement": float(np.max(r.sim.history.dmax)) if len(r.sim.history.dmax) else 0.0,
            "t_collapse": float(r.t_collapse) if r.collapsed else None, "mu_joint": settings.mu_joint,
            "mu_base": settings.mu_base, "wall_s": time.perf_counter() - t0}


#: The case function of the fragility studies.
FRAGILITY_CASE = shake_case


# ------------------------------------------------------------------------------------------ study
@dataclass(frozen=True)
class Curve:
    """One fragility curve: ``group`` (a frequency or a record suite), its ``stripes``, the ``fit``
    (None with ``fit_note`` when the stripes do not bracket collapse), ``deterministic`` threshold."""

    group: str
    unit: str
    stripes: list
    fit: object | None
    fit_note: str = ""
    deterministic: float | None = None

    def describe(self) -> dict:
        return {"group": self.group, "unit": self.unit, "points": [s.describe() for s in self.stripes],
                "fit": None if self.fit is None else self.fit.describe(), "fit_note": self.fit_note,
                "deterministic_threshold": self.deterministic}


#: The fits' table: one row per curve (empty cells where no fit).
FITS_SCHEMA = Schema((
    Column("group", "str"), Column("unit", "str"), Column("median", "float"), Column("median_ci_low", "float"),
    Column("median_ci_high", "float"), Column("beta", "float"), Column("beta_ci_low", "float"),
    Column("beta_ci_high", "float"), Column("n_runs", "int"), Column("deterministic_threshold", "float"),
    Column("note", "str"),
))


def stripes_csv(study_path: str | os.PathLike) -> Path:
    """The stripes' table beside the study file ``study_path``: ``STEM-stripes.csv``."""
    study = Path(study_path)
    return study.with_name(study.stem + "-stripes.csv")


@dataclass(frozen=True)
class FragilityResult(Result):
    """A fragility study's curves (:class:`Curve`), its runs and failures, its file and its wall time [s].
    Its table (``SCHEMA``): one row per stripe; :meth:`fit_rows` (:data:`FITS_SCHEMA`) one per curve."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("group", "str"), Column("unit", "str"), Column("intensity", "float"), Column("n_runs", "int"),
        Column("n_collapsed", "int"), Column("p", "float"), Column("ci_low", "float"), Column("ci_high", "float"),
        Column("modes", "str"),
    ))

    label: str
    curves: list
    n_runs: int
    failed: tuple[str, ...]
    result_file: str
    wall_s: float
    extra: dict = field(default_factory=dict)
    #: what the study was asked, as its JSON answer gives it after the summary (:meth:`describe`)
    inputs: dict = field(default_factory=dict)

    def summary(self) -> dict:
        out = {"id": self.label, "curves": [c.describe() for c in self.curves], "n_runs": self.n_runs,
               "failed": list(self.failed), "wall_s": self.wall_s, "result_file": self.result_file, **self.extra}
        if len(self.curves) == 1:
            c = out["curves"][0]
            out.update(points=c["points"], fit=c["fit"], deterministic_threshold=c["deterministic_threshold"])
        return out

    def describe(self) -> dict:
        """The JSON answer of ``archdem fragility``: :meth:`summary`, what the study was asked (its motions,
        perturbation and settings) and the path of its stripes' table (:func:`stripes_csv`)."""
        return {**self.summary(), **self.inputs, "csv": str(stripes_csv(self.result_file))}

    def rows(self) -> list[dict]:
        """One row per stripe: its curve, intensity, runs, collapses, probability with its interval, and
        the failure modes as ``mode:count`` words."""
        return [{"group": c.group, "unit": c.unit, **{k: v for k, v in s.describe().items() if k != "modes"},
                 "modes": " ".join(f"{m}:{n}" for m, n in sorted(s.modes.items()))} for c in self.curves for s in c.stripes]

    def fit_rows(self) -> list[dict]:
        """One row per curve: the fitted median and beta with their intervals (None without a fit), the
        runs, the deterministic threshold and the fit's note."""
        none = dict.fromkeys(("median", "median_ci_low", "median_ci_high", "beta", "beta_ci_low", "beta_ci_high"))
        return [{"group": c.group, "unit": c.unit,
                 **({"median": c.fit.median, "median_ci_low": c.fit.median_ci[0], "median_ci_high": c.fit.median_ci[1],
                     "beta": c.fit.beta, "beta_ci_low": c.fit.beta_ci[0], "beta_ci_high": c.fit.beta_ci[1]}
                    if c.fit else none),
                 "n_runs": sum(s.n for s in c.stripes), "deterministic_threshold": c.deterministic, "note": c.fit_note}
                for c in self.curves]

    def lines(self, realisations: int) -> list[str]:
        """The study as ``archdem fragility`` prints it; ``realisations``: per stripe."""
        out = [f"{self.label}: {self.n_runs} runs ({realisations} realisations per stripe), {self.wall_s:.0f} s -> "
               f"{self.result_file}"]
        for c in self.curves:
            pts = "  ".join(f"{s.intensity:g}:{s.k}/{s.n}" for s in c.stripes)
            fit = (f"median {c.fit.median:.4g} {c.unit} [{c.fit.median_ci[0]:.4g}, {c.fit.median_ci[1]:.4g}], beta "
                   f"{c.fit.beta:.3g} [{c.fit.beta_ci[0]:.3g}, {c.fit.beta_ci[1]:.3g}]" if c.fit
                   else f"no fit ({c.fit_note})")
            det = "" if c.deterministic is None else f"; deterministic threshold {c.deterministic:.4g} {c.unit}"
            out.append(f"  {c.group}: {fit}{det}\n    collapsed/runs per stripe: {pts}")
        if self.failed:
            out.append(f"  {len(self.failed)} runs failed; first: {self.failed[0]}")
        return out


def make_cases(label: str, structure: dict, settings: dict, perturbation: Perturbation, groups: list,
               n: int, seed: int) -> list[dict]:
    """The study's cases: per group ``(name, unit, [(intensity, motion spec), ...])`` every intensity x
    realisations ``0..n-1``."""
    if isinstance(n, bool) or not (isinstance(n, int) and 1 <= n <= MAX_REALISATIONS):
        raise ArchdemInputError(f"realisations must be a whole number from 1 to {MAX_REALISATIONS}, got {n!r}")
    if isinstance(seed, bool) or not (isinstance(seed, int) and 0 <= seed < 2**63):
        raise ArchdemInputError(f"the seed must be a whole number >= 0, got {seed!r}")
    cases = [{"label": label, "structure": structure, "settings": settings, "perturbation": perturbation.describe(),
              "seed": int(seed), "realisation": k, "group": name, "intensity": float(x), "motion": spec}
             for name, _, items in groups for x, spec in items for k in range(n)]
    if len(cases) > MAX_RUNS:
        raise ArchdemInputError(f"{len(cases)} runs: a study holds at most {MAX_RUNS}")
    return cases


def fragility(label: str, structure: dict, settings: dict, perturbation: Perturbation, groups: list, n: int,
              seed: int, out_path: str | os.PathLike, workers: int | None = None, scheduler: str | None = None,
              resume: bool = False, progress: bool = True,
              deterministic: dict[str, float | Callable[[], float]] | None = None,
              definition: dict | None = None) -> FragilityResult:
    """Run (or resume) the study of ``groups`` x ``n`` realisations and fit each group's curve;
    ``deterministic``: group -> threshold of the nominal structure, reported beside the fit, or the
    function that computes it: called once the study file exists, each threshold kept in it as it
    ends (a resume reads it back); ``definition``: the command line's options, stored with a new study."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.codes.fragility import fit_lognormal, stripes
    from dem.studies.sweep import case_key, open_study, run_study, store_note, stored_note, study_lock

    t0 = time.perf_counter()
    cases = make_cases(label, structure, settings, perturbation, groups, n, seed)
    attrs = {"study": STUDY_KIND, "label": label, "structure": structure, "settings": settings,
             "perturbation": perturbation.describe(), "n": n, "groups": [[g, u] for g, u, _ in groups]}
    with study_lock(out_path):
        # the file and its definition first: a stop during the thresholds leaves a study to resume
        open_study(out_path, FRAGILITY_CASE, attrs, int(seed), resume, definition)
        det = dict(stored_note(out_path, "deterministic") or {})
        for name, value in (deterministic or {}).items():
            if name not in det:
                det[name] = value() if callable(value) else value
                store_note(out_path, "deterministic", det)
        deterministic = det
        res = run_study(cases, FRAGILITY_CASE, out_path, workers=workers, scheduler=scheduler, resume=True,
                        progress=progress, study_attrs=attrs, seed=int(seed))
    by_key = res.by_key
    curves, failed = [], []
    for name, unit, _ in groups:
        xs, cs, ms = [], [], []
        for c in (c for c in cases if c["group"] == name):
            rec = by_key.get(case_key(c))
            if rec is not None and rec.ok:
                xs.append(c["intensity"])
                cs.append(bool(rec.results["collapsed"]))
                ms.append(str(rec.results["mode"]))
            else:
                failed.append(f"{name} {c['intensity']:g} #{c['realisation']}: {rec.error if rec else 'not run'}")
        if not xs:
            curves.append(Curve(name, unit, [], None, "no run finished"))
            continue
        pts = stripes(xs, cs, ms)
        try:
            fit, note = fit_lognormal(pts, seed=seed), ""
        except ArchdemInputError as exc:
            fit, note = None, str(exc)
        curves.append(Curve(name, unit, pts, fit, note, (deterministic or {}).get(name)))
    return FragilityResult(label, curves, len(cases), tuple(failed), str(out_path), time.perf_counter() - t0)


@dataclass(frozen=True)
class FragilitySpec:
    """A fragility study (:func:`run`): ``label`` names the structure, ``structure`` its case entry
    (:func:`arch_structure`, :func:`block_structure`, :func:`drawing_structure`), ``settings`` the engine's
    (a dict written into the study), ``perturbation`` each realisation's, ``groups`` ``(name, unit,
    [(intensity, motion spec), ...])`` each, ``n`` realisations per stripe of seed ``seed``; the study file
    ``out_path``, run in ``workers`` or on ``scheduler`` (continued with ``resume``); ``deterministic`` and
    ``definition`` as :func:`fragility` takes them; ``motions`` what the groups are (``input`` ``sine`` with
    its ``freqs``, or ``records`` with the ``im`` and the files), given back in the result's JSON."""

    label: str
    structure: dict
    settings: dict
    perturbation: Perturbation
    groups: list
    n: int
    seed: int
    out_path: Any
    workers: int | None = None
    scheduler: str | None = None
    resume: bool = False
    progress: bool = True
    deterministic: dict | None = None
    definition: dict | None = None
    motions: dict = field(default_factory=dict)

    def cases(self) -> list[dict]:
        """The study's cases (:func:`make_cases`): checks the realisations, the seed and the study's size."""
        return make_cases(self.label, self.structure, self.settings, self.perturbation, self.groups, self.n, self.seed)


def run(spec: FragilitySpec) -> FragilityResult:
    """Run (or resume) the study ``spec`` and fit its curves (:func:`fragility`); the result holds what it was asked."""
    res = fragility(spec.label, spec.structure, spec.settings, spec.perturbation, spec.groups, spec.n, spec.seed,
                    spec.out_path, workers=spec.workers, scheduler=spec.scheduler, resume=spec.resume,
                    progress=spec.progress, deterministic=spec.deterministic, definition=spec.definition)
    return dataclasses.replace(res, inputs={**spec.motions, "perturbation": spec.perturbation.describe(),
                                            "settings": spec.settings})


__all__ = ["Perturbation", "arch_structure", "block_structure", "sine_spec", "record_spec", "prepared_record",
           "shake_case", "make_cases", "fragility", "FragilityResult", "Curve", "FRAGILITY_CASE", "FITS_SCHEMA",
           "FragilitySpec", "run", "stripes_csv"]
