"""Fragility statistics: exact binomial intervals, the lognormal maximum-likelihood fit against a
brute-force likelihood and against a known curve."""
import numpy as np
import pytest
from scipy.stats import binomtest, norm

from analytic.codes.fragility import _nll, fit_lognormal, stripes
from foundation.errors import ArchdemInputError


def test_stripes_group_runs_with_exact_intervals():
    s = stripes([0.2, 0.1, 0.2, 0.2, 0.1], [True, False, False, True, False], ["a", "b", "c", "a", "b"])
    assert [x.intensity for x in s] == [0.1, 0.2] and [(x.n, x.k) for x in s] == [(2, 0), (3, 2)]
    ci = binomtest(2, 3).proportion_ci(0.95, "exact")
    assert s[1].ci == pytest.approx((ci.low, ci.high)) and s[1].modes == {"a": 2, "c": 1}


def test_the_fit_maximises_the_likelihood_and_finds_a_known_curve():
    rng = np.random.default_rng(7)
    x = np.repeat(np.linspace(0.3, 0.7, 9), 60)
    c = rng.random(len(x)) < norm.cdf(np.log(x / 0.5) / 0.15)
    pts = stripes(x, c)
    f = fit_lognormal(pts, n_boot=100)
    assert f.median == pytest.approx(0.5, rel=0.03) and f.beta == pytest.approx(0.15, rel=0.3)
    assert f.median_ci[0] < f.median < f.median_ci[1] and f.beta_ci[0] < f.beta < f.beta_ci[1]
    # no point of a fine grid around the optimum has a higher likelihood
    lx = np.log([p.intensity for p in pts])
    n = np.array([p.n for p in pts], float)
    k = np.array([p.k for p in pts], float)
    best = _nll(np.array([np.log(f.median), np.log(f.beta)]), lx, n, k)
    grid = [_nll(np.array([np.log(f.median) + dm, np.log(f.beta) + db]), lx, n, k)
            for dm in np.linspace(-0.02, 0.02, 9) for db in np.linspace(-0.2, 0.2, 9)]
    assert best <= min(grid) + 1e-9


def test_a_study_that_never_collapses_cannot_be_fitted():
    with pytest.raises(ArchdemInputError, match="every run survived: widen the intensities"):
        fit_lognormal(stripes([0.1, 0.2], [False, False]))


def test_separated_stripes_only_bracket_the_median():
    f = fit_lognormal(stripes([0.30, 0.34, 0.35, 0.40], [False, False, True, True]))
    assert f.separated and f.median_ci == (0.34, 0.35) and f.median == pytest.approx((0.34 * 0.35) ** 0.5)
    assert f.beta_ci[1] == pytest.approx(np.log(0.35 / 0.34))
