"""``archdem analytic --geometry``: the static LP of a drawing's blocks, its hinges (joint, face, the blocks
the joint lies between) and the LP's mu*, as text and JSON; what does not apply to a drawing is refused."""
import json
import math

import ezdxf
import pytest

from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
from dem.cli import main
from dem.experiments.friction_map.run import lp_mu_star
from specimens import discretise, get_specimen, read_assembly, write_assembly
from specimens.constants import DRAWN_DENSITY
from specimens.exchange import EXAMPLE_DRAWING


def _dxf(path, polys, layer="blocks depth 100", supports=()):
    """Rectangles and polygons in mm on a layer stating their depth; ``supports`` on the ground layer."""
    doc = ezdxf.new(units=4)
    for q in polys:
        doc.modelspace().add_lwpolyline(q, format="xy", close=True, dxfattribs={"layer": layer})
    for q in supports:
        doc.modelspace().add_lwpolyline(q, format="xy", close=True, dxfattribs={"layer": "ground"})
    doc.saveas(str(path))
    return str(path)


def _json(capsys, argv, code=0):
    assert main([*argv, "--json"]) == code
    return json.loads(capsys.readouterr().out)


def test_the_shipped_drawing_prints_its_lp_hinges_between_blocks_and_mu_star(capsys):
    """docs/validation.md#18: LP without sliding 0.2792, hinges J5 intrados (V1/V2), J10 extrados (V6/V7),
    J15 intrados (V10/V11), J23 extrados (the right pier's foot); the enumeration the same."""
    assert main(["analytic", "--geometry", str(EXAMPLE_DRAWING)]) == 0
    out = capsys.readouterr().out
    hinges = "J5 intrados (V1|V2), J10 extrados (V6|V7), J15 intrados (V10|V11), J23 extrados (RP1|ground)"
    assert f"LP (no sliding)  lambda = 0.2792   hinges: {hinges}" in out
    assert "LP (friction)    lambda = " in out and "mu* (LP)" in out
    assert "density 2000 kg/m^3 (archdem's default for drawings" in out
    assert "not for a drawing" in out and "the continuous ring" in out and "two-bar" in out
    assert "glued" not in out and "free" not in out


def test_the_shipped_drawing_s_json_is_the_library_s(capsys):
    d = _json(capsys, ["analytic", "--geometry", str(EXAMPLE_DRAWING)])
    asm = read_assembly(EXAMPLE_DRAWING)
    ns, lp = solve_lp(asm, math.inf, math.inf), solve_lp(asm, 0.577, 1.0)
    assert d["lambda_no_sliding"] == ns.lam and d["lambda_lp"] == lp.lam and d["lambda_discrete"] == enumerate_mechanisms(asm).lam
    assert [(h["joint"], h["face"], h["between"]) for h in d["hinges_no_sliding"]] == [
        ("J5", "intrados", ["V1", "V2"]), ("J10", "extrados", ["V6", "V7"]), ("J15", "intrados", ["V10", "V11"]),
        ("J23", "extrados", ["RP1", "ground"])]
    assert d["mu_star_lp"] == lp_mu_star(asm, 1.0, solve_lp(asm, math.inf, 1.0).lam) and 0 < d["mu_star_lp"] < 1
    assert (d["config"], d["density"], d["density_from"], d["gaps"]) == ("drawn", DRAWN_DENSITY, "default", [])
    assert d["lambda_continuous"] is None and d["lambda_two_bar"] is None and d["not_applicable"]
    assert "glued" not in json.dumps(d)


@pytest.mark.slow
def test_the_shipped_drawing_without_dilatancy_collapses_as_the_lp(capsys):
    """The shipped drawing's LP collapse does not slide: without dilatancy the multiplier and hinges are the LP's."""
    argv = ["analytic", "--geometry", str(EXAMPLE_DRAWING), "--friction", "non-associative"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    hinges = "J5 intrados (V1|V2), J10 extrados (V6|V7), J15 intrados (V10|V11), J23 extrados (RP1|ground)"
    assert "  LP (associative) lambda = 0.2792   (upper bound: sliding joints dilate)" in out
    assert f"  non-associative  lambda = 0.2792   0.00 % below; hinges: {hinges}   [optimal (proven" in out
    d = _json(capsys, argv)
    na = d["non_associative"]
    assert na["lambda_associative"] == pytest.approx(d["lambda_lp"], rel=1e-9)
    assert na["lambda_non_associative"] <= d["lambda_lp"] * (1 + 1e-9)
    assert na["lambda_non_associative"] == pytest.approx(d["lambda_lp"], rel=1e-6) and na["optimal"] is True
    assert [(h["joint"], h["face"]) for h in na["hinges"]] == [(h["joint"], h["face"]) for h in d["hinges_lp"]]
    assert "non_associative" not in _json(capsys, argv[:-2])


def test_a_generated_stack_rocks_above_its_mu_star_and_slides_below(tmp_path, capsys):
    """Two blocks 200 x 400 mm stacked on the ground: the stack rocks about its foot at b/h = 0.25; below
    mu 0.25 the top block slides first (lambda = mu): mu* = 0.25."""
    p = _dxf(tmp_path / "stack.dxf", [[(0, 0), (200, 0), (200, 400), (0, 400)], [(0, 400), (200, 400), (200, 800), (0, 800)]])
    d = _json(capsys, ["analytic", "--geometry", p])
    assert d["lambda_lp"] == pytest.approx(0.25, rel=1e-9) and d["lambda_no_sliding"] == pytest.approx(0.25, rel=1e-9)
    assert d["mu_star_lp"] == pytest.approx(0.25, abs=2e-4) and not d["chain"] and d["lambda_discrete"] is None
    assert [(h["joint"], h["between"]) for h in d["hinges_lp"]] == [("J0", ["ground", "B1"])]
    low = _json(capsys, ["analytic", "--geometry", p, "--mu-joint", "0.1"])
    assert low["lambda_lp"] == pytest.approx(0.1, rel=1e-9)
    assert [(m["joint"], m["state"], m["between"]) for m in low["moving_lp"]] == [("J1", "sliding", ["B1", "B2"])]
    assert main(["analytic", "--geometry", p, "--mu-joint", "0.1"]) == 0
    assert "J1 sliding (B1|B2)" in capsys.readouterr().out
    # density: stated, settable, scaling the masses only
    heavy = _json(capsys, ["analytic", "--geometry", p, "--density", "2400"])
    assert (heavy["density"], heavy["density_from"]) == (2400.0, "given")
    assert heavy["total_mass_kg"] == pytest.approx(d["total_mass_kg"] * 2400 / DRAWN_DENSITY)
    assert heavy["lambda_lp"] == d["lambda_lp"]
    assert main(["analytic", "--geometry", p, "--density", "2400"]) == 0
    assert "density 2400 kg/m^3 (--density)" in capsys.readouterr().out


def test_a_catalogue_arch_drawn_is_analysed_as_the_catalogue_s(tmp_path, capsys):
    asm = discretise(get_specimen("Sh06-Sd015").arch)
    p = write_assembly(asm, tmp_path / "arch.dxf")
    d = _json(capsys, ["analytic", "--geometry", str(p)])
    assert d["lambda_lp"] == solve_lp(asm, 0.577, 1.0).lam and d["lambda_discrete"] == enumerate_mechanisms(asm).lam
    assert d["density"] == 500.0 and d["density_from"] == "file"  # archdem wrote the catalogue's density
    arch = _json(capsys, ["analytic", "Sh06-Sd015"])
    assert d["lambda_lp"] == arch["lambda_lp"]


def test_a_drawing_that_slides_under_its_own_weight_at_the_friction_says_so(tmp_path, capsys):
    """A block on a support falling at 30 degrees along +x: with mu_base 0.3 it slides down under self-weight
    (no multiplier at that friction, exit 1); without sliding it stands. No joint between blocks: no mu*."""
    s, c = 0.5, math.sqrt(3) / 2  # sin, cos 30 deg
    blk = [(0, 0), (200 * c, -200 * s), (200 * c + 200 * s, -200 * s + 200 * c), (200 * s, 200 * c)]
    slope = [(-1000 * c, 1000 * s), (-1000 * c, -1000), (1000 * c, -1000), (1000 * c, -1000 * s)]
    p = _dxf(tmp_path / "slope.dxf", [blk], supports=[slope])
    assert main(["analytic", "--geometry", p, "--mu-base", "0.3"]) == 1
    out = capsys.readouterr().out
    assert "cannot stand under self-weight at these frictions" in out and "LP (no sliding)  lambda = " in out
    d = _json(capsys, ["analytic", "--geometry", p, "--mu-base", "0.3"])
    assert d["lambda_lp"] < 0 and d["stands_at_friction"] is False and d["stands"] is True
    assert d["mu_star_lp"] is None


@pytest.mark.parametrize("extra, msg", [
    (["--config", "free"], "--config does nothing here: a drawing's blocks are as drawn"),
    (["--min-spacing", "0.1"], "--min-spacing does nothing here: it belongs to the continuous ring"),
    (["--voussoirs", "4"], "drop --voussoirs"),
    (["--density", "0"], "--density must be between"),
])
def test_what_does_not_apply_to_a_drawing_is_refused_in_one_line(capsys, extra, msg):
    assert main(["analytic", "--geometry", str(EXAMPLE_DRAWING), *extra]) == 2
    err = capsys.readouterr().err
    assert msg in err and err.count("\n") == 1
