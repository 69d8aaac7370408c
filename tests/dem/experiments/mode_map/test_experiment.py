"""The mode map's declaration: an optional campaign step, and its table in the report's summary."""
from dem.campaign.report import _summary_html
from dem.experiments.mode_map.experiment import EXPERIMENT, cell_text, summary_table
from dem.experiments.mode_map.run import ModeMapResult


def test_the_step_is_optional_and_the_summary_table_shows_only_when_it_ran(synthetic):
    (step,) = EXPERIMENT.steps
    assert (step.name, step.optional) == ("mode-map", True)
    assert summary_table({}) is None
    spec, study = synthetic
    rows = ModeMapResult.from_study(study, spec.cases()).rows()
    caption, headers, cells = summary_table({"mode_map": rows})
    assert headers == ("specimen", "8 Hz", "10 Hz")
    assert cells == [("Sh1-Sd015", "<b>3.128</b> m 1st (above reach); R7 1st", "none up to 4.8 g"),
                     ("Sh02-Sd015", "not run", "failed")]
    assert "mode map" in caption and "<td>none up to 4.8 g</td>" in _summary_html({"mode_map": rows})


def test_a_cell_reads_as_the_validation_table_writes_it(synthetic):
    spec, study = synthetic
    fell = ModeMapResult.from_study(study, spec.cases()).rows()[0]
    assert cell_text({**fell, "within_reach": True, "joint": "", "phase": "after-first-rebound"}) == "<b>3.128</b> m 2nd"
    assert cell_text({**fell, "slip_half": "after"}) == "<b>3.128</b> m 1st (above reach); R7 after"
