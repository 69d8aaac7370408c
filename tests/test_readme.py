"""The README is the front door: at most 8 kB, and its Python example runs as written."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"


def test_readme_is_short():
    assert len(README.read_bytes()) <= 8000


def _python_example() -> str:
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)
    assert len(blocks) == 1
    return blocks[0]


def test_readme_python_example_names_no_file_of_the_repository():
    """The README says it runs in any folder: a path relative to the repository would break that."""
    code = _python_example()
    assert not re.search(r"[\"'][\w./-]*/[\w.-]+\.\w+[\"']", code), "a relative file path in the example"
    assert "example_record(" in code  # its record ships with the package


@pytest.mark.slow
def test_readme_python_example_runs_and_agrees_with_limit_analysis(tmp_path):
    # from a folder outside the repository, as the README promises (its record is package data)
    out = subprocess.run([sys.executable, "-c", _python_example()], cwd=tmp_path, capture_output=True, text=True,
                         timeout=600)
    assert out.returncode == 0, out.stderr
    lp = float(re.search(r"limit analysis: lambda = ([\d.]+)", out.stdout).group(1))
    lam = float(re.search(r"tilt test: +lambda = ([\d.]+)", out.stdout).group(1))
    # the tilt test's validation tolerance against the LP of the same blocks (docs/validation.md)
    assert abs(lam - lp) <= 0.03 * lp
    assert re.search(r"shake 4 Hz 0.5 g: (collapse|survival), \w+", out.stdout)
    # the assessment with a record: the code's verdict and the DEM's over the one record
    assert re.search(r"noh-gumbad, ring alone: code check (verified|NOT verified) \(safety index [\d.]+\); "
                     r"DEM over 1 record\(s\): .* -> (verified|NOT verified)", out.stdout)
