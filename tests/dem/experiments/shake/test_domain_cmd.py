"""``archdem domain`` (dem/experiments/shake/domain_cmd.py) and ``archdem rock`` (dem/cli/rock_cmd.py)."""
from __future__ import annotations

import json
import math

import pytest

from dem.cli import main
from foundation.errors import ArchdemInputError
from foundation.io import parse_grid


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_domain_json_block(capsys):
    out = _json(capsys, ["domain", "--block", "0.1", "0.5", "--model", "block", "--input", "A",
                         "--durations", "0.2,0.4", "--scan", "10", "--tol", "1e-3", "--amax", "20",
                         "--workers", "1", "--json"])
    assert set(out) == {"restitution", "omega0", "phi_cr", "lambda", "points", "bands"}
    assert out["lambda"] == pytest.approx(0.2, rel=1e-12)  # b/h
    assert out["restitution"] == pytest.approx(1 - 1.5 * math.sin(math.atan(0.2)) ** 2, rel=1e-12)
    assert [p["x"] for p in out["points"]] == [0.2, 0.4]
    for p in out["points"]:
        assert set(p) == {"x", "amplitude_g", "mode"} and p["mode"] in ("first-half-cycle", "after-impact")


def test_domain_json_arch_oppenheim(capsys):
    out = _json(capsys, ["domain", "Sh06-Sd015", "--layout", "oppenheim", "--freq", "2:3:1", "--scan", "12",
                         "--tol", "1e-2", "--workers", "1", "--restitution", "0.9", "--json"])
    from analytic.rocking.linkage import arch_four_bar, oppenheim_hinges
    from specimens.catalogue import get_specimen

    arch = get_specimen("Sh06-Sd015").arch
    assert out["restitution"] == 0.9
    assert out["lambda"] == pytest.approx(arch_four_bar(arch, oppenheim_hinges(arch)).lam, rel=1e-12)
    assert [p["x"] for p in out["points"]] == [2.0, 3.0]  # a collapse found at both frequencies
    assert all(p["amplitude_g"] >= out["lambda"] for p in out["points"])  # none below the static onset


def test_rock_plot_and_json(tmp_path, capsys):
    png = tmp_path / "r.png"
    out = _json(capsys, ["rock", "--block", "0.1", "0.5", "--model", "block", "--input", "sine", "--freq", "2",
                         "--amplitude", "0.3", "--plot", str(png), "--json"])
    assert png.stat().st_size > 1000
    # the library's answer for the same block and input
    from analytic.rocking.domain import make_input
    from analytic.rocking.dynamics import simulate
    from analytic.rocking.rocking_block import RockingBlock
    from specimens.constants import G

    blk = RockingBlock(0.1, 0.5)
    lib = simulate(blk, make_input("sine", 0.3 * G, 2.0, abs(blk.onset))).summary()
    assert {k: out[k] for k in lib} == lib
    # 0.3 g > onset 0.2 g: it rocks and impacts, each with Housner's 1 - 1.5 sin^2(alpha), tan(alpha) = b/h
    assert out["t_start"] is not None and out["n_impacts"] >= 1
    e_housner = 1 - 1.5 * math.sin(math.atan(0.2)) ** 2
    assert [i["e"] for i in out["impacts"]] == pytest.approx([e_housner] * out["n_impacts"], rel=1e-12)
    assert main(["rock", "--block", "0.1", "0.5", "--freq", "2", "--amplitude", "0.3", "--plot", str(png)]) == 2  # never overwrite


@pytest.mark.slow
def test_domain_plot(tmp_path, capsys):
    png = tmp_path / "d.png"
    assert main(["domain", "--block", "0.1", "0.5", "--freq", "2,4", "--scan", "8", "--tol", "1e-2",
                 "--workers", "1", "--plot", str(png)]) == 0
    assert png.stat().st_size > 1000


@pytest.mark.parametrize("argv", [
    ["domain", "--block", "0.1", "0.5", "--freq", "a:b"],
    ["domain", "--block", "0.1", "0.5", "--restitution", "1.5"],
    ["domain", "--block", "0.1", "0.5", "--input", "A", "--freq", "2"],
    ["domain", "Sh06-Sd015", "--block", "0.1", "0.5"],
    ["domain", "Sh06-Sd015", "--layout", "1,2"],
    ["domain", "--block", "0.1", "0.5", "--engine", "dem"],
    ["rock", "--block", "0.1", "0.5", "--freq", "2"],
    ["rock", "--block", "0.1", "0.5", "--freq", "2", "--amplitude", "0.1"],
])
def test_bad_input_exit_2(argv, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("archdem: error:") and len(err.strip().splitlines()) == 1


def test_parse_grid():
    assert parse_grid("1:2:0.5") == [1.0, 1.5, 2.0]
    assert parse_grid("0.5,1,2") == [0.5, 1.0, 2.0]
    with pytest.raises(ArchdemInputError):
        parse_grid("2:1:0.5")


def test_rock_record(capsys):
    from pathlib import Path

    rec = Path(__file__).resolve().parents[3] / "data" / "ground_motions" / "RSN6_IMPVALL.I_I-ELC180.AT2"
    if not rec.exists():
        pytest.skip("ground-motion test data not present")
    out = _json(capsys, ["rock", "--block", "0.2", "1.0", "--record", str(rec), "--scale", "2.0", "--json"])
    # El Centro peak 0.28 g x 2 = 0.56 g > onset 0.2 g: the block rocks
    assert out["t_start"] is not None and out["input"]["scale"] == 2.0
    assert main(["rock", "--block", "0.2", "1.0", "--record", str(rec)]) == 2  # --scale required
