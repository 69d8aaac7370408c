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
