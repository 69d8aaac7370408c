"""``archdem assess``: the linear kinematic check of an arch (or an arch on piers) against a site spectrum."""
import json

import pytest

from analytic.spectra import ec8, ntc2018
from dem.cli import main
from specimens.constants import G

NTC = ["--spectrum", "ntc2018", "--ag", "0.25", "--F0", "2.4", "--Tc-star", "0.3", "--soil", "C"]


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_assess_an_arch_on_an_ntc_site(capsys):
    d = _json(capsys, ["assess", "Sh06-Sd015", *NTC, "--json"])
    site = ntc2018(0.25 * G, 2.4, 0.3, "C")
    assert d["spectrum"]["S"] == pytest.approx(site.S) and d["check"]["demand_pga"] == pytest.approx(site.pga)
    assert d["a0_star"] == pytest.approx(d["alpha0"] * G / (d["e_star"] * d["FC"]))
    assert d["check"]["capacity_pga"] == pytest.approx(2.0 * d["a0_star"]) and d["FC"] == 1.35
    assert d["check"]["safety_index"] == pytest.approx(d["check"]["capacity_pga"] / site.pga)
    # a better knowledge level (FC 1) raises the capacity by 1.35
    d1 = _json(capsys, ["assess", "Sh06-Sd015", *NTC, "--FC", "1", "--json"])
    assert d1["check"]["safety_index"] == pytest.approx(1.35 * d["check"]["safety_index"])


def test_assess_an_arch_on_piers_on_an_ec8_site(capsys):
    piers = ["--pier-height", "0.4", "--pier-width", "0.144", "--pier-courses", "4"]
    d = _json(capsys, ["assess", "Sh06-Sd015", *piers, "--spectrum", "ec8", "--ag", "0.1", "--soil", "B", "--json"])
    bare = _json(capsys, ["assess", "Sh06-Sd015", "--spectrum", "ec8", "--ag", "0.1", "--soil", "B", "--json"])
    assert d["check"]["demand_pga"] == pytest.approx(ec8(0.1 * G, "B").pga)
    # loads along -x (a positive ground acceleration): the left pier rocks on its outer foot
    assert {"joint": "LP0", "face": "extrados"} in d["mechanism"]["hinges"]
    assert d["alpha0"] < bare["alpha0"] and d["check"]["safety_index"] < bare["check"]["safety_index"]
    assert main(["assess", "Sh06-Sd015", *piers, "--spectrum", "ec8", "--ag", "0.1"]) == 0
    assert "safety index" in capsys.readouterr().out
