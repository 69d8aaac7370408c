"""The engines' shake study: the least collapsing amplitude of a one-cycle sine and every band above
it, per specimen, frequency, engine, time step and friction case, one case per threshold search in a
resumable study file (:mod:`dem.studies.sweep`); then each feature classified as common to the
engines or not (:func:`features`).

A case is the search of :func:`dem.experiments.shake.thresholds.threshold` over the DEM domain's
amplitudes (from the static onset ``lambda g`` to ``A_MAX_RATIO lambda g``, scan ratio 1.15, the
first collapse bisected to 1 %). Its ``step`` multiplies the engine's own integration step
(:func:`integration_step`): x1 runs the defaults; x0.5 halves what the engine integrates with (the
protocol step ``dt`` of PyBullet; MuJoCo and LMGC90 cut ``dt`` into steps of at most 0.25 ms, so
theirs is halved by a ``dt`` of 0.125 ms). The friction cases
are those of :data:`dem.experiments.compare_engines.run.FRICTIONS`; the study's are "joints" (the
joints' own friction on a base that does not slide: joint sliding is the question) and "none" (no
sliding anywhere: rocking only). docs/validation.md#19-three-engine-shake-study has the figures.
"""
from __future__ import annotations

import csv
import math
from collections import Counter
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np

from dem.core.engines import available_engines, check_engine
from dem.core.provenance import engine_version
from dem.core.engines.lmgc90_engine import LMGC90Options
from dem.core.engines.mujoco_engine import DEFAULT_OPTIONS as MUJOCO_OPTIONS
from dem.core.model import from_assembly
from dem.core.settings import DYNAMICS_DT, DYNAMICS_ENGINE, Settings
from dem.experiments.compare_engines.run import FRICTIONS
from dem.experiments.shake import CHECK_MARGIN, reference_needed, static_onset, threshold
from specimens.blocks import discretise
from specimens.catalogue import CATALOGUE, get_specimen, select_specimens
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path, parse_grid

STUDY_FREQS = (2.0, 4.0, 6.0, 8.0, 10.0)  # [Hz], the shake-table tests' range
#: The specimens the laboratory shook: Sd 0.15 and 0.20.
STUDY_SPECIMENS = tuple(s.id for s in CATALOGUE if round(s.arch.Sd, 3) in (0.15, 0.20))
STUDY_FRICTIONS = ("joints", "none")
STUDY_STEPS = (1.0, 0.5)  # integration steps as multiples of the engine's default: the default and its half
STUDY_ENGINES = ("pybullet", "mujoco", "lmgc90")
A_MAX_RATIO = 6.0  # top of the amplitude scan / (lambda g): the DEM domain's
SCAN_RATIO, TOL = 1.15, 0.01  # scan step and bisection tolerance of the first collapse
#: Two engines' readings of a feature agree when they differ by at most one scan step: band edges
#: are known to the scan's resolution only.
AGREE_RATIO = SCAN_RATIO


def integration_step(engine: str) -> float:
    """The step [s] ``engine`` integrates with at the default protocol step: PyBullet steps by ``dt``,
    MuJoCo and LMGC90 by equal parts of it of at most their ``max_dt``."""
    cap = {"mujoco": MUJOCO_OPTIONS.max_dt, "lmgc90": LMGC90Options().max_dt}.get(engine, math.inf)
    return min(Settings().dt, cap)


def case_dt(engine: str, step: float) -> float:
    """Protocol step ``dt`` [s] that gives ``engine`` ``step`` x its own integration step (the default
    ``dt`` at x1 and above)."""
    return Settings().dt * step if step >= 1 else step * integration_step(engine)


def study_attrs(config: str = "glued") -> dict:
    """What every case of a study shares (checked when a study is resumed)."""
    return {"study": "engines-shake", "config": config, "a_max_ratio": A_MAX_RATIO, "scan_ratio": SCAN_RATIO,
            "tol": TOL, "input": "one-cycle sine"}


def study_cases(ids=STUDY_SPECIMENS, freqs=STUDY_FREQS, engines=STUDY_ENGINES,
                steps=STUDY_STEPS, frictions=STUDY_FRICTIONS, config: str = "glued") -> list[dict]:
    """One case per (specimen, friction, step, frequency, engine), in that nesting order."""
    for f in frictions:
        if f not in FRICTIONS:
            raise ArchdemInputError(f"friction case must be one of {', '.join(FRICTIONS)}, got {f!r}")
    for s in steps:
        if not (0 < s <= 4):
            raise ArchdemInputError(f"a time step factor must be in (0, 4], got {s!r}")
    return [{"id": sid, "config": config, "friction": fr, "mu_joint": FRICTIONS[fr][0], "mu_base": FRICTIONS[fr][1],
             "dt": case_dt(e, float(s)), "step": float(s), "freq": float(f), "engine": e}
            for sid in ids for fr in frictions for s in steps for f in freqs for e in engines]


def shake_case(case: dict) -> dict:
    """Case function: the threshold search of one case (see the module docstring), one process."""
    model = from_assembly(discretise(get_specimen(case["id"]).arch, config=case["config"]), name=case["id"])
    st = Settings(engine=case["engine"], dt=case["dt"], mu_joint=case["mu_joint"], mu_base=case["mu_base"])
    lam = static_onset(model, st)
    r = threshold(model, case["freq"], st, a_min_g=lam, a_max_g=A_MAX_RATIO * lam, scan_ratio=SCAN_RATIO, tol=TOL,
                  workers=1)
    runs = sorted(r.runs, key=lambda o: o.amplitude_g)
    return {"lambda": lam, "a_max_g": A_MAX_RATIO * lam,
            "amplitude_g": math.nan if r.amplitude_g is None else r.amplitude_g,
            "mode": r.mode, "phase": r.phase or "", "n_sims": r.n_sims, "search_wall_s": r.wall_s,
            "run_amplitude_g": np.array([o.amplitude_g for o in runs]),
            "run_collapsed": np.array([o.collapsed for o in runs]),
            "run_mode": [o.mode or "-" for o in runs],
            "engine_version": engine_version(case["engine"])}


def bands(res: dict) -> list[dict]:
    """The case's bands from its runs (sorted by amplitude): ``from_g``/``to_g`` (edges at the
    geometric middle of the runs either side, the first collapse at its bisected amplitude),
    ``collapse``, ``modes`` (of the collapsing runs inside, most frequent first), ``top`` (reaches
    the scan's top)."""
    a, c, m = np.asarray(res["run_amplitude_g"]), np.asarray(res["run_collapsed"], bool), list(res["run_mode"])
    first = res["amplitude_g"]
    out: list[dict] = []
    for k in range(len(a)):
        if out and out[-1]["collapse"] == bool(c[k]):
            out[-1]["to_g"] = float(a[k])
            out[-1]["_modes"].append(m[k])
            continue
        edge = float(a[k]) if k == 0 else (float(first) if (c[k] and not any(b["collapse"] for b in out)
                                                            and math.isfinite(first)) else math.sqrt(a[k - 1] * a[k]))
        if out:
            out[-1]["to_g"] = edge
        out.append({"from_g": edge, "to_g": float(a[k]), "collapse": bool(c[k]), "_modes": [m[k]]})
    for b in out:
        modes = b.pop("_modes")
        b["modes"] = [k for k, _ in Counter(modes).most_common()] if b["collapse"] else []
        b["top"] = False
    if out:
        out[-1]["top"] = True
    return out


def feature_values(res: dict) -> dict:
    """The features of one case: ``first`` (least collapsing amplitude [g], nan if none),
    ``low_bands`` (collapse bands with survival above them: [from, to] each), ``survival_above``
    (survival bands above the first collapse), ``upper_edge`` (lower end of the collapse band that
    reaches the top of the scan, nan if the top survives)."""
    bs = bands(res)
    low = [[b["from_g"], b["to_g"]] for b in bs if b["collapse"] and not b["top"]]
    surv = [[b["from_g"], b["to_g"]] for b in bs if not b["collapse"] and math.isfinite(res["amplitude_g"])
            and b["from_g"] > res["amplitude_g"]]
    upper = bs[-1]["from_g"] if bs and bs[-1]["collapse"] else math.nan
    return {"first": res["amplitude_g"], "low_bands": low, "survival_above": surv, "upper_edge": upper}


#: How each feature is read from :func:`feature_values` (a band by the lower end of its first instance,
#: nan when there is none).
FEATURES = {"first threshold": lambda f: f["first"],
            "low collapse band": lambda f: f["low_bands"][0][0] if f["low_bands"] else math.nan,
            "survival band above": lambda f: f["survival_above"][0][0] if f["survival_above"] else math.nan,
            "upper edge": lambda f: f["upper_edge"]}


#: The features the two-by-two and step comparisons count (the survival band goes with the low band).
COMPARED = ("first threshold", "low collapse band", "upper edge")


def _agree(values: list[float]) -> bool:
    v = [x for x in values if math.isfinite(x)]
    if len(v) != len(values):
        return not v  # all absent agrees; some absent does not
    return max(v) / min(v) <= AGREE_RATIO * (1 + 1e-9)


def features(results: dict) -> dict:
    """Classification of each feature of one (specimen, friction, frequency) across its engines.

    ``results``: ``{(engine, step): case result}``. A feature is ``common`` when every engine at
    every step shows it and their readings agree within :data:`AGREE_RATIO` (or none shows it),
    ``engine-dependent`` when the engines differ at both steps, ``step-dependent`` when they would
    agree taking only the finer step of each engine but not at both. Returns
    ``{feature: {"class": ..., "values": {"engine@step": value}}}``; the band features are compared
    by presence and by the lower end of the first such band."""
    fv = {k: feature_values(r) for k, r in results.items()}
    out = {}
    for name, get in FEATURES.items():
        vals = {f"{e}@{s:g}": get(f) for (e, s), f in fv.items()}
        finest = {}
        for (e, s), f in fv.items():
            if e not in finest or s < finest[e][0]:
                finest[e] = (s, get(f))
        if _agree(list(vals.values())):
            cls = "common"
        elif len(finest) > 1 and _agree([v for _, v in finest.values()]):
            cls = "step-dependent"
        else:
            cls = "engine-dependent"
        out[name] = {"class": cls, "values": vals}
    return out


def _group_key(p: dict) -> tuple:
    return (p["id"], p["friction"], p["freq"])


def _by_group(records, keep=None) -> dict[tuple, dict]:
    """The finished cases (those whose parameters pass ``keep``) by (specimen, friction, frequency),
    in the records' order, then by (engine, step): their results."""
    groups: dict[tuple, dict] = {}
    for r in records:
        if r.ok and (keep is None or keep(r.params)):
            groups.setdefault(_group_key(r.params), {})[(r.params["engine"], r.params["step"])] = r.results
    return groups


def case_rows(records) -> list[dict]:
    """One row per finished case (study records of :func:`shake_case`): its parameters, the first
    collapse, the bands as text (``0.73-0.82 C rocking``), the scanned range, cost."""
    rows = []
    for r in records:
        if not r.ok:
            continue
        p, res = r.params, r.results
        text = "; ".join(f"{b['from_g']:.3g}-{b['to_g']:.3g} {'C' if b['collapse'] else 'S'}"
                         + (f" {'/'.join(b['modes'])}" if b["modes"] else "") for b in bands(res))
        rows.append({"id": p["id"], "friction": p["friction"], "mu_joint": p["mu_joint"], "mu_base": p["mu_base"],
                     "freq": p["freq"], "engine": p["engine"], "step": p["step"], "dt": p["dt"],
                     "lambda": res["lambda"], "a_max_g": res["a_max_g"], "first_g": res["amplitude_g"],
                     "mode": res["mode"], "bands": text, "n_sims": res["n_sims"], "wall_s": r.wall,
                     "engine_version": res["engine_version"]})
    return rows


def classify(records) -> list[dict]:
    """:func:`features` of every (specimen, friction, frequency) that more than one engine has
    finished, in the records' order: ``id``, ``friction``, ``freq``, ``engines``, ``features``."""
    out = []
    for (sid, fr, f), res in _by_group(records).items():
        engines = sorted({e for e, _ in res})
        if len(engines) > 1:
            out.append({"id": sid, "friction": fr, "freq": f, "engines": engines, "features": features(res)})
    return out


def class_counts(classified: list[dict]) -> dict:
    """``{friction: {feature: {class: count}}}`` over the classified groups."""
    out: dict = {}
    for g in classified:
        for name, v in g["features"].items():
            c = out.setdefault(g["friction"], {}).setdefault(name, {})
            c[v["class"]] = c.get(v["class"], 0) + 1
    return out


def pairwise(records, step: float = 1.0) -> dict:
    """How often two engines agree, at time step ``step`` (x the default): ``{"a/b": {feature:
    [agreeing groups, groups both ran]}}`` over the (specimen, friction, frequency) groups, with the
    rule of :func:`features` (the same reading within :data:`AGREE_RATIO`, or both without it)."""
    groups = {k: {e: feature_values(res) for (e, _), res in g.items()}
              for k, g in _by_group(records, lambda p: p["step"] == step).items()}
    getters = {k: FEATURES[k] for k in COMPARED}
    engines = sorted({e for g in groups.values() for e in g})
    out: dict = {}
    for i, a in enumerate(engines):
        for b in engines[i + 1:]:
            both = [g for g in groups.values() if a in g and b in g]
            out[f"{a}/{b}"] = {name: [sum(_agree([get(g[a]), get(g[b])]) for g in both), len(both)]
                               for name, get in getters.items()}
    return out


def step_agreement(records, steps: tuple[float, float] | None = None) -> dict:
    """How often each engine's features hold when its integration step is changed: ``{engine:
    {feature: [groups where every step of the engine agrees, groups it ran at two steps or more]}}``;
    ``steps``: compare these two steps only (e.g. ``(0.5, 0.25)``), default every step run."""
    runs: dict[tuple, dict] = {}
    for key, g in _by_group(records, None if steps is None else lambda p: p["step"] in steps).items():
        for (engine, step), res in g.items():
            runs.setdefault((engine, *key), {})[step] = feature_values(res)
    out: dict = {}
    for (engine, *_), by_step in runs.items():
        if len(by_step) < 2:
            continue
        e = out.setdefault(engine, {k: [0, 0] for k in COMPARED})
        for name in e:
            e[name][0] += _agree([FEATURES[name](f) for f in by_step.values()])
            e[name][1] += 1
    return out


def step_moves(records, engines: tuple[str, ...] | None = None, feature: str = "first threshold") -> list[dict]:
    """The groups where an engine's ``feature`` moves with its step (two of its steps read it more
    than :data:`AGREE_RATIO` apart, or one has it and the other not), in the records' order: ``id``,
    ``friction``, ``freq``, ``moved`` (the engines that move), ``values`` (``{(engine, step): value}``
    of every engine and step run on the group); ``engines``: only these (default all)."""
    out = []
    for (sid, fr, f), g in _by_group(records, None if engines is None else lambda p: p["engine"] in engines).items():
        vals = {k: FEATURES[feature](feature_values(res)) for k, res in g.items()}
        by_engine: dict[str, list[float]] = {}
        for (e, _), v in vals.items():
            by_engine.setdefault(e, []).append(v)
        moved = sorted(e for e, v in by_engine.items() if len(v) > 1 and not _agree(v))
        if moved:
            out.append({"id": sid, "friction": fr, "freq": f, "moved": moved, "values": vals})
    return out


def default_step(engine: str = DYNAMICS_ENGINE) -> float:
    """The study's step factor of the shakes' default (``DYNAMICS_DT`` on ``engine``: x0.5 for MuJoCo)."""
    return DYNAMICS_DT / integration_step(engine)


def _reads_alike(default: float, other: float) -> bool:
    """The rule of the thresholds' check: ``other``'s first threshold within the default's bracket
    widened by ``CHECK_MARGIN`` (its survival end: the threshold / (1 + TOL)); both none agree."""
    if not (math.isfinite(default) and math.isfinite(other)):
        return not (math.isfinite(default) or math.isfinite(other))
    return default / (CHECK_MARGIN * (1 + TOL)) < other <= default * CHECK_MARGIN * (1 + 1e-9)


def group_verdict(firsts: dict, freq: float, mu_joint: float, mu_base: float, engine: str = DYNAMICS_ENGINE,
                  step: float | None = None, reference: str = "lmgc90") -> dict:
    """The settled-or-range verdict of a group's default threshold from a study's readings, by the rule of
    :func:`dem.experiments.shake.check_threshold`: ``firsts`` ``{(engine, step): first threshold [g], nan
    none}``; the default ``(engine, step)`` (``step`` default :func:`default_step`) checked against the same
    engine at half its step and, where :func:`reference_needed`, against ``reference`` at its default step.
    Returns ``status`` (settled, range, unchecked), ``range_g`` ``[low, high]`` (None: no collapse to the top),
    ``why``, ``readings`` ``{"engine@step": value}``."""
    step = default_step(engine) if step is None else step
    if (engine, step) not in firsts:
        return {"status": "unchecked", "range_g": [None, None], "why": f"no {engine} x{step:g} reading", "readings": {}}
    wanted = [("half step", (engine, 0.5 * step))]
    if reference_needed(freq, Settings(mu_joint=mu_joint, mu_base=mu_base)):
        wanted.append((reference, (reference, 1.0)))
    t0 = firsts[(engine, step)]
    used = {(engine, step): t0}
    missing, moved = [], []
    for name, key in wanted:
        if key not in firsts:
            missing.append(f"no {key[0]} x{key[1]:g} reading")
            continue
        used[key] = firsts[key]
        if not _reads_alike(t0, firsts[key]):
            moved.append(name)
    readings = {f"{e}@{s:g}": v for (e, s), v in used.items()}
    vals = list(used.values())
    if moved:
        finite = [v for v in vals if math.isfinite(v)]
        return {"status": "range", "range_g": [min(finite), None if len(finite) < len(vals) else max(finite)],
                "why": f"{', '.join(moved)} reads otherwise" + (f"; {'; '.join(missing)}" if missing else ""),
                "readings": readings}
    if missing:
        return {"status": "unchecked", "range_g": [None, None], "why": "; ".join(missing), "readings": readings}
    return {"status": "settled", "range_g": [t0, t0], "why": "", "readings": readings}


def verdicts(records, engine: str = DYNAMICS_ENGINE, step: float | None = None) -> list[dict]:
    """:func:`group_verdict` of every (specimen, friction, frequency) of a study, in the records' order:
    ``id``, ``friction``, ``freq`` and the verdict's fields."""
    out = []
    for (sid, fr, f), g in _by_group(records).items():
        firsts = {k: res["amplitude_g"] for k, res in g.items()}
        mu_j, mu_b = FRICTIONS[fr]
        out.append({"id": sid, "friction": fr, "freq": f, **group_verdict(firsts, f, mu_j, mu_b, engine, step)})
    return out


def verdict_counts(rows: list[dict]) -> dict:
    """``{friction: {status: count}}`` over :func:`verdicts`."""
    out: dict = {}
    for r in rows:
        c = out.setdefault(r["friction"], {})
        c[r["status"]] = c.get(r["status"], 0) + 1
    return out


# ------------------------------------------------------------------ the study as archdem compare-shake runs it
def _listed(values) -> str:
    return ",".join(v if isinstance(v, str) else f"{v:g}" for v in values)


def _names(text: str, what: str, allowed) -> tuple[str, ...]:
    names = tuple(t.strip() for t in text.split(",") if t.strip())
    if not names or len(set(names)) != len(names):
        raise ArchdemInputError(f"{what}: give distinct names separated by commas, got {text!r}")
    for n in names:
        if n not in allowed:
            raise ArchdemInputError(f"{what}: unknown {n!r}; one of {', '.join(allowed)}")
    return names


def _opt(default: str, help: str, unit: str = "", **meta: Any) -> Any:
    """A field that is an option of ``archdem compare-shake`` (its help, unit; ``shown`` None: the help says
    the default itself)."""
    return field(default=default, metadata={"help": help, "unit": unit, **meta})


@dataclass(frozen=True)
class ShakeStudySpec:
    """The engines' shake study as ``archdem compare-shake`` takes it, in the options' text: the specimens
    (``all`` or ids), engines, sine frequencies [Hz], time steps (x the engine's own) and friction cases,
    comma-separated (the grids also ``start:stop:step``); the blocks cut in ``config``. Checked on
    construction, in that order; ``cases`` are :func:`study_cases` of them."""

    specimens: str = _opt(_listed(STUDY_SPECIMENS), "all or comma-separated ids (default: the Sd 0.15 and 0.20 "
                          f"specimens, {_listed(STUDY_SPECIMENS)})", shown=None)
    engines: str = _opt(_listed(STUDY_ENGINES), "engines")
    freq: str = _opt(_listed(STUDY_FREQS), "sine frequencies", "Hz")
    steps: str = _opt(_listed(STUDY_STEPS), "time steps as multiples of the default one")
    friction: str = _opt(_listed(STUDY_FRICTIONS), "friction cases: " + ", ".join(
        f"{k} {v[0]:g}/{v[1]:g}" for k, v in FRICTIONS.items()) + f" (joint/base; default {_listed(STUDY_FRICTIONS)})",
        shown=None)
    config: str = "glued"

    def __post_init__(self) -> None:
        self.cases  # noqa: B018 (built here: its refusals before any run)
        for e in self.engine_names:
            check_engine(e)

    @cached_property
    def cases(self) -> list[dict]:
        ids = [s.id for s in select_specimens(self.specimens)]
        engines = self.engine_names
        frictions = _names(self.friction, "--friction", tuple(FRICTIONS))
        steps = self.step_factors
        freqs = parse_grid(self.freq, "--freq")
        if any(not (0 < f <= 50) for f in freqs):
            raise ArchdemInputError(f"--freq: one-cycle sines from above 0 to 50 Hz, got {self.freq!r}")
        return study_cases(ids, freqs, engines, steps, frictions, self.config)

    @cached_property
    def engine_names(self) -> tuple[str, ...]:
        return _names(self.engines, "--engines", available_engines())

    @cached_property
    def step_factors(self) -> list[float]:
        return [float(s) for s in parse_grid(self.steps, "--steps")]

    def run(self, path: str, resume: bool = False, workers: int | None = None, scheduler: str | None = None,
            progress: bool = True, definition: dict | None = None) -> ShakeStudy:
        """The study's cases through the sweep engine (local cores or a Dask ``scheduler``) into the study
        file ``path`` (``resume``: continue it), its table written beside it (``.csv``); ``definition``: what
        the study stores of the command that made it."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.studies.sweep import run_study

        res = run_study(self.cases, shake_case, path, workers=workers, scheduler=scheduler, resume=resume,
                        progress=progress, study_attrs=study_attrs(self.config), definition=definition)
        rows = case_rows(res.records)
        csv_path = write_csv(rows, Path(path).with_suffix(".csv"))
        failed = [f"{r.params['id']} {r.params['engine']} {r.params['freq']:g} Hz: "
                  f"{r.error.strip().splitlines()[-1]}" for r in res.failed]
        return ShakeStudy(str(path), str(csv_path), len(res), rows, classify(res.records),
                          {f"{s:g}": pairwise(res.records, s) for s in self.step_factors},
                          step_agreement(res.records), verdicts(res.records), failed)


def write_csv(rows: list[dict], path: Path) -> Path:
    """One row per finished case, written whole (atomically) beside the study file."""
    with atomic_path(path, overwrite=True) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]) if rows else ["id"])
        w.writeheader()
        w.writerows(rows)
    return path


@dataclass(frozen=True)
class ShakeStudy:
    """What a study gives (:meth:`ShakeStudySpec.run`): its file and table, the number of its cases, a row
    per finished case (:func:`case_rows`), the classified features (:func:`classify`), the two-by-two
    agreement by step (:func:`pairwise`), the step agreement (:func:`step_agreement`), the settled-or-range
    verdicts (:func:`verdicts`), and a line per failed case."""

    study: str
    csv: str
    n_cases: int
    rows: list[dict]
    features: list[dict]
    pairwise: dict
    step_agreement: dict
    verdicts: list[dict]
    failed: list[str]

    def describe(self) -> dict:
        """The JSON of ``archdem compare-shake``."""
        return {"study": self.study, "csv": self.csv, "cases": self.rows, "features": self.features,
                "counts": class_counts(self.features), "pairwise": self.pairwise,
                "step_agreement": self.step_agreement, "verdicts": self.verdicts,
                "verdict_counts": verdict_counts(self.verdicts), "failed": self.failed}

    def lines(self) -> list[str]:
        """What ``archdem compare-shake`` prints: the cases, the classes' counts, the agreements, the
        verdicts and the failed cases."""
        out = [f"{len(self.rows)} of {self.n_cases} cases -> {self.study} (table: {self.csv})"]
        for r in self.rows:
            first = "none" if not math.isfinite(r["first_g"]) else f"{r['first_g']:.3f} g"
            out.append(f"{r['id']:<11} {r['friction']:<6} {r['freq']:4g} Hz {r['engine']:<8} x{r['step']:<4g} "
                       f"first {first:<9} {r['bands']}")
        for name, counts in class_counts(self.features).items():
            out.append(f"{name}: " + "; ".join(f"{f} " + ", ".join(f"{c} {k}" for k, c in sorted(v.items()))
                                               for f, v in counts.items()))
        for s, pw in self.pairwise.items():
            out += [f"x{s} {pair} agree: " + ", ".join(f"{k} {a}/{n}" for k, (a, n) in v.items())
                    for pair, v in pw.items()]
        out += [f"{e} at its steps agrees: " + ", ".join(f"{k} {a}/{n}" for k, (a, n) in v.items())
                for e, v in self.step_agreement.items()]
        for v in self.verdicts:
            lo, hi = v["range_g"]
            rng = "" if v["status"] != "range" else f" {lo:.3f}-" + ("none" if hi is None else f"{hi:.3f}") + " g"
            out.append(f"{v['id']:<11} {v['friction']:<6} {v['freq']:4g} Hz default threshold {v['status']}{rng}"
                       + (f" ({v['why']})" if v["why"] else ""))
        return out + [f"failed: {f}" for f in self.failed]
