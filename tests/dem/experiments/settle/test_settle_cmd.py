"""``archdem settle``: the JSON object is the result's row; bad input is one line, exit 2."""
import json

import pytest

from dem.cli import main
from dem.experiments.settle.run import SettleResult


def test_settle_json_is_the_result_row(capsys):
    assert main(["settle", "Sh02-Sd020", "--duration", "0.3", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert list(out) == SettleResult.SCHEMA.names
    assert out["id"] == "Sh02-Sd020" and out["duration_s"] == 0.3 and out["at_rest"] is True
    assert out["max_displacement_mm"] < 1.0


@pytest.mark.parametrize("argv, msg", [
    (["settle", "Nope"], "unknown specimen"),
    (["settle", "Sh02-Sd020", "--duration", "0"], "settle duration"),
])
def test_bad_input_is_one_line(argv, msg, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and msg in err
