"""The campaign's piers study, run for real on one arch (quick: the bare arch and three pier heights)."""
import csv
import math

import pytest

from dem.campaign.runner import run_campaign
from dem.common.campaign import CampaignContext
from dem.experiments.tilt.step_piers import PIER_HEIGHTS_QUICK
from specimens.catalogue import select_specimens

pytestmark = pytest.mark.slow  # every test here simulates, spawns processes or runs a campaign


@pytest.fixture(scope="module")
def piers(tmp_path_factory):
    out = tmp_path_factory.mktemp("campaign")
    ctx = CampaignContext(out=out, specimens=select_specimens("Sh06-Sd015"), quick=True, workers=2, log=lambda s: None)
    manifest = run_campaign(ctx, ["piers"])
    with open(out / "piers" / "piers.csv", newline="") as fh:
        return out, manifest, list(csv.DictReader(fh))


def test_taller_piers_lower_lambda_in_la_and_dem(piers):
    _, _, rows = piers
    assert [float(r["height_over_rise"]) for r in rows] == list(PIER_HEIGHTS_QUICK)
    lp = [float(r["lambda_lp_no_sliding"]) for r in rows]
    dem = [float(r["lambda_dem_no_sliding"]) for r in rows]
    assert all(b <= a + 1e-12 for a, b in zip(lp, lp[1:])) and lp[-1] < 0.8 * lp[0]
    assert dem[-1] < 0.8 * dem[0]
    # the criterion: the DEM within 3 % of the LP with no sliding at every height
    assert all(abs(d / p - 1) <= 0.03 for d, p in zip(dem, lp))
    assert all(float(r["lambda_lp_reference"]) <= p + 1e-9 for r, p in zip(rows, lp))


def test_hinges_move_into_the_piers_in_la_and_dem(piers):
    _, _, rows = piers
    assert int(rows[0]["hinges_in_piers"]) == 0 and int(rows[-1]["hinges_in_piers"]) > 0
    for r in rows:
        lp = {h.split(":")[0] for h in r["hinges_lp"].split()}
        dem = set(r["hinges_dem"].split())
        # the DEM rocks; its hinges in the piers are the LP's (ring hinges may sit one joint over)
        assert r["mode_dem"] == "rocking" and {j for j in dem if "P" in j} == {j for j in lp if "P" in j}


def test_the_study_is_in_the_report(piers):
    out, manifest, rows = piers
    rec = manifest["steps"]["piers"]["outputs"]
    assert (out / rec["figures"][0]["path"]).is_file() and "lambda falls from" in rec["findings"][0]
    # the findings say what the table says
    lp = [float(r["lambda_lp_no_sliding"]) for r in rows]
    assert rec["findings"][0].startswith(f"lambda falls from {lp[0]:.3f} (the ring on a rigid base) to {lp[-1]:.3f} ")
    assert f"within {max(abs(float(r['err_dem_vs_lp_pct'])) for r in rows):.1f} % of the LP" in rec["findings"][1]
    assert "[piers]" in (out / "report.html").read_text(encoding="utf-8")
    assert not math.isnan(manifest["steps"]["piers"]["wall_s"])


def test_the_table_reads_back_in_its_declared_kinds(piers):
    from dem.common.tables import read_csv
    from dem.experiments.tilt.step_piers import PierTilt

    out, _, rows = piers
    schema, typed = read_csv(out / "piers" / "piers.csv")
    assert schema == PierTilt.SCHEMA and len(typed) == len(rows)
    assert all(isinstance(r["hinges_in_piers"], int) and isinstance(r["hinges_lp"], str) for r in typed)
