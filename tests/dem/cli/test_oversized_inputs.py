"""Inputs far past the bounds of a record or a drawing are refused in one line within a second of
computing, before they are parsed: a record of 10 million samples, /dev/zero, a drawing 5e9 m across
or of 5000 blocks (docs/decisions/010-input-rules.md#record-size-and-run-length)."""
import os
import time

import pytest

from dem.cli import main


def _refused_at_once(argv, says, capsys):
    t0 = time.process_time()  # CPU seconds: on shared cores the wall time measures the neighbours
    assert main(argv) == 2
    cpu = time.process_time() - t0
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and says in err, err
    assert cpu < 1.0, f"refused after {cpu:.2f} s of computing"


def test_a_record_of_ten_million_samples_is_refused_before_it_is_parsed(tmp_path, capsys):
    # 4 bytes a sample: under the 64 MB of a record file, so its count of samples refuses it
    big = tmp_path / "big.csv"
    big.write_bytes(b"t [s],a [g]\n" + b"0,0\n" * 10_000_000)
    _refused_at_once(["record", str(big)], "big.csv: 10000001 non-blank lines, more than the 1000000 samples a record "
                                           "may hold", capsys)


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero here")
def test_dev_zero_is_refused_after_64_mb(capsys):
    _refused_at_once(["record", "/dev/zero"], "holds more than the 64 MB a record file may have", capsys)


@pytest.mark.parametrize("rows, says", [
    ([("b", 0, 0), ("b", 5e9, 0), ("b", 5e9, 1), ("b", 0, 1)], "the drawing is 5e+09 m across"),
    ([(f"b{k}", x + k * 0.2, z) for k in range(5000) for x, z in ((0, 0), (0.1, 0), (0.1, 0.1), (0, 0.1))],
     "the drawing holds 5000 blocks"),
], ids=["5e9 m across", "5000 blocks"])
def test_a_drawing_too_large_is_refused_naming_it(rows, says, tmp_path, capsys):
    f = tmp_path / "drawing.csv"
    f.write_text("block,x,z,layer\n" + "".join(f"{b},{x},{z},depth 0.1\n" for b, x, z in rows))
    _refused_at_once(["analytic", "--geometry", str(f)], f"drawing.csv: {says}", capsys)
