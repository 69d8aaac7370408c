"""The experiment contract: typed tables written once and read back typed, and the registry from which
the program's commands, the campaign's steps and the report's summary come."""
import csv
import json
import math
from pathlib import Path

import pytest

from dem.common.tables import (
    Column,
    Schema,
    fmt,
    infer_schema,
    read_csv,
    schema_path,
    table_html,
    to_json_rows,
    write_csv,
    write_h5_group,
)
from dem.experiments.contract import Experiment, Step, given_options, resolve
from dem.experiments.registry import DECLARED, commands, experiments, steps, summaries

SCHEMA = Schema((Column("id", "str"), Column("a_g", "float", "g"), Column("n", "int"), Column("ok", "bool"),
                 Column("extra", "json")))
ROWS = [{"id": "A", "a_g": 0.1, "n": 3, "ok": True, "extra": {"k": [1, 2]}},
        {"id": "B", "a_g": math.nan, "n": None, "ok": False, "extra": None}]


def _same(a, b) -> bool:
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))


def test_a_declared_table_reads_back_typed(tmp_path):
    write_csv(tmp_path / "t.csv", ROWS, SCHEMA)
    schema, rows = read_csv(tmp_path / "t.csv")
    assert schema == SCHEMA and schema_path(tmp_path / "t.csv").name == "t.schema.json"
    assert all(_same(rows[i][k], ROWS[i][k]) for i in range(2) for k in SCHEMA.names)
    assert rows[0]["ok"] is True and rows[1]["n"] is None
    with open(tmp_path / "t.csv", newline="") as fh:
        text = list(csv.reader(fh))
    assert text[1:] == [["A", "0.1", "3", "True", '{"k": [1, 2]}'], ["B", "nan", "", "False", ""]]


def test_rows_without_a_schema_are_written_as_before_with_their_inferred_kinds(tmp_path):
    rows = [{"id": "A", "x": 1, "y": 0.5, "flag": True, "lab": 0.3, "mixed": "a", "n": 2},
            {"id": "B", "x": 2.5, "y": 1.0, "flag": False, "lab": "", "mixed": 1.5, "n": 7}]
    schema = infer_schema(rows)
    assert [c.kind for c in schema.columns] == ["str", "float", "float", "bool", "float", "str", "int"]
    write_csv(tmp_path / "t.csv", rows)
    with open(tmp_path / "t.csv", newline="") as fh:
        assert fh.read() == "id,x,y,flag,lab,mixed,n\r\nA,1,0.5,True,0.3,a,2\r\nB,2.5,1.0,False,,1.5,7\r\n"
    _, typed = read_csv(tmp_path / "t.csv")
    assert typed[1] == {"id": "B", "x": 2.5, "y": 1.0, "flag": False, "lab": None, "mixed": "1.5", "n": 7}


def test_a_table_written_before_schemas_reads_with_kinds_from_its_text(tmp_path):
    (tmp_path / "old.csv").write_text("id,lam,ok\nA,0.4,True\nB,nan,False\n")
    schema, rows = read_csv(tmp_path / "old.csv")
    assert [c.kind for c in schema.columns] == ["str", "float", "bool"]
    assert rows[0] == {"id": "A", "lam": 0.4, "ok": True} and math.isnan(rows[1]["lam"])


def test_a_schema_refuses_rows_of_other_columns_and_a_file_of_other_columns(tmp_path):
    with pytest.raises(ValueError, match="not the schema's"):
        write_csv(tmp_path / "t.csv", [{"id": "A"}], SCHEMA)
    (tmp_path / "u.csv").write_text("id,b\nA,1\n")
    with pytest.raises(ValueError, match="not the schema's"):
        read_csv(tmp_path / "u.csv", SCHEMA)
    with pytest.raises(ValueError, match="kind"):
        Column("x", "complex")


def test_json_html_and_hdf5_from_the_one_schema(tmp_path):
    h5py = pytest.importorskip("h5py")
    assert json.loads(json.dumps(to_json_rows(ROWS[:1], SCHEMA))) == ROWS[:1]
    page = table_html(ROWS, SCHEMA, "T", "t")
    assert '<th title="g">a_g</th>' in page and "<td>–</td>" in page and "<td>True</td>" in page
    with h5py.File(tmp_path / "t.h5", "w") as f:
        write_h5_group(f.create_group("t"), ROWS, SCHEMA)
    with h5py.File(tmp_path / "t.h5", "r") as f:
        g = f["t"]
        assert g["ok"].dtype.kind == "b" and g["ok"][()].tolist() == [True, False]
        assert g["a_g"].attrs["unit"] == "g" and g["a_g"][0] == 0.1 and math.isnan(g["a_g"][1])
        assert math.isnan(g["n"][1]) and g["n"][0] == 3  # a missing whole number: float with NaN
        assert [v.decode() for v in g["extra"][()]] == ['{"k": [1, 2]}', ""]


@pytest.mark.parametrize("value, shown", [(0.123456, "0.1235"), (2.0, "2"), (1234567, "1.235e+06"), (12, "12"),
                                          (math.nan, "–"), (None, ""), (True, "True"), ("a<b", "a&lt;b"),
                                          ("0.2389586202248558", "0.239"), ("5", "5"), ("nan", "–")])
def test_cells_show_as_the_report_always_showed_them(value, shown):
    assert fmt(value) == shown


# ----------------------------------------------------------------------------- the registry
def test_the_campaign_runs_its_steps_in_today_s_order():
    from dem.campaign.runner import OPTIONAL_STEPS, STEPS, default_steps

    assert list(STEPS) == ["catalogue", "analytic", "modes", "tilt", "lab", "map", "shake", "record", "piers", "assess",
                           "fragility", "drawing", "settle", "mode-map"]
    assert OPTIONAL_STEPS == ("piers", "fragility", "drawing", "settle", "mode-map")
    assert default_steps() == ["catalogue", "analytic", "modes", "tilt", "lab", "map", "shake", "record", "assess"]
    assert [s.name for s in steps()] == list(STEPS)[2:]


def test_every_declaration_names_modules_of_its_own_folder():
    root = Path(__file__).resolve().parents[3] / "dem" / "experiments"
    assert len(experiments()) == len(DECLARED) and all(isinstance(e, Experiment) for e in experiments())
    for module, e in zip(DECLARED, experiments()):
        folder = f"dem.experiments.{e.name}."
        assert module == folder + "experiment" and (root / e.name / "experiment.py").is_file()
        for path in e.commands + tuple(s.function for s in e.steps):
            assert path.startswith(folder), f"{e.name} declares {path}, outside its folder"
        for s in e.steps:
            # a step's name may hold a hyphen (mode-map); its function's, an underscore
            assert callable(s.load()) and s.load().__name__ == f"step_{s.name.replace('-', '_')}"
    names = [s.name for s in steps()]
    assert len(set(names)) == len(names) and not {"catalogue", "analytic"} & set(names)


def test_the_program_lists_every_experiment_s_commands():
    import argparse

    from dem.cli import build_parser

    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction)).choices
    assert {"settle", "tilt", "calibrate", "shake", "modes", "record", "assess", "fragility", "map"} <= set(sub)
    assert len(commands()) == len(set(commands())) and all(hasattr(resolve(m), "register") for m in commands())
    assert list(sub)[:6] == ["specimens", "mesh", "draw", "analytic", "rock", "campaign"]


def test_the_summary_comes_from_the_declarations_and_typed_rows():
    from dem.campaign.report import _summary_html

    assert [p.columns for p in summaries() if p.columns] == [
        ("lambda laboratory", "lambda limit analysis", "lambda DEM"), ("least shake threshold (DEM)",)]
    tables = {"assess": [{"configuration": "vault", "frp": True, "lambda": 0.2, "a0_over_pga_published_convention": None,
                          "safety_index_linear": 1.5, "safety_index_displacement": 0.8, "verified": False}]}
    page = _summary_html(tables)
    assert "Per specimen" not in page
    assert "<tr><td>vault</td><td>yes</td><td>0.2</td><td></td><td>1.5</td><td>0.8</td><td>NOT verified</td></tr>" in page
    assert _summary_html({}) == "<p>No step with per-specimen results was run.</p>"


def test_a_step_named_twice_in_an_experiment_is_refused():
    with pytest.raises(ValueError, match="named twice"):
        Experiment("x", "x", steps=(Step("a", "m:f", "a", 1), Step("a", "m:g", "a", 2)))


def test_the_options_given_by_hand_count_a_default_typed_and_leave_the_parser_as_it_was():
    import argparse

    parser = argparse.ArgumentParser()
    cmd = parser.add_subparsers(dest="command").add_parser("run")
    cmd.add_argument("--seed", type=int, default=0)
    cmd.add_argument("--out", default="runs")
    argv = ["run", "--seed", "0"]
    assert given_options(parser, argv, "run") == {"seed"}
    assert vars(parser.parse_args(argv)) == {"command": "run", "seed": 0, "out": "runs"}


def test_a_spec_option_takes_its_aliases_and_shown_default():
    import argparse
    from dataclasses import dataclass, field

    from dem.experiments.contract import add_spec_options

    @dataclass(frozen=True)
    class Spec:
        realizations: int | None = field(default=None, metadata={"help": "runs", "aliases": ("--realisations",)})
        scatter: float | None = field(default=None, metadata={"help": "arch: scatter", "unit": "mm", "shown": 0.3})

    p = argparse.ArgumentParser()
    add_spec_options(p, Spec)
    assert p.parse_args(["--realisations", "3"]).realizations == 3
    assert p.parse_args(["--realizations", "4"]).realizations == 4 and p.parse_args([]).scatter is None
    assert "arch: scatter [mm] (default 0.3)" in " ".join(p.format_help().split())
