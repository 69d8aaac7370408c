"""The campaign's modes step: every specimen's frequencies, those of ``analytic.compliant.modes`` on the study's joints."""
import csv
import json

import pytest

from analytic.compliant.modes import modes
from dem.campaign.runner import run_campaign
from dem.common.campaign import CampaignContext
from specimens import get_specimen
from specimens.blocks import discretise
from specimens.catalogue import STUDY_JOINTS


@pytest.mark.slow
def test_modes_step_lists_every_specimen(tmp_path):
    specs = [get_specimen(s) for s in ("Sh02-Sd015", "Sh06-Sd020")]
    ctx = CampaignContext(out=tmp_path, specimens=specs, log=lambda _: None)
    manifest = run_campaign(ctx, ["modes"])
    with open(tmp_path / "modes" / "modes.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["id"] for r in rows] == ["Sh02-Sd015", "Sh06-Sd020"]
    own = modes(discretise(specs[1].arch, config="glued"), STUDY_JOINTS["Sh06-Sd020"][0]).frequencies_hz
    assert float(rows[1]["f1_Hz"]) == pytest.approx(own[0], rel=1e-9)
    assert len(json.loads(rows[1]["all_Hz"])) == len(own)
    assert (tmp_path / "modes" / "modes_Sh02-Sd015.png").exists() and "modes" in manifest["steps"]
