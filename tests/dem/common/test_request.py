"""The structure asked for, checked once for a command and a Python caller alike (dem/common/request.py)."""
from __future__ import annotations

import argparse
import dataclasses

import pytest

from dem.common.request import MAX_PIER_LOAD_KN, PLANE_DEPTH_M, ArchRequest, density_text
from foundation.errors import ArchdemInputError
from specimens.drawn import DrawnAssembly
from specimens.exchange import EXAMPLE_DRAWING
from specimens.geometry import PointedArch
from specimens.piers import Piers

PIERS = {"pier_height": 0.2, "pier_width": 0.1, "pier_courses": 2, "pier_load": 1.0}


def _parsed(argv: list[str]) -> argparse.Namespace:
    from dem.cli import build_parser

    return build_parser().parse_args(argv)


def test_a_python_callers_bad_pier_load_is_refused_as_on_the_command_line():
    with pytest.raises(ArchdemInputError) as exc:
        ArchRequest(id="Sh02-Sd020", pier_height=0.2, pier_width=0.1, pier_load=2 * MAX_PIER_LOAD_KN)
    assert str(exc.value) == f"--pier-load must be a force between 0 and {MAX_PIER_LOAD_KN:g} kN, got 2e+06"


def test_the_command_line_and_a_python_caller_ask_for_the_same_arch_under_the_same_label():
    from dem.common.options import arch_request

    args = _parsed(["analytic", "Sh02-Sd020", "--pier-height", "0.2", "--pier-width", "0.1", "--pier-courses", "2",
                    "--pier-load", "1"])
    cli = arch_request(args)
    mine = ArchRequest(id="Sh02-Sd020", **PIERS)
    assert cli == mine
    label, arch = mine.structure()
    assert label == cli.structure()[0] == "Sh02-Sd020-piers-H0.2-B0.1-N2-P1kN"
    assert isinstance(arch, PointedArch) and mine.piers == Piers(0.2, 0.1, None, 0.0, 2, 1e3)
    assert mine.discretise_kwargs(arch) == {"piers": mine.piers}


def test_an_arch_by_its_ratios_is_labelled_by_them():
    label, arch = ArchRequest(Sh=0.2, Sd=0.2, Rc=1.0, width=0.3, voussoirs=6, density=2000).structure()
    assert label == "Sh0.2-Sd0.2-Rc1" and arch.width == 0.3
    assert ArchRequest(Sh=0.2, Sd=0.2, Rc=1.0, voussoirs=6, density=2000).discretise_kwargs(arch) == {
        "n_voussoirs": 6, "density": 2000}


@pytest.mark.parametrize("kw, msg", [
    (dict(id="Sh02-Sd020", Ri=1.0), "give either a specimen id or --Ri/--Re/--e or --Sh/--Sd/--Rc, not both"),
    (dict(Ri=1.0, Re=1.2), "give a specimen id, or all of --Ri --Re --e"),
    (dict(Ri=1.0, Re=1.2, e=0.1, Sh=0.2), "give a specimen id, or all of --Ri --Re --e"),
    (dict(Ri=1.0, Re=1.0 + 1e-9, e=0.1), "ring thickness"),
    (dict(id="Sh02-Sd020", width=-1.0), "--width must be a length between"),
    (dict(id="Sh02-Sd020", voussoirs=0), "--voussoirs must be 1 to 100"),
    (dict(id="Sh02-Sd020", voussoirs=2.5), "--voussoirs must be 1 to 100"),
    (dict(id="Sh02-Sd020", density=0.0), "--density must be between"),
    (dict(id="Sh02-Sd020", contact=1.5), "effective contact must be a fraction"),
    (dict(id="Sh02-Sd020", contact="calibrate"), "--contact must be a fraction in (0, 1] or 'calibrated'"),
    (dict(id="Sh02-Sd020", pier_height=0.2), "piers need both --pier-height and --pier-width"),
    (dict(id="Sh02-Sd020", pier_height=0.2, pier_width=0.1, pier_courses=0), "pier courses must be a whole number"),
    (dict(id="Sh02-Sd020", block=(0.05, 0.2)), "give either --block B H or an arch, not both"),
    (dict(geometry="x.dxf", id="Sh02-Sd020"), "--geometry gives the whole structure: drop the specimen id"),
    (dict(geometry="x.dxf", pier_height=0.2, pier_width=0.1), "drop --pier-height"),
    (dict(geometry="x.dxf", depth=-1.0), "--depth must be a length"),
    (dict(geometry="x.dxf", units="parsec"), "--units must be one of"),
    (dict(id="no-such-arch"), "unknown specimen"),
])
def test_a_bad_request_is_refused_on_construction_in_one_line(kw, msg):
    with pytest.raises(ArchdemInputError) as exc:
        ArchRequest(**kw)
    assert msg in str(exc.value) and "\n" not in str(exc.value)


def test_the_piers_are_checked_against_the_arch_they_carry():
    req = ArchRequest(id="Sh02-Sd020", pier_height=0.2, pier_width=0.001)
    _, arch = req.structure()
    with pytest.raises(ArchdemInputError, match="narrower than the ring's springing"):
        req.discretise_kwargs(arch)


def test_a_block_or_an_arch_or_a_one_line_request_for_one():
    assert ArchRequest(block=[0.05, 0.2]).rectangular_block() == (0.05, 0.2)
    assert ArchRequest(id="Sh02-Sd020").rectangular_block() is None
    with pytest.raises(ArchdemInputError, match="give a specimen id, the arch parameters or --block B H"):
        ArchRequest().rectangular_block()
    with pytest.raises(ArchdemInputError, match="give a specimen id, or all of"):
        ArchRequest(block=(0.05, 0.2)).structure()


def test_a_drawing_is_read_as_drawn_with_its_density_and_where_it_came_from():
    label, drawn = ArchRequest(geometry=EXAMPLE_DRAWING, density=1800).structure()
    assert label == EXAMPLE_DRAWING.stem and isinstance(drawn, DrawnAssembly)
    assert density_text(drawn) == "density 1800 kg/m^3 (--density)"
    assert PLANE_DEPTH_M == 1.0


def test_from_namespace_reads_what_a_command_has_and_leaves_a_records_units():
    req = ArchRequest.from_namespace(argparse.Namespace(id="Sh02-Sd020", units="g", contact="calibrated"))
    assert req == ArchRequest(id="Sh02-Sd020", contact="calibrated")
    with pytest.raises(dataclasses.FrozenInstanceError):
        req.id = "Sh06-Sd015"  # type: ignore[misc]
