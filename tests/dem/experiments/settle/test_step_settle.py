"""The optional settle step: asked for by name, its typed table beside its CSV, its report section and
its group in ``campaign.h5``."""
import h5py
import pytest

from dem.campaign.runner import OPTIONAL_STEPS, STEPS, default_steps, run_campaign
from dem.common.campaign import CampaignContext
from dem.common.tables import read_csv
from dem.experiments.settle.run import SettleResult
from specimens.catalogue import select_specimens

pytestmark = pytest.mark.slow  # a campaign with one simulation


def test_the_settle_step_runs_when_asked_for_and_reports(tmp_path):
    assert "settle" in STEPS and "settle" in OPTIONAL_STEPS and "settle" not in default_steps()
    ctx = CampaignContext(out=tmp_path, specimens=select_specimens("Sh02-Sd020"), log=lambda s: None)
    manifest = run_campaign(ctx, ["settle"])
    assert list(manifest["steps"]) == ["settle"]
    schema, rows = read_csv(tmp_path / "settle" / "settle.csv")
    assert schema == SettleResult.SCHEMA and [r["id"] for r in rows] == ["Sh02-Sd020"] and rows[0]["at_rest"] is True
    (finding,) = manifest["steps"]["settle"]["outputs"]["findings"]
    assert finding.startswith("1 of 1 specimens at rest")
    page = (tmp_path / "report.html").read_text(encoding="utf-8")
    assert f"<h2 id='settle'>{STEPS['settle'][1]}</h2>" in page and '<th title="mm">max_displacement_mm</th>' in page
    with h5py.File(tmp_path / "campaign.h5", "r") as f:
        g = f["tables/settle"]
        assert g["at_rest"].dtype.kind == "b" and g["max_displacement_mm"].attrs["unit"] == "mm"
        assert g["max_displacement_mm"][0] == rows[0]["max_displacement_mm"]
