"""The campaign's assessment step: the Noh Gumbad vaults, unreinforced and with FRP strips."""
import csv

import pytest

from dem.campaign.runner import run_campaign
from dem.common.campaign import CampaignContext
from specimens.catalogue import select_specimens


@pytest.mark.slow
def test_the_noh_gumbad_section(tmp_path):
    ctx = CampaignContext(out=tmp_path, specimens=select_specimens("Sh06-Sd015"), quick=True, workers=1,
                          log=lambda s: None)
    manifest = run_campaign(ctx, ["assess"])
    with open(tmp_path / "assess" / "assess.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [(r["configuration"], r["frp"]) for r in rows] == [
        (c, f) for c in ("ring alone", "half-height piers", "full-height piers") for f in ("False", "True")]
    lam = [float(r["lambda"]) for r in rows]
    assert all(b > a for a, b in zip(lam[::2], lam[1::2]))  # the strips raise every multiplier
    page = (tmp_path / "report.html").read_text()
    assert "Noh Gumbad" in page and "assess" in manifest["steps"]
    # the governing configuration's calculation, and the summary up front
    with open(tmp_path / "assess" / "calculation.csv", newline="") as fh:
        calc = {r["quantity"]: r for r in csv.DictReader(fh)}
    assert calc["M*"]["formula"] == "(sum m dx)^2 / sum m dx^2" and float(calc["e*"]["value"]) > 0
    assert page.index("<h2>Summary</h2>") < page.index("<h2>Findings</h2>") and "a0*/PGA" in page
    assert "<table class='params'>" in page
