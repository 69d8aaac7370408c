"""``--table-speed``: a one-cycle sine through a table whose servo cannot exceed a speed
(analytic/motions/table.py) runs through ``archdem shake`` and is refused where it means nothing."""
import json

import pytest

from dem.cli import main


def test_table_speed_is_refused_where_it_means_nothing(capsys, tmp_path):
    cases = [
        ["shake", "Sh1-Sd015", "--sine", "8", "--amplitude", "3", "--table-speed", "0", "--out", str(tmp_path)],
        ["shake", "Sh1-Sd015", "--sine", "8", "--amplitude", "3", "--table-speed", "nan", "--out", str(tmp_path)],
        ["threshold", "Sh1-Sd015", "--sine", "8", "--table-speed", "-1"],
    ]
    for c in cases:
        assert main(c) == 2, c
    assert capsys.readouterr().err.count("--table-speed") == len(cases)


@pytest.mark.slow
def test_a_shake_on_the_speed_limited_table_runs_and_reports_a_mode(capsys, tmp_path):
    # 3.4 g at 8 Hz asks 1.35 m/s of the table: the laboratory's 1 m/s servo cannot follow it
    args = ["shake", "Sh1-Sd015", "--sine", "8", "--amplitude", "3.4", "--json", "--out", str(tmp_path)]
    assert main(args + ["--table-speed", "1"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["input"]["kind"] == "record" and "v_max 1 m/s" in s["input"]["source"]
    assert s["pga_g"] <= 3.4 + 1e-6
    assert s["mode"] in ("rocking", "mixed", "sliding")
    assert s["collapsed"] and s["collapse_phase"] in ("before-first-rebound", "after-first-rebound")
    assert main(args) == 0  # the ideal sine, for contrast: another motion
    assert json.loads(capsys.readouterr().out)["input"]["kind"] == "sine"
