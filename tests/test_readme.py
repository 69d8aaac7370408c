"""The README is the front door: at most 8 kB, and its Python example runs as written."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_is_short():
    assert len(README.read_bytes()) <= 8000


@pytest.mark.slow
def test_readme_python_example_runs_and_agrees_with_limit_analysis(tmp_path):
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)
    assert len(blocks) == 1
    out = subprocess.run([sys.executable, "-c", blocks[0]], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    lp = float(re.search(r"limit analysis: lambda = ([\d.]+)", out.stdout).group(1))
    lam = float(re.search(r"tilt test: +lambda = ([\d.]+)", out.stdout).group(1))
    # the tilt test's validation tolerance against the LP of the same blocks (docs/validation.md)
    assert abs(lam - lp) <= 0.03 * lp
    assert re.search(r"shake 4 Hz 0.5 g: (collapse|survival), \w+", out.stdout)
