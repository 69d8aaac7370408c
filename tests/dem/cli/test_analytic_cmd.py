"""``archdem analytic`` command line."""
import json

import pytest

from analytic.limit.limit_discrete import enumerate_mechanisms
from dem.cli import main
from specimens.blocks import discretise
from specimens.catalogue import get_specimen


def test_json_keys_and_values(capsys):
    assert main(["analytic", "Sh06-Sd015", "--config", "free", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    for key in ("lambda_continuous", "hinges_continuous", "lambda_discrete", "hinges_discrete", "lambda_lp",
                "joints_lp", "lambda_two_bar"):
        assert key in out
    assert len(out["hinges_continuous"]) == 4
    assert set(out["hinges_continuous"][0]) >= {"half", "angle_rad", "face"}
    assert [set(h) for h in out["hinges_discrete"]] == [{"joint", "face"}] * 4
    # the CLI reports the library's number (independent call)
    kin = enumerate_mechanisms(discretise(get_specimen("Sh06-Sd015").arch, config="free"))
    assert out["lambda_discrete"] == pytest.approx(kin.lam, rel=1e-12)
    assert out["lambda_lp"] <= out["lambda_discrete"] + 1e-9  # friction can only lower it


def test_params_and_unstable_arch(capsys):
    assert main(["analytic", "--Sh", "0.2", "--Sd", "0.03", "--Rc", "1", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["stands"] is False and out["lambda_continuous"] < 0


def test_bad_input_exit_2(capsys):
    assert main(["analytic", "Sh06-Sd015", "--effective-thickness", "1.5"]) == 2
    assert "effective-thickness" in capsys.readouterr().err
    assert main(["analytic", "nope"]) == 2
