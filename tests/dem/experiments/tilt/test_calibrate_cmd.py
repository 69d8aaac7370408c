"""``archdem calibrate`` and ``--contact calibrated``: the stored calibration is the one used."""
import json

import pytest

from dem.cli import main
from specimens.catalogue import get_specimen

TABLE = """# two specimens of the shipped table
id,lambda_mean,lambda_sd,observed_mode
Sh06-Sd020,0.337,0.039,rocking
Sh1-Sd015,0.256,0.021,rocking
"""


@pytest.mark.slow
def test_calibrate_stores_what_contact_calibrated_uses(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "lab.csv").write_text(TABLE)
    assert main(["calibrate", "--experiments", "lab.csv", "--no-scatter", "--json"]) == 0
    cal = json.loads(capsys.readouterr().out)
    stored = json.loads((tmp_path / "runs" / "calibration" / "contact.json").read_text())
    assert stored["edge_loss_mm"] == cal["edge_loss_mm"] and stored["experiments"] == "lab.csv"
    assert [r["id"] for r in cal["specimens"]] == ["Sh06-Sd020", "Sh1-Sd015"]
    assert main(["analytic", "Sh06-Sd020", "--contact", "calibrated", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    t = get_specimen("Sh06-Sd020").arch.t
    assert out["contact"] == pytest.approx(1 - 2 * cal["edge_loss_mm"] / 1e3 / t, rel=1e-12)
    # the LP at that contact is the calibration's fitted value for this specimen
    assert out["lambda_lp"] == pytest.approx(cal["specimens"][0]["lambda_fit"], rel=1e-9)


@pytest.mark.slow
def test_an_existing_calibration_is_kept_unless_replaced(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "lab.csv").write_text(TABLE)
    out = tmp_path / "c.json"
    out.write_text("{}")
    assert main(["calibrate", "--experiments", "lab.csv", "--no-scatter", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--replace" in err and out.read_text() == "{}"
    assert main(["calibrate", "--experiments", "lab.csv", "--no-scatter", "--out", str(out), "--replace"]) == 0
    assert json.loads(out.read_text())["edge_loss_mm"] > 0


@pytest.mark.parametrize("table, msg", [
    ("id,lambda_mean\nSh06-Sd020,0.3\n", "missing column"),
    ("id,lambda_mean,lambda_sd,observed_mode\nNope,0.3,0.01,rocking\n", "unknown specimen id"),
])
def test_bad_experiments_exit_2_in_one_line_and_write_nothing(tmp_path, monkeypatch, capsys, table, msg):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "lab.csv").write_text(table)
    assert main(["calibrate", "--experiments", "lab.csv"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and msg in err
    assert not (tmp_path / "runs").exists()
