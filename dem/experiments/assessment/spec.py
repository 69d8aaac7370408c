"""The options of ``archdem assess`` as one frozen spec: each field is an option (its help, unit and
choices in its metadata, its default the library's), checked once in the spec itself; the command adds
them from the fields (:func:`dem.experiments.contract.add_spec_options`). The spec builds the library's
objects (site, height, strips, tie) and the run spec of :mod:`dem.experiments.assessment.run`."""
from __future__ import annotations

import inspect
import math
from dataclasses import dataclass, field, fields
from functools import cached_property
from typing import TYPE_CHECKING, Any

from analytic.codes.assessment import assess, monument_site, monument_strips
from analytic.codes.frp import ETA_A, GAMMA_F, GAMMA_FD, MASONRY_TYPES, BondFactors, Masonry, Strips, masonry_type
from analytic.codes.kinematic import CONFIDENCE_FACTORS, Height
from analytic.limit.ties import Tie
from analytic.motions.spectra import EC8_GROUND, NTC_SOIL, NTC_TOPOGRAPHY, ec8, ntc2018, read_spectrum, rebuild
from foundation.errors import ArchdemInputError
from foundation.io import parse_grid, writable_file
from specimens.constants import G

if TYPE_CHECKING:  # the run specs, for type checkers (importing run.py loads what `archdem --help` must not)
    from dem.experiments.assessment.run import AssessSpec, MonumentSpec

CODES = ("ntc2018", "ec8")
_BOND = BondFactors().describe()


def _default(obj: Any, name: str) -> Any:
    """The default of parameter or field ``name`` of ``obj`` (a function or a dataclass)."""
    if isinstance(obj, type):
        return next(f.default for f in fields(obj) if f.name == name)
    return inspect.signature(obj).parameters[name].default


def _opt(default: Any, help: str, unit: str = "", **meta: Any) -> Any:
    """A field that is an option: ``help`` and ``unit`` for its help text, and argparse's ``choices``,
    ``metavar``, ``nargs`` or ``shown`` (the library default the help shows when the field's is None)."""
    return field(default=default, metadata={"help": help, "unit": unit, **meta})


def _bond_opt(factor: str, scale: float, metavar: str, what: str) -> Any:
    """A bond factor of CNR-DT 200 R1/2013 §5.3 in the option's unit (``scale`` to SI)."""
    d = _BOND[factor]
    return _opt(None, f"CNR-DT 200 R1/2013 bond factor: {what}; strips designed on a --masonry, and noh-gumbad's; "
                "its default is UNVERIFIED against the guideline: set it from your copy", "", metavar=metavar,
                factor=factor, scale=scale, shown=f"{d['value']:g}{'' if d['unit'] == '-' else ' ' + d['unit']}")


def _numbers(text: str, counts: tuple[int, ...]) -> list[float] | None:
    """``A,B,C`` as finite numbers, or None when not ``counts`` of them."""
    try:
        vals = [float(x) for x in text.split(",")]
    except ValueError:
        return None
    return vals if len(vals) in counts and all(math.isfinite(v) for v in vals) else None


@dataclass(frozen=True)
class AssessOptions:
    """What ``archdem assess`` takes besides the structure: the site's spectrum, the limit state, the
    mechanism's height, FRP strips and a tie, records and a report, in the options' units. It checks
    itself in one line per refusal (naming the option typed); ``given``: the options set by hand (an
    option that does nothing here is refused when given, even at its default); ``monument``: the
    built-in monument assessed (:mod:`specimens.monuments`), None for an arch."""

    spectrum: str | None = _opt(None, "the code's elastic spectrum, or a file of period [s] and Se [g] at 5 % damping "
                                "(a monument such as noh-gumbad: its site's by default)", metavar="ntc2018|ec8|FILE")
    ag: float | None = _opt(None, "peak ground acceleration on rock (NTC: of the return period)", "g")
    F0: float | None = _opt(None, "NTC 2018: the site's plateau amplification F0")
    Tc_star: float | None = _opt(None, "NTC 2018: the site's Tc*", "s")
    soil: str = _opt(_default(ntc2018, "soil"), f"soil category (NTC) or ground type (EC8), {'/'.join(EC8_GROUND[1])}",
                     choices=list(NTC_SOIL) + [s.lower() for s in NTC_SOIL])
    topography: str = _opt(_default(ntc2018, "topography"), "NTC 2018 topographic category",
                           choices=list(NTC_TOPOGRAPHY))
    type: int | None = _opt(None, "EN 1998-1 spectrum type", choices=(1, 2), shown="1")
    damping: float = _opt(_default(ntc2018, "damping"), "damping ratio of the site spectrum", "%")
    limit_state: str = _opt(_default(assess, "limit_state"), "the limit state whose hazard the spectrum is: SLD "
                            "(activation check, no q), SLV (linear and displacement checks) or SLC (displacement check)",
                            choices=("SLD", "SLV", "SLC", "sld", "slv", "slc"))
    sld_ag: float | None = _opt(None, "the SLD hazard's ag (same site): adds the activation check (no q) beside SLV "
                                "or SLC (any arch, and noh-gumbad)", "g")
    sld_F0: float | None = _opt(None, "NTC 2018: F0 of the SLD hazard", shown="the spectrum's")
    sld_Tc_star: float | None = _opt(None, "NTC 2018: Tc* of the SLD hazard", "s", shown="the spectrum's")
    FC: float = _opt(_default(assess, "FC"), "confidence factor of the knowledge level (" + ", ".join(
        f"{k} {v:g}" for k, v in CONFIDENCE_FACTORS.items()) + ")")
    q: float = _opt(_default(assess, "q"), "behaviour factor of the linear check")
    z_ratio: float | None = _opt(None, "mechanism at a height: z/H in the building (0, 1]")
    T1: float | None = _opt(None, "mechanism at a height: the building's first period", "s")
    floors: int | None = _opt(None, "mechanism at a height: the building's number of floors")
    building_damping: float = _opt(_default(Height, "damping1"), "mechanism at a height: the building's first-mode "
                                   "damping", "%")
    frp: str | None = _opt(None, "FRP strips along the ring: characteristic strength, equivalent thickness, total "
                           "width, and a design strength of your own (default: the guideline's rupture eta_a f_fk / "
                           "gamma_f, and with --masonry the least of it and the debonding strengths)",
                           metavar="STRENGTH_MPA,THICKNESS_MM,WIDTH_MM[,DESIGN_MPA]")
    frp_modulus: float | None = _opt(None, "the strips' modulus E_f", "GPa", metavar="GPA")
    frp_fibre: str = _opt(_default(Strips, "fibre"), "fibre", choices=sorted(ETA_A["internal"]))
    frp_exposure: str = _opt(_default(Strips, "exposure"), "exposure of the environmental factor eta_a",
                             choices=list(ETA_A))
    frp_application: str = _opt(_default(Strips, "application"), "application type of the partial factors "
                                f"(A: gamma_f {GAMMA_F['A']:g}, gamma_fd {GAMMA_FD['A']:g}; B: {GAMMA_F['B']:g}, "
                                f"{GAMMA_FD['B']:g})", choices=list(GAMMA_F))
    masonry: str | None = _opt(None, f"the substrate's mean compressive and tensile strengths, or a type "
                               f"({', '.join(MASONRY_TYPES)}): the strips' debonding strengths",
                               metavar="FM_MPA,FMT_MPA|TYPE")
    frp_kG: float | None = _bond_opt("k_G", 1e-3, "MM", "k_G, correction factor of the fracture energy, end debonding")
    frp_kG2: float | None = _bond_opt("k_G2", 1e-3, "MM", "k_G2, correction factor of the fracture energy, "
                                      "intermediate debonding")
    frp_su: float | None = _bond_opt("s_u", 1e-3, "MM", "s_u, ultimate slip of the bond law (f_bd = 2 Gamma_Fd / s_u)")
    frp_gamma_rd: float | None = _bond_opt("gamma_Rd", 1.0, "FACTOR", "gamma_Rd, model factor of the optimal bond "
                                           "length")
    frp_led_min: float | None = _bond_opt("l_ed_min", 1e-3, "MM", "the least optimal bond length l_ed")
    frp_fmt_ratio: float | None = _bond_opt("fmt_ratio", 1.0, "RATIO", "f_mtm / f_mm, the masonry's tensile "
                                            "strength as a share of its compressive one for a named masonry type")
    frp_face: str = _opt(_default(Strips, "face"), "the ring face the strips are bonded to",
                         choices=("extrados", "intrados"))
    tie: str | None = _opt(None, "a steel tie across the structure at a height above the springing line (0: the "
                           "springings or the pier tops; negative: in the piers), of cross-section area and yield "
                           "strength; rigid-plastic in the analyses (the prestress is recorded); with noh-gumbad a row "
                           "per configuration with the tie alone", metavar="HEIGHT_M,AREA_MM2,FY_MPA[,PRESTRESS_KN]")
    records: tuple[str, ...] | None = _opt(None, "records (.AT2, .smc, ESM, CSV) matched to the site spectrum and "
                                           "shaken on the DEM (an arch, not noh-gumbad)", metavar="FILE", nargs="+")
    match_periods: str | None = _opt(None, "period range of the records' match", "s", metavar="LO,HI",
                                     shown="0.2-2 x the limit state's period")
    report: str | None = _opt(None, "write the assessment with its figures: FILE.html one page, FILE.pdf a printable "
                              "report (title block, inputs, site, each step, verdicts, figures) (never overwrites)",
                              metavar="FILE.html|FILE.pdf")
    project: str | None = _opt(None, "--report FILE.pdf: the project named in the title block", shown="-")
    engineer: str | None = _opt(None, "--report FILE.pdf: the engineer named in the title block", shown="-")
    given: frozenset[str] = frozenset()
    monument: Any = None

    def __post_init__(self) -> None:
        self._unused("q", self.limit_state.upper() == "SLV", "it is the behaviour factor of the linear check, "
                                                             "which only --limit-state SLV has")
        for name in ("frp_fibre", "frp_exposure", "frp_application"):
            self._unused(name, self.frp is not None, "it designs the --frp strips")
        # built once here, in the order the command has always refused them
        order = ("tie_rod", "sld_site", "strips") if self.monument is not None else ("strips", "tie_rod", "sld_site")
        for name in ("site", "height", *order):
            getattr(self, name)
        self._check_report()
        if self.monument is None:
            self._unused("match_periods", bool(self.records), "it belongs to --records")

    def _unused(self, name: str, used: bool, why: str) -> None:
        """Refuse option ``name`` given (by hand, or away from its default) where it is not ``used``."""
        if not used and (name in self.given or getattr(self, name) != _default(AssessOptions, name)):
            raise ArchdemInputError(f"--{name.replace('_', '-')} does nothing here: {why}")

    @cached_property
    def site(self):
        """The site's elastic spectrum (a monument's own without ``--spectrum``)."""
        if self.spectrum is None and self.monument is not None:
            return monument_site()
        if self.spectrum is None:
            raise ArchdemInputError("--spectrum ntc2018|ec8|FILE is needed (the site's elastic spectrum)")
        if self.spectrum not in CODES:
            if self.ag is not None or self.F0 is not None or self.Tc_star is not None or self.type is not None:
                raise ArchdemInputError("a spectrum file gives the whole spectrum: --ag, --F0, --Tc-star and --type "
                                        "belong to the codes' spectra")
            return read_spectrum(self.spectrum)
        if self.ag is None:
            raise ArchdemInputError("--ag (peak ground acceleration on rock, in g) is needed")
        if not (math.isfinite(self.ag) and 0 < self.ag <= 3):
            raise ArchdemInputError(f"--ag must be in (0, 3] g, got {self.ag:g}")
        if self.spectrum == "ntc2018":
            if self.F0 is None or self.Tc_star is None:
                raise ArchdemInputError("the NTC 2018 spectrum needs --F0 and --Tc-star of the site")
            if self.type is not None:
                raise ArchdemInputError("--type is the EN 1998-1 spectrum type; NTC 2018 takes --F0 and --Tc-star")
            return ntc2018(self.ag * G, self.F0, self.Tc_star, self.soil, self.topography, self.damping)
        if self.F0 is not None or self.Tc_star is not None or self.topography != _default(ntc2018, "topography"):
            raise ArchdemInputError("--F0, --Tc-star and --topography belong to the NTC 2018 spectrum")
        return ec8(self.ag * G, self.soil, self.type or 1, self.damping)

    @cached_property
    def height(self) -> Height | None:
        """The mechanism's height in a building, or None at ground level."""
        given = [self.z_ratio, self.T1, self.floors]
        if all(v is None for v in given):
            if self.building_damping != _default(Height, "damping1"):
                raise ArchdemInputError("--building-damping belongs to a mechanism at a height (--z-ratio, --T1, "
                                        "--floors)")
            return None
        if any(v is None for v in given):
            raise ArchdemInputError("a mechanism at a height needs --z-ratio, --T1 and --floors together")
        return Height(self.z_ratio, self.T1, self.floors, self.building_damping)

    @cached_property
    def tie_rod(self) -> Tie | None:
        """``--tie HEIGHT_M,AREA_MM2,FY_MPA[,PRESTRESS_KN]`` in SI."""
        if self.tie is None:
            return None
        vals = _numbers(self.tie, (3, 4))
        if vals is None:
            raise ArchdemInputError(f"--tie takes HEIGHT_M,AREA_MM2,FY_MPA[,PRESTRESS_KN], got {self.tie!r}")
        return Tie(vals[0], vals[1] * 1e-6, vals[2] * 1e6, vals[3] * 1e3 if len(vals) == 4 else 0.0)

    @cached_property
    def sld_site(self):
        """The SLD hazard: the same site's spectrum at ``--sld-ag`` (and for NTC 2018 its ``--sld-F0``,
        ``--sld-Tc-star``), or None."""
        site = self.site
        if self.sld_ag is None:
            if self.sld_F0 is not None or self.sld_Tc_star is not None:
                raise ArchdemInputError("--sld-F0 and --sld-Tc-star belong to --sld-ag")
            return None
        if self.limit_state.upper() == "SLD":
            raise ArchdemInputError("--sld-ag is the SLD hazard beside a life-safety one; with --limit-state SLD the "
                                    "spectrum itself is the SLD hazard")
        if not (math.isfinite(self.sld_ag) and 0 < self.sld_ag * G <= site.ag):
            raise ArchdemInputError(f"--sld-ag must be in (0, the spectrum's ag = {site.ag / G:.3g}] g, got "
                                    f"{self.sld_ag:g}")
        if self.sld_F0 is not None or self.sld_Tc_star is not None:
            if site.describe().get("code") != "NTC 2018":
                raise ArchdemInputError("--sld-F0 and --sld-Tc-star belong to the NTC 2018 spectrum")
            p = site.params
            return ntc2018(self.sld_ag * G, self.sld_F0 if self.sld_F0 is not None else p["F0"],
                           self.sld_Tc_star if self.sld_Tc_star is not None else p["Tc_star"], p["soil"],
                           p["topography"], p["damping"])
        return rebuild(site, ag=self.sld_ag * G)

    def _bond(self, debonding: bool, named_masonry: bool, why: str) -> BondFactors:
        """The bond factors given (the unverified defaults otherwise), each refused where no debonding is
        designed (``why`` says what they belong to), the tensile ratio where ``--masonry`` gives f_mtm."""
        bond = [f for f in fields(self) if "factor" in f.metadata]
        for f in bond:
            self._unused(f.name, debonding, why)
        self._unused("frp_fmt_ratio", named_masonry, "--masonry FM_MPA,FMT_MPA gives the tensile strength; the "
                                                     "ratio belongs to a named masonry type")
        return BondFactors.given(**{f.metadata["factor"]: getattr(self, f.name) * f.metadata["scale"] for f in bond
                                    if getattr(self, f.name) is not None})

    def _masonry(self, bond: BondFactors) -> Masonry | None:
        """``--masonry FM_MPA,FMT_MPA`` or a named type (by the knowledge level ``--FC``, its tensile
        strength by ``bond``'s ratio)."""
        if self.masonry is None:
            return None
        if self.masonry in MASONRY_TYPES:
            return masonry_type(self.masonry, self.FC, bond)
        vals = _numbers(self.masonry, (2,))
        if vals is None:
            raise ArchdemInputError(f"--masonry takes FM_MPA,FMT_MPA or one of {', '.join(MASONRY_TYPES)}, "
                                    f"got {self.masonry!r}")
        return Masonry(vals[0] * 1e6, vals[1] * 1e6, "given")

    @cached_property
    def strips(self) -> Strips | None:
        """The ``--frp`` strips designed by the other FRP options (a monument's own without ``--frp``)."""
        named = self.masonry is None or self.masonry in MASONRY_TYPES
        if self.frp is None and self.monument is not None:
            if self.frp_modulus is not None:
                raise ArchdemInputError(f"{self.monument.name}'s strips are described by the study (E_f assumed): "
                                        f"--frp-modulus belongs to --frp")
            bond = self._bond(True, named, "")
            return monument_strips(self.FC, self.frp_face, self._masonry(bond), bond)
        if self.frp is None:
            self._unused("frp_face", False, "it places the --frp strips")
            self._bond(False, False, "it sets a bond factor of the --frp strips' debonding (with --masonry)")
            if self.masonry is not None or self.frp_modulus is not None:
                raise ArchdemInputError("--masonry and --frp-modulus belong to --frp (the strips they design)")
            return None
        vals = _numbers(self.frp, (3, 4))
        if vals is None:
            raise ArchdemInputError(f"--frp takes STRENGTH_MPA,THICKNESS_MM,WIDTH_MM[,DESIGN_MPA], got {self.frp!r}")
        bond = self._bond(self.masonry is not None, self.masonry in MASONRY_TYPES,
                          "the bond factors design debonding from the --masonry; without it the strips are designed "
                          "for rupture only")
        masonry = self._masonry(bond)
        if self.frp_modulus is not None and not (math.isfinite(self.frp_modulus) and self.frp_modulus > 0):
            raise ArchdemInputError(f"--frp-modulus must be a positive number of GPa, got {self.frp_modulus:g}")
        if masonry is not None and self.frp_modulus is None:
            raise ArchdemInputError("--masonry needs --frp-modulus (the strips' E_f: debonding depends on it)")
        return Strips(vals[0] * 1e6, vals[1] * 1e-3, vals[2] * 1e-3, self.frp_face,
                      vals[3] * 1e6 if len(vals) == 4 else None,
                      modulus=None if self.frp_modulus is None else self.frp_modulus * 1e9, fibre=self.frp_fibre,
                      exposure=self.frp_exposure, application=self.frp_application, masonry=masonry, FC=self.FC,
                      bond=bond)

    @property
    def period_range(self) -> tuple[float, float] | None:
        """``--match-periods LO,HI`` [s], or None (the library's default range)."""
        if self.match_periods is None:
            return None
        rng = parse_grid(self.match_periods, "--match-periods")
        if len(rng) != 2:
            raise ArchdemInputError(f"--match-periods takes LO,HI in s, got {self.match_periods!r}")
        return rng[0], rng[1]

    def _check_report(self) -> None:
        """A ``--report`` neither HTML nor PDF or that would overwrite a file, and a title-block option
        without a PDF report, refused."""
        if self.report is not None:
            if not self.report.lower().endswith((".html", ".pdf")):
                raise ArchdemInputError(f"--report must end in .html or .pdf, got {self.report!r}")
            writable_file(self.report, overwrite=False)
        for name in ("project", "engineer"):
            self._unused(name, (self.report or "").lower().endswith(".pdf"),
                         "it goes in the title block of a --report FILE.pdf")

    def run_spec(self, arch: Any = None, label: str | None = None, settings: Any = None, workers: int | None = None,
                 **blocks: Any) -> AssessSpec | MonumentSpec:
        """What :func:`dem.experiments.assessment.run.run` assesses: the monument in every configuration, or
        ``arch`` (named ``label``) with its records run with ``settings`` in ``workers`` processes, its
        blocks by ``blocks`` (:func:`specimens.blocks.discretise` keywords)."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.assessment.run import AssessSpec, MonumentSpec

        if self.monument is not None:
            return MonumentSpec(self.monument, self.strips, self.site, self.FC, self.q, self.limit_state, self.height,
                                self.tie_rod, self.sld_site)
        return AssessSpec(arch, self.site, tuple(self.records or ()), FC=self.FC, q=self.q,
                          limit_state=self.limit_state, height=self.height, period_range=self.period_range,
                          settings=settings, workers=workers, strips=self.strips, tie=self.tie_rod,
                          sld_site=self.sld_site, label=label, **blocks)
