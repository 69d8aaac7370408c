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


@pytest.mark.slow
def test_analyse_adds_the_non_associative_collapse_of_the_same_blocks_only_when_asked():
    """``non_associative=True``: the library's solve on the blocks and frictions of the LP entry, beside it;
    the default leaves the dict as it was. The same for a drawing."""
    import math

    from analytic.limit.non_associative import solve_non_associative
    from analytic.limit.summary import analyse, analyse_drawing
    from specimens import discretise, read_assembly
    from specimens.exchange import EXAMPLE_DRAWING

    s = get_specimen("Sh02-Sd025")
    row = _series_row(s)
    plain = analyse(s.arch, "free", 0.577, 1.0, continuous=row["continuous"])
    both = analyse(s.arch, "free", 0.577, 1.0, continuous=row["continuous"], non_associative=True)
    assert "non_associative" not in plain
    na = both.pop("non_associative")
    assert both == plain  # nothing else changes
    lib = solve_non_associative(discretise(s.arch, config="free"), 0.577, 1.0)
    assert na["lambda_non_associative"] == pytest.approx(lib.lam, rel=1e-9)
    assert na["lambda_associative"] == pytest.approx(plain["lambda_lp"], rel=1e-9)
    assert na["lambda_non_associative"] < plain["lambda_lp"]  # its LP collapse slides and dilates
    asm = read_assembly(EXAMPLE_DRAWING)
    d = analyse_drawing(asm, 0.577, 1.0, non_associative=True)
    assert d["non_associative"]["lambda_associative"] == pytest.approx(d["lambda_lp"], rel=1e-9)
    assert d["non_associative"]["lambda_non_associative"] <= d["lambda_lp"] * (1 + 1e-9)
    assert d["non_associative"]["optimal"] and math.isfinite(d["non_associative"]["lambda_non_associative"])
    assert "non_associative" not in analyse_drawing(asm, 0.577, 1.0)
