"""The mode map's spec, its cases (those the study files have always stored) and its typed table."""
import math

import pytest

from dem.common.tables import read_csv
from dem.experiments.mode_map.run import MAP_FREQS, ModeMapResult, ModeMapSpec
from dem.studies.sweep import case_key
from foundation.errors import ArchdemInputError
from specimens.catalogue import SPECIMEN_IDS


def test_the_default_spec_is_the_fitted_table_and_its_cases_keep_their_stored_form():
    spec = ModeMapSpec()
    assert spec.specimens == SPECIMEN_IDS and spec.freqs == MAP_FREQS == (2.0, 4.0, 6.0, 8.0, 10.0)
    cases = spec.cases()
    assert len(cases) == 55 and cases[1]["id"] == SPECIMEN_IDS[0] and cases[1]["freq"] == 4.0
    # a case as the study files written before the experiment existed hold it: the same key, so they resume
    old = {"id": "Sh1-Sd015", "freq": 8.0, "table_speed": 1.0, "tau": None, "mu_base": 1.0, "contact": 1.0,
           "restitution": 0.0, "scan_over": 1.5, "reach_speed": 1.0, "slip_mm": 0.2}
    assert spec.case("Sh1-Sd015", 8) == old and case_key(spec.case("Sh1-Sd015", 8)) == case_key(old)
    # whole numbers are stored as floats: 1 and 1.0 would be two cases
    assert case_key(ModeMapSpec(mu_base=1, scan_over=1.5, restitution=0).case("Sh1-Sd015", 8)) == case_key(old)


def test_the_ideal_sine_has_no_position_loop_and_the_title_says_the_table():
    ideal = ModeMapSpec(specimens=("Sh1-Sd015",), table_speed=None, tau=0.02)
    assert ideal.tau is None and "ideal sine" in ideal.title()
    loop = ModeMapSpec(specimens=("Sh1-Sd015",), tau=0.02, contact="calibrated")
    assert "position loop 20 ms" in loop.title() and loop.case("Sh1-Sd015", 4)["contact"] == "calibrated"


@pytest.mark.parametrize("kw, match", [
    ({"specimens": ("Sh9-Sd999",)}, "unknown specimen"), ({"specimens": ()}, "at least one"),
    ({"freqs": (2.0, 0.0)}, "positive"), ({"freqs": (2.0, 2.0)}, "named twice"),
    ({"contact": 1.5}, "contact"), ({"table_speed": -1.0}, "table speed"), ({"scan_over": math.nan}, "scan_over"),
    ({"restitution": 2.0}, "restitution"),
])
def test_bad_input_is_refused_in_one_line(kw, match):
    with pytest.raises(ArchdemInputError, match=match):
        ModeMapSpec(**kw)


def test_rows_from_a_study_are_typed_and_a_case_not_stored_reads_not_run(synthetic, tmp_path):
    spec, study = synthetic
    res = ModeMapResult.from_study(study, spec.cases(), title=spec.title())
    fell, stood, not_run, failed = res.rows()
    assert list(fell) == ModeMapResult.SCHEMA.names
    assert (fell["label"], fell["id"], fell["freq"], fell["amplitude_g"], fell["within_reach"], fell["joint"],
            fell["n_sims"], fell["tau"], fell["contact"]) == ("map", "Sh1-Sd015", 8.0, 3.128, False, "R7", 18, None, "1.0")
    # no collapse: no amplitude, no reach verdict; the slip time NaN stored is a missing value
    assert stood["mode"] == "none" and stood["amplitude_g"] is None and stood["within_reach"] is None
    assert stood["t_slip_s"] is None and stood["scan_top_g"] == 4.8
    assert (not_run["mode"], not_run["lambda"], not_run["phase"]) == ("not run", None, "")
    assert failed["mode"] == "failed" and failed["id"] == "Sh02-Sd015" and failed["freq"] == 10.0
    res.write_csv(tmp_path / "mode_map.csv")
    schema, back = read_csv(tmp_path / "mode_map.csv")
    assert schema == ModeMapResult.SCHEMA and back == res.rows()


def test_its_findings_and_lines_are_computed_from_the_rows(synthetic):
    spec, study = synthetic
    res = ModeMapResult.from_study(study, spec.cases())
    assert res.findings() == [
        "1 of 4 searches find a collapse: 0 rocking, 1 mixed, 0 sliding; 1 stand up to the scan's top; 2 failed or not run.",
        "Collapses only the saturated table gives (above its reach): Sh1-Sd015 at 8 Hz.",
        "Collapses before the first rebound: Sh1-Sd015 at 8 Hz; the first slip in the first half cycle: Sh1-Sd015 at 8 Hz."]
    lines = res.lines()
    assert len(lines) == 4 and "3.128 g mixed" in lines[0] and "first slip R7 first" in lines[0]
    assert "none" in lines[1] and "scan to 4.80 g" in lines[1] and "not run" in lines[2]
