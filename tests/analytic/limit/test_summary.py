"""The multiplier series of the figures and the campaign: computed on a process pool, equal to
the serial computation and in the order given."""
import numpy as np
import pytest

from analytic.limit.summary import _series_row, multiplier_series
from specimens.catalogue import get_specimen


@pytest.mark.slow
def test_parallel_series_equals_serial():
    specs = [get_specimen("Sh06-Sd015"), get_specimen("Sh1-Sd025")]
    par = multiplier_series(specs)
    ser = [_series_row(s) for s in specs]
    assert [r["id"] for r in par] == ["Sh06-Sd015", "Sh1-Sd025"]  # order kept
    for a, b in zip(par, ser):
        for k in ("cont", "cont08", "disc", "two_bar"):
            assert a[k] == b[k]  # same computation, bit for bit
        assert np.array_equal(np.asarray(a["polar"]), np.asarray(b["polar"]))


@pytest.mark.slow
def test_analyse_with_the_series_continuous_result_equals_solving_it():
    """The campaign hands each specimen's series result to ``analyse`` instead of solving the
    profile twice: the answer must be the one ``analyse`` computes itself."""
    from analytic.limit.summary import analyse

    s = get_specimen("Sh06-Sd015")
    row = _series_row(s)
    own = analyse(s.arch, "glued", 0.577, 1.0)
    reused = analyse(s.arch, "glued", 0.577, 1.0, continuous=row["continuous"])
    assert reused == own
    # a result at another thickness is not the one asked for
    import pytest

    from analytic.limit.limit_continuous import continuous_collapse

    with pytest.raises(ValueError, match="thickness"):
        analyse(s.arch, "glued", 0.577, 1.0, continuous=continuous_collapse(s.arch, effective_thickness=0.8))
