"""The options of ``archdem assess`` as one spec: the parser's options come from its fields, and the spec
checks itself (as a library object too) and builds the assessment's inputs."""
import argparse
from dataclasses import dataclass, field

import pytest

from analytic.codes.frp import BondFactors, Strips
from analytic.motions.spectra import ec8
from dem.experiments.assessment.spec import AssessOptions
from dem.experiments.contract import add_spec_options, spec_from_args, spec_options
from foundation.errors import ArchdemInputError
from specimens.constants import G

EC8 = {"spectrum": "ec8", "ag": 0.2}


def _assess_parser() -> argparse.ArgumentParser:
    from dem.cli import build_parser

    p = build_parser()
    return next(a for a in p._actions if isinstance(a, argparse._SubParsersAction)).choices["assess"]


def test_every_field_is_an_option_of_assess_with_the_fields_default():
    actions = {a.dest: a for a in _assess_parser()._actions}
    names = [f.name for f in spec_options(AssessOptions)]
    assert "given" not in names and "monument" not in names and len(names) == 37
    for f in spec_options(AssessOptions):
        a = actions[f.name]
        assert a.option_strings == ["--" + f.name.replace("_", "-")] and a.default == f.default, f.name
    assert actions["Tc_star"].option_strings == ["--Tc-star"] and actions["floors"].type is int
    assert actions["records"].nargs == "+" and actions["type"].choices == (1, 2)
    # the help shows the library's default, and the unit
    assert actions["damping"].help.endswith("[%%] (default 5)") and actions["FC"].help.endswith("(default 1.35)")
    assert f"(default {BondFactors().k_G * 1e3:g} mm)" in actions["frp_kG"].help


def test_the_spec_checks_itself_as_a_library_object():
    with pytest.raises(ArchdemInputError, match=r"--ag must be in \(0, 3\] g, got 0"):
        AssessOptions(spectrum="ec8", ag=0.0)
    with pytest.raises(ArchdemInputError, match="--spectrum ntc2018|ec8|FILE is needed"):
        AssessOptions()
    # an option that does nothing here: refused away from its default, or given by hand at it
    with pytest.raises(ArchdemInputError, match="--q does nothing here"):
        AssessOptions(**EC8, limit_state="SLD", q=3.0)
    with pytest.raises(ArchdemInputError, match="--q does nothing here"):
        AssessOptions(**EC8, limit_state="SLD", given=frozenset({"q"}))
    assert AssessOptions(**EC8, limit_state="SLD").q == 2.0
    with pytest.raises(ArchdemInputError, match="--frp-kG does nothing here"):
        AssessOptions(**EC8, frp="2000,0.05,50", frp_kG=0.05)
    with pytest.raises(ArchdemInputError, match="--match-periods does nothing here"):
        AssessOptions(**EC8, match_periods="0.1,1")


def test_the_spec_builds_the_assessments_inputs_in_si():
    o = AssessOptions(**EC8, soil="B", frp="2000,0.05,50", frp_modulus=230.0, masonry="3,0.3", frp_kG=0.062,
                      tie="0.05,100,235,1", sld_ag=0.1, match_periods="0.2,1.5", records=("r.AT2",))
    assert o.site.ag == pytest.approx(ec8(0.2 * G, "B").ag) and o.sld_site.ag == pytest.approx(0.1 * G)
    s = o.strips
    assert isinstance(s, Strips) and s.modulus == pytest.approx(230e9) and s.thickness == pytest.approx(0.05e-3)
    assert s.bond.k_G == pytest.approx(0.062e-3) and s.masonry.fm == pytest.approx(3e6)
    assert (o.tie_rod.area, o.tie_rod.prestress) == (pytest.approx(100e-6), pytest.approx(1e3))
    assert o.period_range == (0.2, 1.5) and o.height is None
    spec = o.run_spec("ARCH", "label", workers=2, density=900.0)
    assert (spec.target, spec.label, spec.records, spec.workers, spec.density) == ("ARCH", "label", ("r.AT2",), 2, 900.0)
    assert spec.strips is s and spec.tie is o.tie_rod and spec.period_range == (0.2, 1.5)


def test_a_monuments_spec_takes_its_own_site_and_strips():
    from analytic.codes.assessment import monument_site
    from specimens.monuments import NOH_GUMBAD

    spec = AssessOptions(monument=NOH_GUMBAD, FC=1.0).run_spec()
    assert spec.monument is NOH_GUMBAD and spec.site.ag == pytest.approx(monument_site().ag) and spec.FC == 1.0
    assert spec.strips.masonry is not None  # the study's strips, designed for debonding
    with pytest.raises(ArchdemInputError, match="--frp-modulus belongs to --frp"):
        AssessOptions(monument=NOH_GUMBAD, frp_modulus=200.0)


@dataclass(frozen=True)
class _Toy:
    n: int | None = field(default=None, metadata={"help": "a count"})
    mode: str = field(default="a", metadata={"help": "a mode", "choices": ("a", "b")})
    length: float = field(default=2.0, metadata={"help": "a length", "unit": "m"})
    files: tuple[str, ...] | None = field(default=None, metadata={"help": "files", "nargs": "+"})
    fast: bool = field(default=False, metadata={"help": "go fast"})
    given: frozenset = frozenset()


def test_the_generic_options_of_any_spec():
    p = argparse.ArgumentParser()
    add_spec_options(p, _Toy)
    args = p.parse_args(["--n", "3", "--files", "x", "y", "--fast"])
    assert spec_from_args(_Toy, args) == _Toy(3, "a", 2.0, ("x", "y"), True)
    args.given = ["n", "files", "fast", "json"]  # what archdem records; only the spec's own are kept
    assert spec_from_args(_Toy, args).given == frozenset({"n", "files", "fast"})
    helps = {a.dest: a.help for a in p._actions}
    assert (helps["length"], helps["mode"], helps["n"]) == ("a length [m] (default 2)", "a mode (default a)", "a count")
    with pytest.raises(SystemExit):
        p.parse_args(["--mode", "c"])
