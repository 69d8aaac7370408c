"""The code assessment of an arch with its virtual check (docs/physics/assessment.md): the codes'
kinematic checks of its governing mechanism against a site's spectrum (with FRP strips or a tie-rod:
the strengthened one's too), and records matched to the site over the period range of the check,
shaken on the DEM (:mod:`dem.experiments.record.run`)."""
from __future__ import annotations

import os
from dataclasses import dataclass, replace

from analytic.codes.assessment import Assessment, assess, monument_site
from analytic.codes.frp import StrengthenedCollapse, Strips, strengthened_collapse
from analytic.codes.kinematic import CONFIDENCE_FACTORS, Q_MASONRY, Height
from analytic.motions.inputs import SampledMotion
from analytic.motions.matching import MatchedRecord, match_record
from analytic.motions.records import baseline_correct, read_record
from analytic.limit.limit_discrete import require_standing
from analytic.limit.ties import Tie, tie_link
from analytic.rocking.linkage import governing_four_bar
from dem.core.model import Model, from_assembly
from dem.core.settings import Settings, dynamics_settings
from dem.core.ties import tie_spec
from dem.experiments.record.run import RecordRun, dem_verdict, run_records
from specimens.blocks import DEFAULT_DENSITY, Assembly, discretise
from specimens.catalogue import Specimen, get_specimen
from specimens.drawn import DrawnAssembly
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from specimens.monuments import MONUMENTS, Monument

#: What the DEM of the virtual check leaves out, and what it shakes with a tie (and no strips).
DEM_NOTE = "the DEM shakes the unreinforced structure (strips and ties are not modelled)"
DEM_NOTE_TIED = "the DEM shakes the tied structure (an elastic-perfectly-plastic tie) against the tied assessment"


@dataclass(frozen=True)
class RecordCheck:
    """Records matched to the site over ``period_range`` [s] and run on the DEM: the matches, the
    runs and the codes' verdict over them (:func:`dem.experiments.record.run.dem_verdict`); ``tied``:
    the DEM shook the tied structure, against the tied assessment."""

    period_range: tuple[float, float]
    matched: tuple[MatchedRecord, ...]
    runs: tuple[RecordRun, ...]
    verdict: dict
    engine: str
    tied: bool = False

    def describe(self) -> dict:
        return {"period_range": list(self.period_range), "matched": [m.describe() for m in self.matched],
                "runs": [r.describe() for r in self.runs], "verdict": self.verdict, "engine": self.engine,
                "dem_note": DEM_NOTE_TIED if self.tied else DEM_NOTE}


def match_period_range(assessment: Assessment, site) -> tuple[float, float]:
    """The default period range of the match [s]: 0.2 to 2 times the displacement check's period
    (at most the spectrum's last period)."""
    period = _displacement_check(assessment)["period"]
    return 0.2 * period, min(2.0 * period, site.t_max)


def _displacement_check(assessment: Assessment) -> dict:
    check = next((c for c in assessment.checks if c["kind"] == "non-linear"), None)
    if check is None:
        raise ArchdemInputError("records check the displacement demand, which the SLD has not: assess SLV or SLC")
    return check


def check_records(assembly: Assembly | Model, assessment: Assessment, site, records,
                  period_range: tuple[float, float] | None = None, settings: Settings | None = None,
                  workers: int | None = None) -> RecordCheck:
    """The virtual check of ``assessment``: each of ``records`` (files, or sampled motions) baseline-
    corrected, matched to ``site`` over ``period_range`` (default :func:`match_period_range`) and run
    on ``assembly`` (or a model: with ties, the tied structure) in ``workers`` processes (default: one
    per record, at most the cores)."""
    du_star = _displacement_check(assessment)["d_u_star"]
    lo, hi = period_range if period_range is not None else match_period_range(assessment, site)
    motions = [r if isinstance(r, SampledMotion) else read_record(r) for r in records]
    matched = [match_record(baseline_correct(m), site, (lo, hi)) for m in motions]
    settings = settings or dynamics_settings()
    runs = run_records(assembly, [m.motion for m in matched], assessment.curve.e_star, settings,
                       workers=workers or min(len(matched), os.cpu_count() or 1))
    return RecordCheck((lo, hi), tuple(matched), tuple(runs), dem_verdict(runs, assessment.curve.d0_star, du_star),
                       settings.engine, isinstance(assembly, Model) and bool(assembly.ties))


@dataclass(frozen=True)
class ArchAssessment:
    """The assessment of one arch: its governing ``mechanism``, the code checks (``assessment``), with
    strips or a tie the strengthened structure's least mechanism (``strengthened``) and its checks
    (``strengthened_assessment``), and with records their virtual check (``records``: of the tied
    structure against the tied assessment when a tie acts without strips, else of the unreinforced one)."""

    label: str
    site: object
    mechanism: object
    assessment: Assessment
    records: RecordCheck | None = None
    strengthened: StrengthenedCollapse | None = None
    strengthened_assessment: Assessment | None = None

    def summary(self) -> str:
        """The verdicts in one line: the code's, and the DEM's over the records."""
        a = self.assessment
        text = (f"{self.label}: code check {'verified' if a.verified else 'NOT verified'} "
                f"(safety index {a.safety_index:.2f})")
        if self.strengthened_assessment is not None:
            s = self.strengthened_assessment
            text += (f"; strengthened {'verified' if s.verified else 'NOT verified'} "
                     f"(safety index {s.safety_index:.2f})")
        if self.records is not None:
            v = self.records.verdict
            text += (f"; DEM{' (tied)' if self.records.tied else ''} over {v['n_records']} record(s): mean peak d* {v['mean_peak_d_star'] * 1e3:.3g} mm vs "
                     f"d_u* {v['du_star'] * 1e3:.3g} mm, {v['n_collapsed']} collapse(s) -> "
                     f"{'verified' if v['verified'] else 'NOT verified'}")
        return text


def _structure(target, configuration: str | None):
    """``(label, arch, density, piers, default site)`` of a monument (name or :class:`Monument`) or an
    arch (catalogue id, Specimen, PointedArch, or a drawn assembly, :mod:`specimens.drawn`)."""
    monument = MONUMENTS.get(target) if isinstance(target, str) else target if isinstance(target, Monument) else None
    if monument is None:
        if configuration is not None:
            raise ArchdemInputError("configuration names a monument's piers; give piers= for an arch")
        spec = get_specimen(target) if isinstance(target, str) else target
        if isinstance(spec, Specimen):
            return spec.id, spec.arch, None, None, None
        if isinstance(spec, PointedArch):
            return "arch", spec, None, None, None
        if isinstance(spec, DrawnAssembly):  # its own discrete governing mechanism (governing_four_bar)
            return spec.source.get("file", "drawing"), spec, None, None, None
        raise ArchdemInputError(f"expected a monument, specimen id, Specimen, PointedArch or drawn assembly, "
                                f"got {type(target).__name__}")
    name = configuration if configuration is not None else next(iter(monument.configurations))
    if name not in monument.configurations:
        raise ArchdemInputError(f"{monument.name} has the configurations {', '.join(monument.configurations)}, "
                                f"not {name!r}")
    return f"{monument.name}, {name}", monument.arch, monument.density, monument.configurations[name], monument_site()


def assess_with_records(target, records=(), site=None, *, configuration: str | None = None,
                        FC: float = CONFIDENCE_FACTORS["LC1"], q: float = Q_MASONRY, limit_state: str = "SLV",
                        height: Height | None = None, period_range: tuple[float, float] | None = None,
                        settings: Settings | None = None, workers: int | None = None,
                        density: float | None = None, contact: float = 1.0, piers=None,
                        n_voussoirs: int | None = None, strips: Strips | None = None, tie: Tie | None = None,
                        sld_site=None) -> ArchAssessment:
    """Assess ``target`` against ``site`` (:mod:`analytic.motions.spectra`) as ``archdem assess --records`` does:
    the governing four-bar (:func:`analytic.rocking.linkage.governing_four_bar`), the code checks of
    ``limit_state`` (:func:`analytic.codes.assessment.assess`) and, with ``records`` (files or sampled
    motions), their virtual check on the DEM (:func:`check_records`).

    ``target``: a monument (``"noh-gumbad"``: its ring as reconstructed, the piers of ``configuration``
    (default the first, "ring alone"), its density, by default its site, and the least mechanism of
    the fine cut as in :func:`analytic.codes.assessment.assess_monument`) or an arch (catalogue id,
    ``Specimen``, ``PointedArch`` or a drawn assembly, :func:`specimens.read_assembly`; ``site`` needed). ``density`` [kg/m^3], ``contact`` (the joints'
    contact fraction), ``piers`` and ``n_voussoirs``: the blocks, as :func:`specimens.blocks.discretise`.
    ``sld_site``: the SLD hazard, its activation check beside a life-safety one (:func:`analytic.codes.assessment.assess`).

    ``strips`` (:class:`analytic.codes.frp.Strips`) or ``tie`` (:class:`analytic.limit.ties.Tie`): the
    strengthened structure's least mechanism (:func:`analytic.codes.frp.strengthened_collapse`) and its
    checks too; with a tie and no strips the records shake the tied structure (its elastic-perfectly-
    plastic tie in the engine, :mod:`dem.core.ties`) against the tied assessment, else the unreinforced
    one against the unreinforced assessment (the DEM does not model strips).
    """
    label, arch, m_density, m_piers, m_site = _structure(target, configuration)
    site = site if site is not None else m_site
    if site is None:
        raise ArchdemInputError("the assessment needs the site's elastic spectrum (analytic.motions.spectra: ec8, ntc2018)")
    piers = piers if piers is not None else m_piers
    kw = {"density": density if density is not None else m_density if m_density is not None else DEFAULT_DENSITY,
          "contact": contact, "piers": piers, **({"n_voussoirs": n_voussoirs} if n_voussoirs is not None else {})}
    if piers is not None:
        piers.check(arch)
    if m_site is not None:  # a monument: its least mechanism of the fine cut, as its rows (assess_monument)
        sc = strengthened_collapse(arch, None, kw["density"], piers, load_sign=1)
        mech = sc.mechanism
        res = assess(mech, site, FC, q, limit_state, height, alpha0=sc.lam, sld_site=sld_site)
    else:
        require_standing(label, discretise(arch, **kw))
        mech = governing_four_bar(arch, kw["density"], kw["contact"], kw["piers"],
                                  **({"n_voussoirs": n_voussoirs} if n_voussoirs is not None else {}))
        res = assess(mech, site, FC, q, limit_state, height, sld_site=sld_site)
    strengthened = strengthened_res = None
    if strips is not None or tie is not None:
        # a monument's rows load along +x (assess_monument); an arch's governing four-bar along -x
        strengthened = strengthened_collapse(arch, strips, kw["density"], piers, load_sign=1 if m_site is not None else -1,
                                             tie=tie)
        strengthened_res = assess(strengthened.mechanism, site, FC, q, limit_state, height, alpha0=strengthened.lam,
                                  extra_force=strengthened.extra_force, sld_site=sld_site)
    check = None
    if records:
        target = discretise(arch, **kw)
        tied = tie is not None and strips is None  # the DEM models a tie, not strips
        if tied:
            target = replace(from_assembly(target), ties=(tie_spec(tie_link(target, tie), tie.area, tie.prestress),))
        check = check_records(target, strengthened_res if tied else res, site, records, period_range, settings, workers)
    return ArchAssessment(label, site, mech, res, check, strengthened, strengthened_res)


__all__ = ["DEM_NOTE", "DEM_NOTE_TIED", "RecordCheck", "match_period_range", "check_records", "ArchAssessment", "assess_with_records"]
