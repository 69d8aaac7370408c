"""The assessment with records from Python (dem/experiments/assessment/run.py): the same answer as
``archdem assess``, for an arch with records and for the Noh Gumbad vault."""
import json

import pytest

from analytic.motions.spectra import ec8
from dem.cli import main
from dem.experiments.assessment.run import assess_with_records
from specimens.constants import G


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


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
