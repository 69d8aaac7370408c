"""The DEM failure domain of an arch over sine frequencies (:func:`dem_failure_domain`), and the
four-bar and two-bar analytic domains of the same arch to set beside it (:func:`analytic_domains`);
one frequency's DEM threshold beside the linkages' (:class:`DomainThreshold`, a row of the shake step)."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar, Sequence

from analytic.rocking.domain import failure_domain as linkage_domain
from dem.core.model import as_model
from dem.core.progress import Progress
from dem.core.settings import Settings, dynamics_settings
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.shake import thresholds
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from foundation.errors import ArchdemInputError


def dem_failure_domain(label: str, arch, freqs: Sequence[float], config: str = "glued", mu_joint: float | None = None,
                       mu_base: float | None = None, a_max_ratio: float = 6.0, scan_ratio: float = 1.15,
                       tol: float = 0.01, workers: int | None = None, disc_kw: dict | None = None,
                       settings=None, protocol=None, scheduler: str | None = None, joints: dict | None = None,
                       engine: str | None = None, dt: float | None = None, progress: Progress | None = None,
                       check: bool | str = False) -> dict:
    """DEM failure domain of ``arch`` (one-cycle plain sines at ``freqs`` [Hz]).

    The amplitude scan runs from the static onset ``lambda g`` (LP with the same friction;
    nothing moves below it) to ``a_max_ratio lambda g``. Returns the dict of
    :func:`dem.experiments.shake.thresholds.failure_domain` plus ``id``, ``lambda``, ``config``, ``mu_joint``, ``mu_base``.
    ``joints``: contact-law fields of :class:`dem.core.settings.Settings` (rigid if None); ``engine``
    and ``dt`` [s]: the physics engine and its time step (defaults: the settings'); all three unless
    ``settings`` is given. ``progress(done, total, note)``: called as each frequency's threshold is found
    (:mod:`dem.core.progress`). ``check``: each threshold settled or a range (:func:`thresholds.check_threshold`;
    ``"half-step"``: the half-step check only, as :class:`thresholds.ThresholdSpec` takes it).
    """
    mu_j = REFERENCE_MU_JOINT if mu_joint is None else float(mu_joint)
    mu_b = REFERENCE_MU_BASE if mu_base is None else float(mu_base)
    model = as_model(arch, config=config, name=label, **(disc_kw or {}))
    lam = thresholds.static_onset(model, Settings(mu_joint=mu_j, mu_base=mu_b))
    if not (math.isfinite(lam) and lam > 0):
        raise ArchdemInputError(f"{label}: the arch has no positive static collapse multiplier (lambda = {lam})")
    run = {k: v for k, v in (("engine", engine), ("dt", dt)) if v is not None}
    st = settings or dynamics_settings(mu_joint=mu_j, mu_base=mu_b, **(joints or {}), **run)
    out = thresholds.failure_domain(model, freqs, st, protocol, workers=workers, a_min_g=lam, a_max_g=a_max_ratio * lam,
                         scan_ratio=scan_ratio, tol=tol, scheduler=scheduler, progress=progress, check=check)
    out.update({"id": label, "lambda": lam, "config": config, "mu_joint": mu_j, "mu_base": mu_b,
                "physics_engine": st.engine, "dt": st.dt,
                "input": "sine0", "a_range_g": [lam, a_max_ratio * lam]})
    return out


def analytic_domains(arch, freqs: Sequence[float], density: float = 500.0, workers: int | None = 1,
                     contact: float = 1.0, piers=None) -> dict:
    """Four-bar (minimised layout) and two-bar analytic domains of ``arch`` for the plain sine
    (``sine0``, the DEM input) at ``freqs``: name -> :class:`analytic.rocking.domain.FailureDomain`.
    With an effective ``contact`` < 1 only the four-bar (the two-bar does not model it); on
    ``piers`` only the four-bar of the discrete mechanism through them."""
    # deferred: `archdem --help` imports this module, not the linkages (scipy) (docs/architecture.md#imports)
    from analytic.rocking import linkage

    out = {}
    fb = linkage.governing_four_bar(arch, density, contact, piers)
    out["four-bar"] = linkage_domain(fb, "sine0", freqs, a_max_ratio=10.0, n_scan=24, tol=1e-3, workers=workers)
    if contact != 1.0 or piers is not None:
        return out
    try:
        tb = linkage.arch_two_bar(arch, density, direction=1)
        out["two-bar"] = linkage_domain(tb, "sine0", freqs, a_max_ratio=10.0, n_scan=24, tol=1e-3, workers=workers)
    except ArchdemInputError:  # pragma: no cover - two-bar not defined for this geometry
        pass
    return out


def dem_domain_json(res: dict) -> dict:
    """What ``archdem domain --engine dem --json`` prints of :func:`dem_failure_domain`'s answer: each
    threshold cut to its value, bracket, modes, count of runs and verdict (``archdem threshold``'s)."""
    keep = ("freq", "amplitude_g", "bracket_g", "mode", "collapse_phase", "n_sims", "verdict")
    return {k: v for k, v in res.items() if k != "thresholds"} | {
        "thresholds": [{k: t[k] for k in keep} for t in res["thresholds"]]}


def dem_domain_lines(label: str, res: dict) -> list[str]:
    """What ``archdem domain --engine dem`` prints of :func:`dem_failure_domain`'s answer on ``label``: the run,
    then the threshold [g], the survival bands above it and its verdict at each frequency, the checks' count
    and cost [s] if any ran, and the figure if one was drawn."""
    lines = [f"{label}  DEM ({res['physics_engine']}, dt {res['dt']:g} s, {res['config']}, mu {res['mu_joint']:g}/"
             f"{res['mu_base']:g})  static lambda {res['lambda']:.4f}"]
    verdicts = [t.get("verdict") or thresholds.NOT_CHECKED.to_dict() for t in res["thresholds"]]
    for t, v in zip(res["thresholds"], verdicts):
        a = "none up to %.3f g" % res["a_range_g"][1] if t["amplitude_g"] is None else f"{t['amplitude_g']:.4f} g"
        above = ", ".join(f"{b['from_g']:.3f}-{b['to_g']:.3f} g" for b in t["survival_bands_above"])
        lines.append(f"  {t['freq']:6.3g} Hz: collapse from {a}" + (f"; survives again {above}" if above else "")
                     + (f"; {verdict_phrase(v)}" if not _not_checked(v) else ""))
    runs = sum(r["check"] != "search" for v in verdicts for r in v["readings"])
    if not all(_not_checked(v) for v in verdicts):
        lines.append(f"  checks: {runs} runs, {sum(v['wall_s'] for v in verdicts):.1f} s")
    return lines + ([f"figure: {res['plot']}"] if "plot" in res else [])


def verdict_phrase(v: dict) -> str:
    """A threshold's verdict (:meth:`thresholds.Verdict.to_dict`) in a few words: ``settled``, ``range
    0.950-1.020 g`` (``below the scan`` / ``above`` the top read where a check left it open), or
    ``unchecked (why)``."""
    if v["status"] == "settled":
        return "settled"
    if v["status"] != "range":
        return v["text"]
    lo, hi = v["range_g"]
    top = max((r["amplitude_g"] for r in v["readings"]), default=math.nan)
    if lo is not None and hi is not None:
        return f"range {lo:.3f}-{hi:.3f} g"
    return (f"range {'below the scan' if lo is None else f'{lo:.3f} g'} to "
            f"{f'above {top:.3f} g' if hi is None else f'{hi:.3f} g'}")


def _not_checked(v: dict) -> bool:
    # the search alone (check off): no verdict to print, as ``archdem threshold --no-check`` prints none
    return v["status"] == thresholds.NOT_CHECKED.status and v.get("why") == thresholds.NOT_CHECKED.why


def analytic_domain_json(mech, dom, e: float) -> dict:
    """What ``archdem domain --json`` prints of the analytic domain ``dom`` of mechanism ``mech`` at energy
    restitution ``e``."""
    hinges = {"hinges": mech.summary()["hinges"]} if "hinges" in mech.summary() else {}
    return {"restitution": e, "omega0": dom.omega0, "phi_cr": dom.phi_cr, "lambda": dom.lam, **hinges,
            "points": dom.points(), "bands": dom.bands()}


def analytic_domain_lines(label: str, mech, dom, e: float) -> list[str]:
    """What ``archdem domain`` prints of the analytic domain ``dom`` of ``mech``: the linkage, then the
    collapsing amplitudes [g] and their modes at each frequency [Hz] or duration [s]."""
    unit = "Hz" if dom.axis == "frequency" else "s"
    lines = [f"{label}  {mech.label}  lambda {dom.lam:.4f}  omega0 {dom.omega0:.4g} rad/s  phi_cr {dom.phi_cr:.4g} rad  "
             f"e {e:.4f}"]
    for c in dom.columns:
        th = ", ".join(f"{a / 9.81:.4f} g ({m})" for a, m in c.thresholds) or "none below a_max"
        lines.append(f"  {c.x:8.4g} {unit}: collapse from {th}")
    return lines


@dataclass(frozen=True)
class AnalyticDomain:
    """The analytic failure domain ``domain`` (:class:`analytic.rocking.domain.FailureDomain`) of ``mechanism``
    (of the structure ``label``) at energy restitution ``restitution``, drawn into ``plot`` if given."""

    label: str
    mechanism: Any
    domain: Any
    restitution: float
    plot: str | None = None

    def to_json(self) -> dict:
        """What ``archdem domain --json`` prints (:func:`analytic_domain_json`)."""
        return analytic_domain_json(self.mechanism, self.domain, self.restitution)

    def lines(self) -> list[str]:
        """What ``archdem domain`` prints (:func:`analytic_domain_lines`), and the figure if one was drawn."""
        return (analytic_domain_lines(self.label, self.mechanism, self.domain, self.restitution)
                + ([f"figure: {self.plot}"] if self.plot else []))


@dataclass(frozen=True)
class DemDomain:
    """The DEM failure domain of the structure ``label``: :func:`dem_failure_domain`'s answer ``values``
    (with ``plot``, the figure's file, if one was drawn)."""

    label: str
    values: dict

    def to_json(self) -> dict:
        """What ``archdem domain --engine dem --json`` prints (:func:`dem_domain_json`)."""
        return dem_domain_json(self.values)

    def lines(self) -> list[str]:
        """What ``archdem domain --engine dem`` prints (:func:`dem_domain_lines`)."""
        return dem_domain_lines(self.label, self.values)


@dataclass(frozen=True)
class DomainThreshold(Result):
    """One frequency of a specimen's DEM domain beside the four-bar's and two-bar's least collapsing
    amplitudes [g] (NaN where none), with the threshold's settled-or-range verdict: a row of the shake step."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("id", "str"), Column("freq_Hz", "float", "Hz"), Column("lambda_static", "float"),
        Column("a_dem_g", "float", "g"), Column("dem_mode", "str"), Column("collapse_phase", "str"),
        Column("a_four_bar_g", "float", "g"), Column("a_two_bar_g", "float", "g"), Column("ratio_dem_to_four_bar", "float"),
        Column("survival_bands_above", "str", "g"), Column("n_sims", "int"), Column("verdict", "str"),
        Column("verdict_text", "str"), Column("range_low_g", "float", "g"), Column("range_high_g", "float", "g"),
        Column("check_runs", "int"), Column("check_wall_s", "float", "s"),
    ))

    row: dict  # the schema's columns

    @classmethod
    def of(cls, sid: str, lam: float, t: dict, a_four_bar_g: float | None, a_two_bar_g: float | None) -> "DomainThreshold":
        """The row of threshold ``t`` (a summary of :class:`thresholds.ThresholdResult`) of specimen ``sid`` of
        static multiplier ``lam``, beside the linkages' thresholds (None: none)."""
        nan = float("nan")
        a, fb = t["amplitude_g"], a_four_bar_g
        v = t["verdict"]
        lo, hi = v["range_g"]
        return cls({
            "id": sid, "freq_Hz": t["freq"], "lambda_static": lam,
            "a_dem_g": a if a is not None else nan, "dem_mode": t.get("mode") or "",
            "collapse_phase": t.get("collapse_phase") or "",
            "a_four_bar_g": fb if fb is not None else nan,
            "a_two_bar_g": a_two_bar_g if a_two_bar_g is not None else nan,
            "ratio_dem_to_four_bar": (a / fb) if (a is not None and fb) else nan,
            "survival_bands_above": " ".join(f"{b['from_g']:.3f}-{b['to_g']:.3f}" for b in t.get("survival_bands_above", [])),
            "n_sims": t.get("n_sims", 0), "verdict": v["status"], "verdict_text": v["text"],
            "range_low_g": nan if lo is None else lo, "range_high_g": nan if hi is None else hi,
            "check_runs": sum(r["check"] != "search" for r in v["readings"]), "check_wall_s": v["wall_s"]})

    def rows(self) -> list[dict]:
        return [self.row]


__all__ = ["dem_failure_domain", "analytic_domains", "AnalyticDomain", "DemDomain", "DomainThreshold", "dem_domain_json", "dem_domain_lines",
           "verdict_phrase", "analytic_domain_json", "analytic_domain_lines"]
