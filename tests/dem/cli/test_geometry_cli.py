"""``--geometry``: a drawn structure on the commands; bad drawings give one line, exit 2, nothing written."""
import json
import math

import ezdxf
import pytest

from analytic.limit.limit_discrete import solve_lp
from dem.cli import main
from specimens import discretise, get_specimen, read_assembly, write_assembly
from specimens.exchange import EXAMPLE_DRAWING


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_draw_shows_the_read_assembly(tmp_path, capsys):
    out = tmp_path / "d.png"
    assert main(["draw", "--geometry", str(EXAMPLE_DRAWING), "--out", str(out)]) == 0
    assert out.stat().st_size > 10_000


def test_assess_runs_on_the_drawn_example(capsys):
    d = _json(capsys, ["assess", "--geometry", str(EXAMPLE_DRAWING), "--spectrum", "ec8", "--ag", "0.25", "--json"])
    asm = read_assembly(EXAMPLE_DRAWING)
    # the governing mechanism is the drawing's own discrete one, opened by a positive ground acceleration (loads
    # along -x): the LP without sliding in that direction (the structure is not symmetric: +x differs)
    lam = solve_lp(asm, math.inf, math.inf, load_sign=-1).lam
    assert d["mechanism"]["lambda"] == pytest.approx(lam, rel=1e-7) != solve_lp(asm, math.inf, math.inf).lam
    # the activation (a0*/PGA convention) beside the code's linear and non-linear checks
    assert {c["kind"] for c in d["checks"]} == {"activation", "linear", "non-linear"}


@pytest.mark.slow
def test_tilt_runs_on_the_drawn_example(tmp_path, capsys):
    d = _json(capsys, ["tilt", "--geometry", str(EXAMPLE_DRAWING), "--json", "--out", str(tmp_path)])
    assert 0.2 < d["lambda"] < 0.3 and d["id"] == "survey-arch-on-piers"


def _bad_dxf(path, polys, layer="blocks"):
    doc = ezdxf.new(units=6)
    for q in polys:
        doc.modelspace().add_lwpolyline(q, format="xy", close=True, dxfattribs={"layer": layer})
    doc.saveas(str(path))
    return str(path)


def _open_dxf(path):
    doc = ezdxf.new(units=6)
    doc.modelspace().add_lwpolyline([(0, 0), (1, 0), (1, 1)], format="xy")
    doc.saveas(str(path))
    return str(path)


def _text(path, content):
    path.write_text(content)
    return str(path)


R = [(0, 0), (0.2, 0), (0.2, 0.4), (0, 0.4)]


@pytest.mark.parametrize("make, msg", [
    (lambda d: _bad_dxf(d / "loose.dxf", [R, [(1, 1), (1.2, 1), (1.2, 1.4), (1, 1.4)]]), "touches no other block"),
    (lambda d: _bad_dxf(d / "over.dxf", [R, [(0.1, 0.2), (0.3, 0.2), (0.3, 0.6), (0.1, 0.6)]]), "blocks overlap"),
    (lambda d: _bad_dxf(d / "zero.dxf", [R, [(0, 0.4), (0.2, 0.4), (0.1, 0.4)]]), "has zero area"),
    (lambda d: _open_dxf(d / "open.dxf"), "open polyline"),
    (lambda d: _text(d / "junk.dxf", "garbage\n"), "not a readable DXF file"),
    (lambda d: _text(d / "junk.csv", "x\n"), "the header must name the columns"),
    (lambda d: _text(d / "junk.obj", "v 1 2\n"), "a vertex needs three numbers"),
    (lambda d: str(d / "missing.dxf"), "no such file"),
])
@pytest.mark.parametrize("command", [["tilt"], ["shake", "--sine", "4", "--amplitude", "0.3"], ["draw"]])
def test_bad_drawings_give_one_line_exit_2_and_nothing_written(tmp_path, capsys, make, msg, command):
    src = tmp_path / "src"
    src.mkdir()
    path = make(src)
    out = tmp_path / "out"
    argv = [command[0], "--geometry", path, *command[1:], "--depth", "0.1", "--out",
            str(out / "d.png") if command[0] == "draw" else str(out)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert msg in err and err.count("\n") == 1
    assert not out.exists()


@pytest.mark.parametrize("argv, msg", [
    (["tilt", "Sh06-Sd015", "--geometry", "x.dxf"], "drop the specimen id"),
    (["tilt", "--geometry", "x.dxf", "--pier-height", "0.3", "--pier-width", "0.1"], "drop --pier-height"),
    (["tilt", "--geometry", "x.dxf", "--depth", "-1"], "--depth must be a length"),
    (["tilt", "--geometry", str(EXAMPLE_DRAWING), "--units", "m"], "states its units as mm, and units m were given"),
    (["tilt", "--geometry", str(EXAMPLE_DRAWING), "--contact", "calibrated"], "not a two-centred arch"),
    (["analytic", "--geometry", str(EXAMPLE_DRAWING)], "not a two-centred arch"),
])
def test_options_that_do_not_go_with_a_drawing_are_refused(tmp_path, capsys, argv, msg):
    assert main([*argv, "--out", str(tmp_path / "o")] if argv[0] == "tilt" else argv) == 2
    err = capsys.readouterr().err
    assert msg in err and err.count("\n") == 1


def test_a_catalogue_arch_drawn_and_read_by_the_cli_is_the_same_tilt_start(tmp_path, capsys):
    """The command line reads the file as Python does: the same blocks, the LP the tilt starts from."""
    p = write_assembly(discretise(get_specimen("Sh06-Sd015").arch), tmp_path / "a.csv")
    assert main(["draw", "--geometry", str(p), "--out", str(tmp_path / "a.png")]) == 0
    assert solve_lp(read_assembly(p), 0.577, 1.0).lam == solve_lp(discretise(get_specimen("Sh06-Sd015").arch), 0.577, 1.0).lam
