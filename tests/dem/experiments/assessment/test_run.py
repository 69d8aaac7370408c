"""The assessment with records from Python (dem/experiments/assessment/run.py): the same answer as
``archdem assess``, for an arch with records, an arch on piers with a tie and the SLD hazard, and for
the Noh Gumbad vault."""
import json

import pytest

from analytic.limit.ties import Tie
from analytic.motions.spectra import ec8, rebuild
from dem.cli import main
from dem.experiments.assessment.run import assess_with_records
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from specimens.piers import Piers


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.slow  # records shaken on the DEM
def test_an_arch_with_records_as_the_command_line(short_records, capsys):
    d = _json(capsys, ["assess", "Sh06-Sd015", "--spectrum", "ec8", "--ag", "0.1", "--records", *short_records,
                       "--workers", "1", "--json"])
    a = assess_with_records("Sh06-Sd015", short_records, ec8(0.1 * G, "A", 1), workers=1)
    assert a.assessment.safety_index == d["safety_index"]
    rec = a.records.describe()
    assert rec["period_range"] == d["records"]["period_range"] and rec["verdict"] == d["records"]["verdict"]
    assert [r["peak_d_star"] for r in rec["runs"]] == [r["peak_d_star"] for r in d["records"]["runs"]]


def test_the_noh_gumbad_vault_as_its_rows(capsys):
    d = _json(capsys, ["assess", "noh-gumbad", "--json"])
    row = next(r for r in d["rows"] if r["configuration"] == "ring alone" and not r["frp"])
    a = assess_with_records("noh-gumbad")
    assert a.records is None and a.label == "noh-gumbad, ring alone"
    assert a.assessment.safety_index == pytest.approx(row["safety_index"], rel=1e-12)
    assert a.assessment.linear.alpha0 == pytest.approx(row["lambda"], rel=1e-12)


def test_a_tie_and_the_sld_hazard_as_the_command_line(capsys):
    """A tie at mid-pier and the SLD hazard beside SLV: the library's strengthened structure and limit states
    are the command line's."""
    d = _json(capsys, ["assess", "Sh06-Sd015", "--pier-height", "0.4", "--pier-width", "0.144", "--pier-courses", "2",
                       "--spectrum", "ec8", "--ag", "0.1", "--sld-ag", "0.05", "--tie=-0.2,1,2", "--json"])
    site = ec8(0.1 * G, "A", 1)
    a = assess_with_records("Sh06-Sd015", (), site, piers=Piers(0.4, 0.144, courses=2), tie=Tie(-0.2, 1e-6, 2e6),
                            sld_site=rebuild(site, ag=0.05 * G))
    assert a.records is None and set(a.assessment.by_limit_state()) == set(d["limit_states"]) == {"SLD", "SLV"}
    assert a.assessment.safety_index == pytest.approx(d["safety_index"], rel=1e-12)
    assert a.strengthened.lam == pytest.approx(d["tie"]["lambda"], rel=1e-12) and a.strengthened.lam > d["alpha0"]
    assert a.strengthened_assessment.safety_index == pytest.approx(d["tie"]["safety_index"], rel=1e-12)


def test_an_arch_that_cannot_stand_is_refused_before_the_work():
    with pytest.raises(ArchdemInputError, match="cannot stand under its own weight"):
        assess_with_records(PointedArch.from_ratios(0.0, 0.03, 0.2), site=ec8(0.2 * G, "A", 1))


@pytest.mark.slow  # the assessment three times
def test_the_library_result_is_the_command_lines_answer_and_text(capsys, tmp_path):
    """The spec's result describes itself as ``archdem assess --json`` and prints as ``archdem assess``; its
    table, the checks as the code states them, is written and read back typed."""
    from dem.common.tables import read_csv
    from dem.experiments.assessment.run import CHECKS_SCHEMA, AssessSpec, run

    argv = ["assess", "Sh06-Sd015", "--pier-height", "0.4", "--pier-width", "0.144", "--pier-courses", "2",
            "--spectrum", "ec8", "--ag", "0.1", "--sld-ag", "0.05", "--tie=-0.2,1,2"]
    d = _json(capsys, [*argv, "--json"])
    assert main(argv) == 0
    text = capsys.readouterr().out
    site = ec8(0.1 * G, "A", 1)
    a = run(AssessSpec("Sh06-Sd015", site, piers=Piers(0.4, 0.144, courses=2), tie=Tie(-0.2, 1e-6, 2e6),
                       sld_site=rebuild(site, ag=0.05 * G), label=d["id"]))
    assert json.loads(json.dumps(a.describe())) == d and "\n".join(a.lines()) + "\n" == text
    assert a.strengthened_key == "tie" and "a tie at -0.2 m yielding at" in text
    a.write_csv(tmp_path / "checks.csv")
    schema, rows = read_csv(tmp_path / "checks.csv")
    assert schema == CHECKS_SCHEMA and [r["limit_state"] for r in rows] == ["SLD", "SLV", "SLV"]
    assert all(isinstance(r["code_check"], bool) for r in rows) and rows == a.rows()


def test_the_monument_result_holds_its_three_tables(tmp_path):
    """Every configuration, bare and strengthened: its rows, its checks and its governing calculation, each
    through its schema; the printed table has a row per configuration and strengthening."""
    from analytic.codes.assessment import monument_strips
    from dem.common.tables import read_csv
    from dem.experiments.assessment.run import MonumentAssessment, MonumentSpec, run
    from specimens.monuments import NOH_GUMBAD

    res = run(MonumentSpec(NOH_GUMBAD, monument_strips()))
    res.write_csv(tmp_path / "assess.csv")
    schema, rows = read_csv(tmp_path / "assess.csv")
    assert schema == MonumentAssessment.SCHEMA and [r["frp"] for r in rows] == [False, True] * 3
    assert rows[0]["lambda"] == pytest.approx(0.4211, abs=1e-4) and rows[0]["M_star_kg"] == res.assessed[0]["M_star"]
    checks = res.check_rows()
    assert len(checks) == sum(len(r["check_rows"]) for r in res.assessed)
    lin = next(c for c in checks if c["check"].startswith("linear"))
    assert lin["unit"] == "g" and lin["capacity_value"] / lin["demand_value"] == pytest.approx(lin["safety_index"])
    calc = res.calculation_rows()
    assert res.governing["safety_index"] == min(r["safety_index"] for r in res.assessed)
    assert {"alpha0", "M*", "e*"} <= {c["quantity"] for c in calc}
    lines = res.lines()
    assert lines[0].startswith("noh-gumbad: EN 1998-1 site") and sum("ring alone" in x for x in lines[2:8]) == 2
    assert lines[-1].startswith("  FRP bond factors (CNR-DT 200 R1/2013): k_G")
