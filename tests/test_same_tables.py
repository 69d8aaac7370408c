"""The cell-by-cell comparison of two campaigns' tables that `make test-py313` runs across Pythons."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

TOOL = Path(__file__).resolve().parents[1] / ".ci" / "same_tables.py"


@pytest.fixture(scope="module")
def same_tables():
    spec = importlib.util.spec_from_file_location("same_tables", TOOL)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _run(root: Path, points: str) -> Path:
    (root / "map").mkdir(parents=True)
    (root / "map" / "map_points.csv").write_text(points)
    return root


POINTS = "id,mu,lambda,mode,wall_s\nSh02-Sd020,0.3,0.18670013069175953,sliding,8.39\n"


def test_equal_tables_pass_and_wall_times_are_not_compared(same_tables, tmp_path, capsys):
    a = _run(tmp_path / "a", POINTS)
    b = _run(tmp_path / "b", POINTS.replace("8.39", "12.7"))
    assert same_tables.main([str(a), str(b), "map/map_points.csv"]) == 0
    assert "1 tables, 5 cells: identical" in capsys.readouterr().out


def test_a_cell_one_ulp_apart_is_a_difference_with_its_size(same_tables, tmp_path, capsys):
    a = _run(tmp_path / "a", POINTS)
    b = _run(tmp_path / "b", POINTS.replace("0.18670013069175953", "0.18670013069175956"))
    assert same_tables.main([str(a), str(b), "map/map_points.csv"]) == 1
    out = capsys.readouterr().out
    assert "map_points.csv row 1 lambda: 0.18670013069175953 vs 0.18670013069175956" in out
    assert "relative difference 1.49e-16" in out


def test_changed_columns_rows_and_words_are_differences(same_tables, tmp_path):
    a = _run(tmp_path / "a", POINTS)
    assert same_tables.differences(a / "map" / "map_points.csv",
                                   _run(tmp_path / "b", POINTS.replace("mode", "state")) / "map" / "map_points.csv")
    c = _run(tmp_path / "c", POINTS + POINTS.splitlines()[1] + "\n")
    assert same_tables.differences(a / "map" / "map_points.csv", c / "map" / "map_points.csv") == [
        "map_points.csv: 1 rows vs 2"]
    d = _run(tmp_path / "d", POINTS.replace("sliding", "rocking"))
    assert same_tables.differences(a / "map" / "map_points.csv", d / "map" / "map_points.csv") == [
        "map_points.csv row 1 mode: sliding vs rocking"]


def test_a_missing_table_is_exit_2(same_tables, tmp_path, capsys):
    a = _run(tmp_path / "a", POINTS)
    assert same_tables.main([str(a), str(tmp_path / "none"), "map/map_points.csv"]) == 2
    assert "cannot read map/map_points.csv" in capsys.readouterr().err


def test_every_wall_time_column_is_left_out(same_tables, tmp_path):
    """The campaign's wall-time columns (a run's, the threshold checks', the solve without dilatancy's) differ
    from one machine to the next: they are no result to compare."""
    header = "id,a_dem_g,wall_s,check_wall_s,seconds_na\n"
    for name, row in (("a", "x,0.5,1.0,2.0,3.0\n"), ("b", "x,0.5,1.1,2.2,3.3\n")):
        (tmp_path / name / "shake").mkdir(parents=True)
        (tmp_path / name / "shake" / "shake.csv").write_text(header + row)
    assert same_tables.differences(tmp_path / "a" / "shake" / "shake.csv", tmp_path / "b" / "shake" / "shake.csv") == []
