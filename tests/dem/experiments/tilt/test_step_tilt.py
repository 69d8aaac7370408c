"""The tilt step's table: one row per specimen declared once (``SpecimenTilt``), the no-sliding columns in the
full campaign only."""
import math

from dem.common.tables import read_csv
from dem.experiments.tilt.check import TiltCheck
from dem.experiments.tilt.step_tilt import SpecimenTilt


def _check(mu: float, lam: float, lp_lam: float) -> TiltCheck:
    return TiltCheck("Sh06-Sd015", "glued", "pybullet", mu, mu, lam, "rocking", (("L0", "intrados"),), (), 3, 1.0,
                     lp_lam, (("L0", "intrados"),))


def test_the_rows_hold_the_columns_of_the_frictions_that_ran(tmp_path):
    quick = SpecimenTilt("Sh06-Sd015", 0.6, 0.15, {"reference": _check(0.577, 0.3, 0.298)},
                         {"reference": "L0:hinge"}, 0.298, 0.31)
    (row,) = quick.rows()
    assert list(row) == SpecimenTilt.schema(False).names and "lambda_dem_no_sliding" not in row
    assert row["err_reference_vs_lp_pct"] == 100 * (0.3 - 0.298) / 0.298 and row["n_sims_reference"] == 3
    full = SpecimenTilt("Sh06-Sd015", 0.6, 0.15, {"reference": _check(0.577, 0.3, 0.298),
                                                  "no_sliding": _check(100.0, 0.31, 0.31)},
                        {"reference": "L0:hinge", "no_sliding": ""}, 0.298, 0.31)
    (row,) = full.rows()
    assert list(row) == SpecimenTilt.SCHEMA.names and row["ratio_reference_to_no_sliding"] == 0.3 / 0.31
    full.write_csv(tmp_path / "tilt.csv")
    _, back = read_csv(tmp_path / "tilt.csv")
    assert back[0]["n_sims_no_sliding"] == 3 and back[0]["joints_no_sliding"] == "" and math.isclose(back[0]["Sh"], 0.6)
