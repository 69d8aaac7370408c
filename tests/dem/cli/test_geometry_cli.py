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
    (["analytic", "--geometry", str(EXAMPLE_DRAWING), "--effective-thickness", "0.8"],
     "--effective-thickness does nothing here: it belongs to the continuous ring"),
    (["analytic", "--geometry", str(EXAMPLE_DRAWING), "--contact", "calibrated"], "not a two-centred arch"),
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


def _ring_dxf(path, gap_mm=0.0, n=8, ri=1000.0, re=1250.0):
    """A semicircular ring of n voussoirs (B1..Bn, mm, 300 mm deep) on the ground; its right half moved
    ``gap_mm`` to the right: a joint drawn open at the crown."""
    doc = ezdxf.new(units=4)
    for k in range(n):
        a0, a1 = math.pi * (1 - k / n), math.pi * (1 - (k + 1) / n)
        dx = gap_mm if k >= n // 2 else 0.0
        q = [(r * math.cos(a) + dx, r * math.sin(a)) for r, a in ((ri, a0), (ri, a1), (re, a1), (re, a0))]
        doc.modelspace().add_lwpolyline(q, format="xy", close=True, dxfattribs={"layer": "ring depth 300"})
    doc.saveas(str(path))
    return str(path)


GAP_LINE = ("gap cannot stand under its own weight (no equilibrium even without sliding): blocks B4 and B5 are "
            "5.0 mm apart (no joint between them); its blocks stand in 2 parts that no joint joins: "
            "B1, B2, B3, B4 | B5, B6, B7, B8")


@pytest.mark.parametrize("command", [["analytic"], ["analytic", "--json"], ["tilt"],
                                     ["shake", "--sine", "4", "--amplitude", "0.3"],
                                     ["fragility", "--sine", "4", "--amplitudes", "0.1,0.2", "--realizations", "2"]])
def test_a_5_mm_gap_between_voussoirs_is_named_in_one_line_exit_2(tmp_path, capsys, command):
    """Read, the drawing stands on the ground at both feet, but no joint closes the crown: every command that
    needs it to stand refuses it naming the gap and the two halves, and writes nothing."""
    path = _ring_dxf(tmp_path / "gap.dxf", 5.0)
    out = tmp_path / "out"
    extra = [] if command[0] == "analytic" else ["--out", str(out / "f.h5") if command[0] == "fragility" else str(out)]
    assert main([command[0], "--geometry", path, *command[1:], *extra]) == 2
    cap = capsys.readouterr()
    assert cap.err == f"archdem: error: {GAP_LINE}\n" and cap.out == ""
    assert not out.exists()


def test_a_gap_is_shown_where_the_drawing_stands_and_drawn(tmp_path, capsys):
    """Two piers 200 x 800 mm 5 mm apart: each stands alone, so the analyses run and say the gap."""
    doc = ezdxf.new(units=4)
    for q in ([(0, 0), (200, 0), (200, 800), (0, 800)], [(205, 0), (405, 0), (405, 800), (205, 800)]):
        doc.modelspace().add_lwpolyline(q, format="xy", close=True, dxfattribs={"layer": "piers depth 200"})
    doc.saveas(str(tmp_path / "piers.dxf"))
    argv = ["--geometry", str(tmp_path / "piers.dxf")]
    d = _json(capsys, ["analytic", *argv, "--json"])
    assert [g["text"] for g in d["gaps"]] == ["blocks B1 and B2 are 5.0 mm apart"] and d["lambda_lp"] == pytest.approx(0.25)
    assert main(["analytic", *argv]) == 0
    assert "gaps (no joint between them): blocks B1 and B2 are 5.0 mm apart" in capsys.readouterr().out
    assert main(["draw", *argv, "--out", str(tmp_path / "p.png")]) == 0
    assert "gaps (no joint between them): blocks B1 and B2 are 5.0 mm apart" in capsys.readouterr().out
    # the check every capacity test makes first: it stands, and says so on stderr in one line
    from dem.common.request import require_standing

    require_standing("piers", read_assembly(tmp_path / "piers.dxf"))
    err = capsys.readouterr().err
    assert err == ("archdem: warning: piers: blocks B1 and B2 are 5.0 mm apart (no joint between them; it stands "
                   "without one)\n")


BLOCK = [(0, 0), (200, 0), (200, 800), (0, 800)]


@pytest.mark.slow
def test_a_drawn_structure_carries_no_glued_or_free_label(tmp_path, capsys):
    """Text, JSON, result file names and the HDF5 file say "drawn"; --config beside --geometry is refused."""
    import h5py

    p = _bad_dxf(tmp_path / "block.dxf", [[(x / 1000, y / 1000) for x, y in BLOCK]], layer="block depth 0.1")
    out = tmp_path / "runs"
    assert main(["tilt", "--geometry", p, "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert text.startswith("block (drawn, mu 0.577/1") and "glued" not in text
    d = _json(capsys, ["tilt", "--geometry", p, "--out", str(out), "--json"])
    assert d["config"] == "drawn" and "glued" not in json.dumps(d)
    assert main(["shake", "--geometry", p, "--sine", "4", "--amplitude", "0.1", "--out", str(out)]) == 0
    assert "(drawn, mu" in capsys.readouterr().out
    files = sorted(f.name for f in out.iterdir())
    assert files == ["shake-block-drawn-sine4Hz-0.1g.h5", "tilt-block-drawn-2.h5", "tilt-block-drawn.h5"]
    for f in out.iterdir():
        with h5py.File(f) as h:
            attrs = [str(v) for _, obj in h.items() for v in obj.attrs.values()] + [str(v) for v in h.attrs.values()]
        assert not any("glued" in a for a in attrs) and any('"config": "drawn"' in a for a in attrs)


@pytest.mark.parametrize("command", [["analytic"], ["tilt"], ["shake", "--sine", "4", "--amplitude", "0.1"], ["draw"],
                                     ["mesh"], ["modes", "--kn", "1e9"], ["map", "--mu", "0.3,1.0"]])
def test_config_beside_geometry_is_refused_in_one_line(tmp_path, capsys, command):
    out = {"draw": ["--out", str(tmp_path / "d.png")], "mesh": ["--out", str(tmp_path / "m")],
           "map": ["--out", str(tmp_path / "m.h5")], "tilt": ["--out", str(tmp_path / "t")],
           "shake": ["--out", str(tmp_path / "s")]}.get(command[0], [])
    assert main([command[0], "--geometry", str(EXAMPLE_DRAWING), *command[1:], "--config", "glued", *out]) == 2
    err = capsys.readouterr().err
    assert "--config does nothing here: a drawing's blocks are as drawn" in err and err.count("\n") == 1
    assert not any(tmp_path.iterdir())


def test_draw_takes_a_plane_drawing_without_a_depth(tmp_path, capsys):
    """The drawing needs no depth (the figure's masses are then per metre of depth); the analyses still ask."""
    p = _bad_dxf(tmp_path / "block.dxf", [[(x / 1000, y / 1000) for x, y in BLOCK]])
    assert main(["draw", "--geometry", p, "--out", str(tmp_path / "d.png")]) == 0
    out = capsys.readouterr().out
    assert out.startswith(f"drawing written to {tmp_path / 'd.png'}; density 2000 kg/m^3 (archdem's default")
    assert main(["tilt", "--geometry", p, "--out", str(tmp_path / "t")]) == 2
    assert "block B1 has no depth" in capsys.readouterr().err
