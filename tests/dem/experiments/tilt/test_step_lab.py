"""The lab step's table: one row per specimen declared once (``SpecimenLab``); the comparison with the
laboratory only where a specimen was tested, empty for a prediction."""
import math

from dem.common.tables import read_csv, write_csv
from dem.experiments.tilt.step_lab import SpecimenLab

BASE = (0.35, 0.79, 0.25, 0.349, 0.247, 0.013, 10, "rocking", "rocking:10")


def test_a_prediction_leaves_the_comparison_empty(tmp_path):
    tested = SpecimenLab("Sh02-Sd020", "laboratory", 0.268, 0.027, "rocking", *BASE, mode_agrees=True,
                         within_2sd_or_15pct=True, err_dem_vs_lab_pct=-8.0, err_ideal_lp_vs_lab_pct=31.0)
    predicted = SpecimenLab("Sh06-Sd015", "prediction", math.nan, math.nan, "", *BASE)
    rows = tested.rows() + predicted.rows()
    assert list(rows[0]) == SpecimenLab.SCHEMA.names
    write_csv(tmp_path / "lab.csv", rows, SpecimenLab.schema(True))
    text = (tmp_path / "lab.csv").read_text().splitlines()
    assert text[2].endswith(",rocking,rocking:10,,,,")  # the prediction's comparison: empty cells
    _, back = read_csv(tmp_path / "lab.csv")
    assert back[0]["mode_agrees"] is True and back[1]["mode_agrees"] is None and back[0]["n_realisations"] == 10
    only = SpecimenLab.schema(False)
    assert only.names == [n for n in SpecimenLab.SCHEMA.names if n not in SpecimenLab.TESTED_ONLY]
