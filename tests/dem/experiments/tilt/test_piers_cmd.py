"""The pier options on the commands: an arch on piers drawn, meshed, analysed and rocked."""
import json

import pytest

from dem.cli import main

PIERS = ["--pier-height", "0.3", "--pier-width", "0.1", "--pier-courses", "3"]


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_analytic_names_the_hinges_in_the_piers(capsys):
    d = _json(capsys, ["analytic", "Sh06-Sd015", *PIERS, "--mu-joint", "inf", "--mu-base", "inf", "--json"])
    assert d["piers"] == {"height": 0.3, "width": 0.1, "depth": 0.1, "offset": 0.0, "courses": 3}
    assert d["lambda_lp"] == pytest.approx(d["lambda_discrete"], rel=1e-7)
    hinges = [(h["joint"], h["in_pier"]) for h in d["hinges_discrete"]]
    assert ("RP0", True) in hinges and all(p == j.startswith(("LP", "RP")) for j, p in hinges)
    assert set(d["joints_lp"]) >= {"LP0", "LP1", "LP2", "L0", "R0", "RP2", "RP1", "RP0"}
    # hinges anywhere: at most the voussoirs' multiplier, the last one at a height of the right pier
    assert d["lambda_continuous"] <= d["lambda_discrete"] and d["continuous_converged"]
    assert d["hinges_continuous"][-1]["pier"] == "right" and d["lambda_two_bar"] is None
    bare = _json(capsys, ["analytic", "Sh06-Sd015", "--mu-joint", "inf", "--mu-base", "inf", "--json"])
    assert d["lambda_discrete"] < bare["lambda_discrete"]


@pytest.mark.slow
def test_rock_and_domain_use_the_four_bar_through_the_piers(capsys):
    a = _json(capsys, ["analytic", "Sh06-Sd015", *PIERS, "--json"])
    r = _json(capsys, ["rock", "Sh06-Sd015", *PIERS, "--freq", "3", "--amplitude", "0.18", "--json"])
    assert r["model"]["lambda"] == pytest.approx(a["lambda_discrete"], rel=1e-9)
    # the mirror of the mechanism under +x loads (a positive ground acceleration loads along -x)
    mirror = {"L": "R", "R": "L"}
    assert [h["joint"] for h in r["model"]["hinges"]] == [mirror[j[0]] + j[1:] for j in
                                                          reversed([h["joint"] for h in a["hinges_discrete"]])]
    assert not r["collapsed"] and r["n_impacts"] > 0  # 0.18 g: just above the onset, 0.174 g
    d = _json(capsys, ["domain", "Sh06-Sd015", *PIERS, "--freq", "2", "--json"])
    assert d["hinges"] == r["model"]["hinges"] and d["points"][0]["amplitude_g"] > d["lambda"]


def test_draw_and_mesh_show_the_piers(tmp_path, capsys):
    assert main(["draw", "Sh06-Sd015", *PIERS, "--out", str(tmp_path / "p.png")]) == 0
    assert (tmp_path / "p.png").stat().st_size > 10_000
    assert main(["mesh", "Sh06-Sd015", *PIERS, "--pier-depth", "0.2", "--out", str(tmp_path / "m")]) == 0
    names = {p.name for p in (tmp_path / "m").iterdir()}
    assert {"LP1_p0.stl", "LP3_p0.stl", "RP1_p0.stl", "C_p0.stl"} <= names
    import trimesh

    for course in ("LP1", "LP3", "RP1", "RP3"):  # a closed box, height / courses x width x depth (float32 STL)
        m = trimesh.load(tmp_path / "m" / f"{course}_p0.stl")
        assert m.is_watertight and m.volume == pytest.approx(0.3 / 3 * 0.1 * 0.2, rel=1e-6)
    assert "Sh06-Sd015-piers-H0.3-B0.1-N3" in capsys.readouterr().out
