"""A synthetic study of the mode map: two cases stored (a collapse above the table's reach with the crown
slipping first, and an arch that stands), one failed, one asked for but not run."""
import math
from pathlib import Path

import pytest

from dem.experiments.mode_map.run import ModeMapSpec
from dem.studies.sweep import CaseRecord, StudyResult, case_key

FELL = {"lambda": 0.33, "contact_fraction": 1.0, "scan_top_g": 3.84, "amplitude_g": 3.128, "mode": "mixed",
        "phase": "before-first-rebound", "joint": "R7", "t_slip_s": 0.027, "slip_half": "first", "n_sims": 18,
        "bands": "S0.330 C3.128", "within_reach": False, "slid": "R7", "wall_s": 120.5}
STOOD = {"lambda": 0.33, "contact_fraction": 1.0, "scan_top_g": 4.8, "amplitude_g": None, "mode": "none",
         "phase": "", "joint": "", "t_slip_s": math.nan, "slip_half": "", "n_sims": 9, "bands": "S0.330",
         "wall_s": 60.0}


@pytest.fixture
def synthetic():
    """(spec, study): Sh1-Sd015 at 8 Hz collapsed, at 10 Hz stood; Sh02-Sd015 at 8 Hz not run, at 10 Hz failed."""
    spec = ModeMapSpec(specimens=("Sh1-Sd015", "Sh02-Sd015"), freqs=(8.0, 10.0))
    cases = spec.cases()
    records = [CaseRecord(case_key(c), c, "ok", dict(out)) for c, out in zip(cases[:2], (FELL, STOOD))]
    records.append(CaseRecord(case_key(cases[3]), cases[3], "failed", {}, "Traceback: boom"))
    return spec, StudyResult(Path("synthetic.h5"), {}, records)
