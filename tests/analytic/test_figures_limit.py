"""Limit-analysis figures: the per-specimen series computed on a process pool equal the serial ones."""
import numpy as np

from analytic.figures_limit import _series, _series_row
from specimens.catalogue import get_specimen


def test_parallel_series_equals_serial():
    specs = [get_specimen("Sh06-Sd015"), get_specimen("Sh1-Sd025")]
    par = _series(specs, with_discrete=True)
    ser = [_series_row((s, True)) for s in specs]
    assert [r["id"] for r in par] == ["Sh06-Sd015", "Sh1-Sd025"]  # order kept
    for a, b in zip(par, ser):
        for k in ("cont", "cont08", "disc", "two_bar"):
            assert a[k] == b[k]  # same computation, bit for bit
        assert np.array_equal(np.asarray(a["polar"]), np.asarray(b["polar"]))
