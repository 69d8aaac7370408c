"""``archdem modes``: frequencies of an arch or a block, and the mode-shape figure."""
import json
import math

import pytest

from dem.cli import main


def test_modes_json_and_plot(tmp_path, capsys):
    assert main(["modes", "--block", "0.05", "0.2", "--kn", "4.34e8", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    m = 500 * 0.1 * 0.1 * 0.4
    assert d["frequencies_hz"][1] == pytest.approx(math.sqrt(4.34e8 * 0.1 * 0.1 / m) / (2 * math.pi))
    png = tmp_path / "m.png"
    assert main(["modes", "Sh06-Sd015", "--kn", "4.34e8", "--count", "5", "--plot", str(png), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert len(d["frequencies_hz"]) == 5 and d["n_modes"] == 45 and png.stat().st_size > 0
    assert d["frequencies_hz"] == sorted(d["frequencies_hz"])
