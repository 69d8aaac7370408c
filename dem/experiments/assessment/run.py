"""The code assessment of an arch with its virtual check (docs/physics/assessment.md): the codes'
kinematic checks of its governing mechanism against a site's spectrum (with FRP strips or a tie-rod:
the strengthened one's too), and records matched to the site over the period range of the check,
shaken on the DEM (:mod:`dem.experiments.record.run`)."""
from __future__ import annotations

import os
from dataclasses import dataclass, replace
from typing import Any, ClassVar

from analytic.codes.assessment import Assessment, assess, assess_monument, index_text, monument_site, quantity_text
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
from dem.experiments.contract import Column, Result, Schema
from dem.experiments.record import RecordRun, dem_verdict, run_records
from specimens.blocks import DEFAULT_DENSITY, Assembly, discretise
from specimens.catalogue import Specimen, get_specimen
from specimens.drawn import DrawnAssembly
from foundation.errors import ArchdemInputError
from specimens.constants import G
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


def check_table(rows: list[dict], lead: list[tuple[str, int, list[str]]] | None = None) -> list[str]:
    """The terminal table of :func:`analytic.codes.assessment.check_rows`: demand and capacity as the
    clause compares them, the index (capacity / demand), the verdict and the clause; ``lead``: columns
    before them, as (header, width, one value per row)."""
    lead = lead or []
    head = "".join(f"{h:{w}s} " for h, w, _ in lead)
    out = [f"  {head}{'limit state / check':28s} {'demand':>32s} {'capacity':>34s} {'index':>7s}  {'verdict':12s}  clause"]
    for k, r in enumerate(rows):
        cols = "".join(f"{vals[k]:{w}s} " for _, w, vals in lead)
        name = f"{r['limit_state']} {r['check']}" + ("" if r["code_check"] else " *")
        out.append(f"  {cols}{name:28s} {r['demand_symbol'] + ' ' + quantity_text(r['demand'], r['unit']):>32s} "
                   f"{r['capacity_symbol'] + ' ' + quantity_text(r['capacity'], r['unit']):>34s} "
                   f"{index_text(r['safety_index']):>7s}  {r['verdict']:12s}  {r['clause']}")
    if any(not r["code_check"] for r in rows):
        out.append("  * the a0*/PGA convention of published tables: reported, not a code check, never governs")
    return out


def _where(height: Height | None) -> str:
    return "ground level" if height is None else f"z/H = {height.z_ratio:g} of a {height.floors}-floor building"


def _bond_line(strips: Strips) -> str:
    """The bond factors of strips designed on a masonry; the tensile ratio only for a named masonry type."""
    return f"FRP bond factors (CNR-DT 200 R1/2013): {strips.bond.text(strips.masonry.name != 'given')}"


def _mechanism_lines(title: str, hinges: list[dict], res: Assessment) -> list[str]:
    """One mechanism's block of the printed assessment: its hinges, its parameters, its checks."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.figure import hinges_text

    d = res.describe()
    return [f"  {title}: hinges at {hinges_text(hinges)}",
            f"    alpha0 = {d['alpha0']:.4f}   M* = {d['M_star']:.4g} kg   e* = {d['e_star']:.3f}   "
            f"a0* = {d['a0_star'] / G:.4f} g (FC {d['FC']:g})   d0* = {d['d0_star'] * 1e3:.4g} mm",
            *("  " + line for line in check_table(d["check_rows"])),
            f"    governing: {d['governing_check']}, safety index {index_text(d['safety_index'])} "
            f"({'verified' if d['verified'] else 'not verified'})"]


#: The checks table of an assessment (every check as the code states it), as a campaign writes it.
CHECKS_SCHEMA = Schema((
    Column("limit_state", "str"), Column("kind", "str"), Column("check", "str"), Column("demand_symbol", "str"),
    Column("demand", "float"), Column("capacity_symbol", "str"), Column("capacity", "float"), Column("unit", "str"),
    Column("safety_index", "float"), Column("verdict", "str"), Column("code_check", "bool"), Column("clause", "str"),
))


@dataclass(frozen=True)
class AssessSpec:
    """What to assess and how (:func:`run`): ``target`` a monument (``"noh-gumbad"``, one of its
    ``configuration``) or an arch (catalogue id, Specimen, PointedArch, drawn assembly); ``site`` its
    elastic spectrum (a monument's own by default); ``records`` (files or sampled motions) for the
    virtual check on the DEM over ``period_range`` [s] with ``settings`` in ``workers`` processes; the
    codes' ``FC``, ``q``, ``limit_state``, ``height`` and SLD hazard ``sld_site``; the blocks' ``density``
    [kg/m^3], ``contact``, ``piers``, ``n_voussoirs``; the strengthening ``strips`` and ``tie``; ``label``
    names it (default the target's id)."""

    target: Any
    site: Any = None
    records: tuple = ()
    configuration: str | None = None
    FC: float = CONFIDENCE_FACTORS["LC1"]
    q: float = Q_MASONRY
    limit_state: str = "SLV"
    height: Height | None = None
    period_range: tuple[float, float] | None = None
    settings: Settings | None = None
    workers: int | None = None
    density: float | None = None
    contact: float = 1.0
    piers: Any = None
    n_voussoirs: int | None = None
    strips: Strips | None = None
    tie: Tie | None = None
    sld_site: Any = None
    label: str | None = None


@dataclass(frozen=True)
class ArchAssessment(Result):
    """The assessment of one arch: its governing ``mechanism``, the code checks (``assessment``), with
    strips or a tie the strengthened structure's least mechanism (``strengthened``) and its checks
    (``strengthened_assessment``), and with records their virtual check (``records``: of the tied
    structure against the tied assessment when a tie acts without strips, else of the unreinforced one).
    Its table: the unreinforced structure's checks as the code states them (:data:`CHECKS_SCHEMA`)."""

    SCHEMA: ClassVar[Schema] = CHECKS_SCHEMA

    label: str
    site: object
    mechanism: object
    assessment: Assessment
    records: RecordCheck | None = None
    strengthened: StrengthenedCollapse | None = None
    strengthened_assessment: Assessment | None = None
    spec: AssessSpec | None = None  # what was assessed (None: built by hand)
    arch: object = None  # the arch or drawn assembly assessed (its width sizes the strips)

    def rows(self) -> list[dict]:
        return [{c: r[c] for c in self.SCHEMA.names} for r in self.assessment.describe()["check_rows"]]

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

    @property
    def strengthened_key(self) -> str:
        """The JSON key of the strengthened structure: ``frp`` with strips, else ``tie``."""
        return "frp" if self.spec is not None and self.spec.strips is not None else "tie"

    def strengthened_describe(self) -> dict | None:
        """The strengthened structure (strips and their design, tie and its force at collapse, its
        mechanism and checks), or None without strengthening."""
        sc, spec = self.strengthened, self.spec
        if sc is None or spec is None:
            return None
        strips, tie = spec.strips, spec.tie
        return {"strips": None if strips is None else strips.describe(self.arch.width), "lambda": sc.lam,
                "mechanism": sc.mechanism.summary(), "hinges": sc.mechanism.summary()["hinges"],
                "strip_hinges": sc.strip_hinges(),
                "crushing": None if strips is None else sc.crushing(strips.masonry, spec.FC),
                "tie": None if tie is None else {**tie.describe(), "force_at_collapse_kN": sc.tie_lp_force / 1e3,
                                                 "anchors_m": [sc.tie_link.p_a.tolist(), sc.tie_link.p_b.tolist()]},
                **self.strengthened_assessment.describe()}

    def describe(self) -> dict:
        """The assessment as ``archdem assess --json`` prints it."""
        height = None if self.spec is None else self.spec.height
        out = {"id": self.label, "spectrum": self.site.describe(), "height": None if height is None else vars(height),
               "mechanism": self.mechanism.summary(), **self.assessment.describe()}
        strengthened = self.strengthened_describe()
        if strengthened is not None:
            out[self.strengthened_key] = strengthened
        if self.records is not None:
            out["records"] = self.records.describe()
        return out

    def write_report(self, path: str, out: dict | None = None, project: str = "-", engineer: str = "-",
                     inputs: list | None = None) -> None:
        """The assessment with its figures: ``FILE.html`` one page, ``FILE.pdf`` a printable report (its title
        block names ``project`` and ``engineer``, its inputs ``inputs``); ``out``: its :meth:`describe` if at hand."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.figure import write_report
        from dem.experiments.assessment.report_pdf import write_pdf_report

        out = self.describe() if out is None else out
        args = (path, self.label, self.site, self.mechanism, self.assessment, out, self.strengthened_assessment,
                out.get(self.strengthened_key))
        if str(path).lower().endswith(".pdf"):
            write_pdf_report(*args, project=project, engineer=engineer, inputs=inputs)
        else:
            write_report(*args)

    def lines(self, out: dict | None = None) -> list[str]:
        """The assessment as ``archdem assess`` prints it; ``out``: its :meth:`describe` if at hand."""
        out = self.describe() if out is None else out
        spec = self.spec or AssessSpec(self.label)
        strips, tie, res, frp = spec.strips, spec.tie, self.assessment, self.strengthened_assessment
        text = [f"{self.label}: {self.site.describe()['code']} site, ag = {self.site.ag / G:.3f} g, PGA = "
                f"{self.site.pga / G:.3f} g; {spec.limit_state.upper()}, mechanism at {_where(spec.height)}",
                *_mechanism_lines(f"unreinforced ({self.mechanism.label})", out["mechanism"].get("hinges", []), res)]
        if frp is not None:
            st = out[self.strengthened_key]
            parts = []
            if strips is not None:
                sd = st["strips"]
                parts.append(f"FRP strips on the {strips.face}, f_fd = {sd['design_strength_MPa']:.4g} MPa "
                             f"({sd['governing']}), T = {sd['force_N'] / 1e3:.3g} kN")
            if tie is not None:
                parts.append(f"a tie at {tie.height:g} m yielding at {tie.force / 1e3:.4g} kN "
                             f"({st['tie']['force_at_collapse_kN']:.4g} kN at collapse)")
            text += _mechanism_lines("with " + " and ".join(parts), st["hinges"], frp)
            if strips is not None and strips.masonry is not None:
                text.append(f"    {_bond_line(strips)}")
            for c in st["crushing"] or []:
                text.append(f"    crushing at {c['joint']} ({c['face']}): C = {c['C_kN']:.3g} kN, stress block "
                            f"{c['y_mm']:.3g} mm of {c['t_mm']:.3g} mm ({'verified' if c['verified'] else 'not verified'})")
        if self.records is not None:
            rec = out["records"]
            text.append(f"  records matched over {rec['period_range'][0]:.3g}-{rec['period_range'][1]:.3g} s, DEM "
                        f"({rec['engine']}, {'tied' if self.records.tied else 'unreinforced'}):")
            for m, r in zip(rec["matched"], rec["runs"]):
                text.append(f"    {m['record'][:48]:48s} x{m['scale']:.3g} (misfit {m['misfit_mean_ln']:.2f}): "
                            f"{'COLLAPSE' if r['collapsed'] else 'stands'}, peak d* {r['peak_d_star'] * 1e3:.3g} mm")
            v = rec["verdict"]
            code = (frp if self.records.tied else res).verified
            text.append(f"    mean peak d* {v['mean_peak_d_star'] * 1e3:.3g} mm vs d_u* {v['du_star'] * 1e3:.3g} mm, "
                        f"{v['n_reach_d0']} of {v['n_records']} reach d0* -> {'verified' if v['verified'] else 'NOT verified'}"
                        f" (code check: {'verified' if code else 'NOT verified'})")
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
    motions), their virtual check on the DEM (:func:`check_records`). :func:`run` of an :class:`AssessSpec`.

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
    return run(AssessSpec(target, site, tuple(records), configuration, FC, q, limit_state, height, period_range,
                          settings, workers, density, contact, piers, n_voussoirs, strips, tie, sld_site))


def _run_arch(spec: AssessSpec) -> ArchAssessment:
    label, arch, m_density, m_piers, m_site = _structure(spec.target, spec.configuration)
    label = spec.label if spec.label is not None else label
    site = spec.site if spec.site is not None else m_site
    if site is None:
        raise ArchdemInputError("the assessment needs the site's elastic spectrum (analytic.motions.spectra: ec8, ntc2018)")
    FC, q, limit_state, height, sld_site = spec.FC, spec.q, spec.limit_state, spec.height, spec.sld_site
    strips, tie, n_voussoirs = spec.strips, spec.tie, spec.n_voussoirs
    piers = spec.piers if spec.piers is not None else m_piers
    kw = {"density": spec.density if spec.density is not None else m_density if m_density is not None else DEFAULT_DENSITY,
          "contact": spec.contact, "piers": piers, **({"n_voussoirs": n_voussoirs} if n_voussoirs is not None else {})}
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
    if spec.records:
        target = discretise(arch, **kw)
        tied = tie is not None and strips is None  # the DEM models a tie, not strips
        if tied:
            target = replace(from_assembly(target), ties=(tie_spec(tie_link(target, tie), tie.area, tie.prestress),))
        check = check_records(target, strengthened_res if tied else res, site, spec.records, spec.period_range,
                              spec.settings, spec.workers)
    return ArchAssessment(label, site, mech, res, check, strengthened, strengthened_res, spec, arch)


# ------------------------------------------------------------------------------------------ a monument
@dataclass(frozen=True)
class MonumentSpec:
    """A monument (:mod:`specimens.monuments`) assessed in every configuration, unreinforced, with
    ``strips`` and with ``tie`` alone, against ``site`` (its own by default), as
    :func:`analytic.codes.assessment.assess_monument` does; ``sld_site``: the SLD hazard beside."""

    monument: Monument
    strips: Strips
    site: Any = None
    FC: float = CONFIDENCE_FACTORS["LC1"]
    q: float = Q_MASONRY
    limit_state: str = "SLV"
    height: Height | None = None
    tie: Tie | None = None
    sld_site: Any = None


def _strengthening(row: dict) -> str:
    return "+".join(k for k, on in (("FRP", row.get("frp")), ("tie", row.get("tie"))) if on) or "none"


@dataclass(frozen=True)
class MonumentAssessment(Result):
    """A monument's configurations assessed (``assessed``: the rows of
    :func:`analytic.codes.assessment.assess_monument`). Its table (``SCHEMA``): one row per configuration
    and strengthening, accelerations in g and displacements in mm; :meth:`check_rows` (``CHECKS_SCHEMA``)
    every check as the code states it, :meth:`calculation_rows` the governing configuration's calculation."""

    SCHEMA: ClassVar[Schema] = Schema((
        Column("configuration", "str"), Column("frp", "bool"), Column("lambda", "float"), Column("e_star", "float"),
        Column("M_star_kg", "float", "kg"), Column("a0_star_g", "float", "g"), Column("d0_star_mm", "float", "mm"),
        Column("du_star_mm", "float", "mm"), Column("a0_over_pga_published_convention", "float"),
        Column("safety_index_linear", "float"), Column("safety_index_displacement", "float"),
        Column("verified", "bool"), Column("hinges_rad", "str", "rad"),
    ))
    CHECKS_SCHEMA: ClassVar[Schema] = Schema((
        Column("configuration", "str"), Column("frp", "bool"), Column("limit_state", "str"), Column("check", "str"),
        Column("demand", "str"), Column("demand_value", "float"), Column("capacity", "str"),
        Column("capacity_value", "float"), Column("unit", "str"), Column("safety_index", "float"),
        Column("verdict", "str"), Column("clause", "str"),
    ))
    CALCULATION_SCHEMA: ClassVar[Schema] = Schema((
        Column("quantity", "str"), Column("value", "str"), Column("unit", "str"), Column("formula", "str"),
    ))

    spec: MonumentSpec
    site: Any
    assessed: list

    def rows(self) -> list[dict]:
        return [{"configuration": r["configuration"], "frp": r["frp"], "lambda": r["lambda"], "e_star": r["e_star"],
                 "M_star_kg": r["M_star"], "a0_star_g": r["a0_star"] / G, "d0_star_mm": r["d0_star"] * 1e3,
                 "du_star_mm": r["du_star"] * 1e3, "a0_over_pga_published_convention": r["activation_over_pga"],
                 "safety_index_linear": r["safety_index_linear"],
                 "safety_index_displacement": r["safety_index_displacement"], "verified": r["verified"],
                 "hinges_rad": " ".join(f"{h['angle_rad']:.3f}" for h in r["hinges"])} for r in self.assessed]

    def check_rows(self) -> list[dict]:
        """Every check as the code states it: accelerations in g, displacements in mm; the index is
        capacity / demand of the two values beside it."""
        def row(c: dict) -> dict:
            f, unit = (1 / G, "g") if c["unit"] == "m/s^2" else (1e3, "mm")
            return {"limit_state": c["limit_state"], "check": c["check"], "demand": f"{c['demand_symbol']}",
                    "demand_value": c["demand"] * f, "capacity": c["capacity_symbol"], "capacity_value": c["capacity"] * f,
                    "unit": unit, "safety_index": c["safety_index"], "verdict": c["verdict"], "clause": c["clause"]}

        return [{"configuration": r["configuration"], "frp": r["frp"], **row(c)}
                for r in self.assessed for c in r["check_rows"]]

    @property
    def governing(self) -> dict:
        """The governing configuration's row (the least governing index)."""
        return min(self.assessed, key=lambda r: r["safety_index"])

    def calculation_rows(self) -> list[dict]:
        """The governing configuration's calculation, line by line, with its unit and formula."""
        return [{"quantity": st["symbol"],
                 "value": " ".join(f"{v:.5g}" for v in st["value"]) if isinstance(st["value"], list) else st["value"],
                 "unit": st["unit"], "formula": st["formula"]} for st in self.governing["trail"]]

    def describe(self) -> dict:
        """The assessment as ``archdem assess MONUMENT --json`` prints it."""
        m, spec, sld = self.spec.monument, self.spec, self.spec.sld_site
        return {"id": m.name, "source": m.source, "arch": {"e": m.arch.e, "t": m.arch.t, "Rp": m.arch.Rp,
                "width": m.arch.width, "span": m.arch.span, "rise": m.arch.rise},
                "configurations": {k: (None if v is None else vars(v)) for k, v in m.configurations.items()},
                "density": m.density, "spectrum": self.site.describe(),
                "sld_spectrum": None if sld is None else sld.describe(),
                "height": None if spec.height is None else vars(spec.height),
                "strips": spec.strips.describe(m.arch.width), "tie": None if spec.tie is None else spec.tie.describe(),
                "rows": self.assessed}

    def write_report(self, path: str, project: str = "-", engineer: str = "-") -> None:
        """Every configuration and the governing one's calculation: ``FILE.pdf`` a printable report (its title
        block names ``project`` and ``engineer``), else one HTML page of the governing configuration."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.figure import write_report
        from dem.experiments.assessment.report_pdf import monument_governing, write_monument_pdf_report

        spec, m = self.spec, self.spec.monument
        if str(path).lower().endswith(".pdf"):
            write_monument_pdf_report(path, m, self.site, spec.strips, spec.FC, spec.q, spec.limit_state, project,
                                      engineer, rows=self.assessed, height=spec.height, sld_site=spec.sld_site)
        else:
            _, name, *gov = monument_governing(m, self.site, spec.strips, spec.FC, spec.q, spec.limit_state,
                                               self.assessed, spec.height, spec.sld_site)
            write_report(path, f"{m.name} ({name})", self.site, *gov)

    def lines(self) -> list[str]:
        """The assessment as ``archdem assess MONUMENT`` prints it."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.figure import hinges_text

        spec, site, rows = self.spec, self.site, self.assessed
        m, strips, tie, sld = spec.monument, spec.strips, spec.tie, spec.sld_site
        sd = strips.describe(m.arch.width)
        text = [f"{m.name}: {site.describe()['code']} site, PGA {site.pga / G:.3f} g ({site.pga:.3g} m/s^2); "
                f"{spec.limit_state.upper()}{'' if sld is None else f' and SLD (ag {sld.ag / G:.3f} g)'}, at "
                f"{_where(spec.height)}; FRP {sd['strength_MPa']:g} MPa x {strips.thickness * 1e3:g} mm x "
                f"{strips.width * 1e3:g} mm on the {strips.face}: design {sd['design_strength_MPa']:.4g} MPa "
                f"({sd['governing']}), force {sd['force_N'] / 1e3:.3g} kN"
                + ("" if tie is None else f"; tie at {tie.height:g} m yielding at {tie.force / 1e3:.4g} kN "
                                          "(without the strips)"),
                f"  {'configuration':18s} {'strengthening':13s} {'lambda':>7s} {'e*':>6s} {'a0* [g]':>8s} "
                f"{'d0* [mm]':>9s} {'a0*/PGA':>7s} {'governing':>22s} {'index':>7s}  {'verdict':12s}  hinges"]
        for r in rows:
            text.append(f"  {r['configuration']:18s} {_strengthening(r):13s} {r['lambda']:7.4f} {r['e_star']:6.3f} "
                        f"{r['a0_star'] / G:8.4f} {r['d0_star'] * 1e3:9.4g} {r['activation_over_pga']:7.3f} "
                        f"{r['governing_check']:>22s} {index_text(r['safety_index']):>7s}  "
                        f"{'verified' if r['verified'] else 'not verified':12s}  {hinges_text(r['hinges'])}")
        text.append("  checks (safety index = capacity / demand):")
        flat = [(r, c) for r in rows for c in r["check_rows"]]
        text += check_table([c for _, c in flat], [("configuration", 18, [r["configuration"] for r, _ in flat]),
                                                   ("strengthening", 13, [_strengthening(r) for r, _ in flat])])
        if strips.masonry is not None:
            text.append(f"  {_bond_line(strips)}")
        return text


def _run_monument(spec: MonumentSpec) -> MonumentAssessment:
    site = spec.site if spec.site is not None else monument_site()
    rows = assess_monument(spec.monument, site, spec.strips, spec.FC, spec.q, spec.limit_state, height=spec.height,
                           tie=spec.tie, sld_site=spec.sld_site)
    return MonumentAssessment(spec, site, rows)


def run(spec: AssessSpec | MonumentSpec) -> ArchAssessment | MonumentAssessment:
    """The assessment ``spec`` asks for: an arch (or one monument configuration) with its records
    (:class:`AssessSpec`), or a monument in every configuration (:class:`MonumentSpec`)."""
    if isinstance(spec, MonumentSpec):
        return _run_monument(spec)
    if isinstance(spec, AssessSpec):
        return _run_arch(spec)
    raise ArchdemInputError(f"expected an AssessSpec or a MonumentSpec, got {type(spec).__name__}")


__all__ = ["DEM_NOTE", "DEM_NOTE_TIED", "RecordCheck", "match_period_range", "check_records", "AssessSpec",
           "ArchAssessment", "MonumentSpec", "MonumentAssessment", "CHECKS_SCHEMA", "check_table", "run",
           "assess_with_records"]
