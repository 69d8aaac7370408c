"""A damaged drawing on the command line: one line on stderr naming the file, exit 2, nothing written
(docs/decisions/010-input-rules.md)."""
import subprocess
import sys

import pytest

from dem.cli import main
from specimens.exchange import EXAMPLE_DRAWING


@pytest.mark.parametrize("cmd", [["modes", "--kn", "1e8"], ["draw", "--out", "x.png"], ["analytic"]])
def test_the_cli_says_a_truncated_dxf_in_one_line_with_exit_2(tmp_path, monkeypatch, capsys, cmd):
    p = tmp_path / "truncated.dxf"
    p.write_bytes(EXAMPLE_DRAWING.read_bytes()[:3000])
    monkeypatch.chdir(tmp_path)
    assert main([cmd[0], "--geometry", str(p), *cmd[1:]]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "truncated.dxf: not a readable DXF file" in err
    assert not (tmp_path / "x.png").exists()


@pytest.mark.slow
def test_archdem_in_its_own_process_says_a_truncated_dxf_in_one_line(tmp_path):
    p = tmp_path / "truncated.dxf"
    p.write_bytes(EXAMPLE_DRAWING.read_bytes()[:3000])
    r = subprocess.run([sys.executable, "-m", "dem.cli", "modes", "--geometry", str(p), "--kn", "1e8"], cwd=tmp_path,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "truncated.dxf: not a readable DXF file, truncated or damaged" in r.stderr
