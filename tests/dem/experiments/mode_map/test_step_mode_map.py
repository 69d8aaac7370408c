"""The optional mode-map step: asked for by name, its searches one resumable study of the campaign, its
table (typed, beside its CSV) and figure in its report section, the map in the report's summary."""
import html

import h5py

from dem.campaign.runner import OPTIONAL_STEPS, STEPS, default_steps, run_campaign
from dem.common.campaign import CampaignContext
from dem.common.tables import read_csv
from dem.experiments.mode_map import step_mode_map as step
from dem.experiments.mode_map.run import ModeMapResult
from specimens.catalogue import select_specimens


def test_the_step_runs_the_map_when_asked_for_and_reports_it(synthetic, tmp_path, monkeypatch):
    assert "mode-map" in STEPS and "mode-map" in OPTIONAL_STEPS and "mode-map" not in default_steps()
    spec, study = synthetic
    calls = []

    def stand_in(spec_asked, path, workers=None, scheduler=None, resume=False):
        calls.append((spec_asked, path, workers, resume))
        return ModeMapResult.from_study(study, spec.cases(), title=spec.title())

    monkeypatch.setattr(step, "run", stand_in)  # the searches themselves: tests/dem/experiments/mode_map/test_case.py
    ctx = CampaignContext(out=tmp_path, specimens=select_specimens("Sh1-Sd015,Sh02-Sd015"), workers=2,
                          log=lambda s: None)
    manifest = run_campaign(ctx, ["mode-map"])
    ((asked, path, workers, resume),) = calls
    assert asked.specimens == ("Sh1-Sd015", "Sh02-Sd015") and asked.freqs == (2.0, 4.0, 6.0, 8.0, 10.0)
    assert path == tmp_path / "studies" / "mode-map.h5" and workers == 2 and resume is True
    schema, rows = read_csv(tmp_path / "mode-map" / "mode_map.csv")
    assert schema == ModeMapResult.SCHEMA and [r["mode"] for r in rows] == ["mixed", "none", "not run", "failed"]
    assert (tmp_path / "mode-map" / "mode_map.png").read_bytes()[:4] == b"\x89PNG"
    outputs = manifest["steps"]["mode-map"]["outputs"]
    assert outputs["findings"][0].startswith("1 of 4 searches find a collapse")
    page = (tmp_path / "report.html").read_text(encoding="utf-8")
    assert f"<h2 id='mode-map'>{html.escape(STEPS['mode-map'][1])}</h2>" in page
    assert '<table class="data" data-name="mode_map">' in page and '<th title="g">amplitude_g</th>' in page
    assert page.count("data:image/png;base64,") == 1
    assert "<td><b>3.128</b> m 1st (above reach); R7 1st</td>" in page  # the summary's map
    with h5py.File(tmp_path / "campaign.h5", "r") as f:
        assert f["tables/mode_map/amplitude_g"].attrs["unit"] == "g" and f["tables/mode_map/n_sims"][0] == 18
