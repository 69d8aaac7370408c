"""``archdem analytic``'s spec, run and results: the checks of the spec, NaN as JSON null, the text of an
arch that cannot stand, and a drawing's mu* from the function handed in."""
import math

import ezdxf
import pytest

from analytic.limit.analysis import ArchAnalysis, ArchAnalysisSpec, json_ready, non_associative_lines, run_drawing
from foundation.errors import ArchdemInputError
from specimens.blocks import discretise
from specimens.exchange import read_assembly


def test_json_ready_nulls_nan_in_floats_and_the_non_associative_entry_only():
    nan = float("nan")
    out = json_ready({"a": nan, "b": 1.5, "non_associative": {"lambda": nan, "hinges": [nan]}, "list": [nan]})
    assert out["a"] is None and out["b"] == 1.5
    assert out["non_associative"] == {"lambda": None, "hinges": [None]}
    assert math.isnan(out["list"][0])  # other entries as analyse gave them


@pytest.mark.parametrize("kw, msg", [
    ({"effective_thickness": 1.5, "min_spacing": 0.0}, "--effective-thickness must be in [0.05, 1]"),
    ({"effective_thickness": 0.8, "min_spacing": 0.0, "disc_kw": {"piers": object()}}, "on piers use --contact"),
    ({"effective_thickness": 1.0, "min_spacing": 0.1, "disc_kw": {"piers": object()}}, "on piers use --contact"),
])
def test_the_spec_refuses_what_the_analyses_cannot_take(kw, msg):
    with pytest.raises(ArchdemInputError, match=msg.replace("[", r"\[").replace("]", r"\]")):
        ArchAnalysisSpec("x", None, "glued", 0.577, 1.0, **kw)


def test_an_arch_that_cannot_stand_prints_its_header_and_no_multiplier():
    res = ArchAnalysis("A", {"config": "free", "mu_joint": 0.5, "mu_base": 1.0, "stands": False,
                             "lambda_continuous": float("nan")})
    assert res.lines() == ["A  (config free, mu_joint 0.5, mu_base 1)",
                           "  the arch cannot stand under self-weight: no collapse multiplier (see --json for the "
                           "analyses)"]
    assert res.exit_code == 1
    assert list(res.to_json())[-1] == "id" and res.to_json()["lambda_continuous"] is None


def test_non_associative_lines_give_the_gap_below_the_lp_and_the_mechanism():
    na = {"lambda_associative": 0.2, "lambda_non_associative": 0.19, "hinges": [{"joint": "J1", "face": "intrados",
          "sliding": True}], "sliding": ["J2"], "open": [], "message": "optimal", "seconds": 0.25, "nodes": 7}
    lines = non_associative_lines(na, {"J1": ["V1", "V2"]})
    assert lines[0].startswith("  LP (associative) lambda = 0.2000")
    assert "5.00 % below; hinges: J1 intrados+sliding (V1|V2); sliding: J2   [optimal; 0.2 s, 7 nodes]" in lines[1]


def test_a_drawing_s_mu_star_comes_from_the_function_handed_in(tmp_path):
    doc = ezdxf.new(units=4)  # two blocks 200 x 400 mm stacked on the ground, 100 mm deep
    for y in (0, 400):
        doc.modelspace().add_lwpolyline([(0, y), (200, y), (200, y + 400), (0, y + 400)], format="xy", close=True,
                                        dxfattribs={"layer": "blocks depth 100"})
    doc.saveas(str(tmp_path / "stack.dxf"))
    asm = discretise(read_assembly(tmp_path / "stack.dxf"))
    seen = []

    def mu_star(a, mu_base, lam):
        seen.append((a, mu_base, lam))
        return 0.4321

    res = run_drawing("stack", asm, 0.6, 0.9, False, mu_star, "density 2000 kg/m^3 (stated)")
    assert seen == [(asm, 0.9, res.values["lambda_no_joint_sliding"])]
    assert res.to_json()["mu_star_lp"] == 0.4321 and list(res.to_json())[0] == "id"
    text = res.lines()
    assert text[0].startswith("stack  (drawing stack.dxf: 2 blocks") and text[1].startswith("  density 2000 kg/m^3 (stated): ")
    assert any(line.startswith("  mu* (LP)         0.432   below it") for line in text)
    assert res.exit_code == (0 if res.values["stands_at_friction"] else 1)
