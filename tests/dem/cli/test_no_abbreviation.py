"""An option a command does not have is refused, not read as the one it abbreviates: ``--engine`` is
not ``--engines``, ``--e`` (an arch's eccentricity) is not ``--experiments`` or ``--engine``."""
import pytest

from dem.cli import main


@pytest.mark.parametrize("argv", [
    ["compare-engines", "--engine", "pybullet"],
    ["compare-shake", "--engine", "pybullet"],
    ["calibrate", "--e", "0.2"],
    ["map", "--specimens", "Sh02-Sd020", "--e", "0.2"],
    ["tilt", "Sh02-Sd020", "--ensem", "2"],
])
def test_an_abbreviated_option_is_refused(argv, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "unrecognized arguments: " + " ".join(argv[-2:]) in err, err
    assert list(tmp_path.iterdir()) == []
