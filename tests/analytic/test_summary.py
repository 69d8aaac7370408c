"""The multiplier series of the figures and the campaign: computed on a process pool, equal to
the serial computation and in the order given."""
import numpy as np

from analytic.summary import _series_row, multiplier_series
from specimens.catalogue import get_specimen


def test_parallel_series_equals_serial():
    specs = [get_specimen("Sh06-Sd015"), get_specimen("Sh1-Sd025")]
    par = multiplier_series(specs)
    ser = [_series_row(s) for s in specs]
    assert [r["id"] for r in par] == ["Sh06-Sd015", "Sh1-Sd025"]  # order kept
    for a, b in zip(par, ser):
        for k in ("cont", "cont08", "disc", "two_bar"):
            assert a[k] == b[k]  # same computation, bit for bit
        assert np.array_equal(np.asarray(a["polar"]), np.asarray(b["polar"]))
