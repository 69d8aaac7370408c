"""Fragility: the probability of collapse given an intensity, from stripes of runs
(docs/physics/fragility.md).

A **stripe** is ``n`` runs at one intensity ``x`` (sine amplitude, or a record's intensity measure),
``k`` of them collapsing: ``p = k / n`` with the exact (Clopper-Pearson) binomial interval. The
**lognormal fragility** ``P(collapse | x) = Phi(ln(x / theta) / beta)`` is fitted by maximum
likelihood over all stripes::

    max over (theta, beta) of  sum_j [ k_j ln P(x_j) + (n_j - k_j) ln(1 - P(x_j)) ]

and its intervals come from a bootstrap that redraws each stripe's outcomes from its observed
proportion (``n_boot`` replicates, the 2.5 / 97.5 percentiles). Stripes that are all-or-nothing and in
order (``separated``) only bracket the median: it is reported as the geometric middle of the two
stripes, its interval as the two stripes, and beta as below their spacing.
"""
from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np
from scipy.optimize import minimize
from scipy.special import log_ndtr
from scipy.stats import binomtest, norm

from foundation.errors import ArchdemInputError

#: Confidence level of the stripes' binomial intervals and of the bootstrap intervals.
CONFIDENCE = 0.95
#: Bootstrap replicates of the fit's intervals.
N_BOOT = 400
#: Smallest dispersion the fit reports [-]: below it the stripes cannot tell a step from a curve.
BETA_MIN = 1e-3


@dataclass(frozen=True)
class Stripe:
    """``n`` runs at ``intensity``, ``k`` collapsed: ``p``, exact interval ``ci``, ``modes`` (mode -> count)."""

    intensity: float
    n: int
    k: int
    ci: tuple[float, float]
    modes: dict = field(default_factory=dict)

    @property
    def p(self) -> float:
        return self.k / self.n

    def describe(self) -> dict:
        return {"intensity": self.intensity, "n_runs": self.n, "n_collapsed": self.k, "p": self.p,
                "ci_low": self.ci[0], "ci_high": self.ci[1], "modes": dict(self.modes)}


def stripes(intensity: Sequence[float], collapsed: Sequence[bool], modes: Sequence[str] | None = None) -> list[Stripe]:
    """Group runs by intensity (sorted) into stripes with their binomial intervals."""
    x = np.asarray(intensity, float)
    c = np.asarray(collapsed, bool)
    if len(x) != len(c) or len(x) == 0:
        raise ArchdemInputError("a fragility needs at least one run, with one outcome per intensity")
    out = []
    for v in np.unique(x):
        sel = x == v
        n, k = int(sel.sum()), int(c[sel].sum())
        ci = binomtest(k, n).proportion_ci(CONFIDENCE, "exact")
        m = Counter(np.asarray(modes)[sel].tolist()) if modes is not None else Counter()
        out.append(Stripe(float(v), n, k, (float(ci.low), float(ci.high)), dict(m)))
    return out


def _nll(params: np.ndarray, lx: np.ndarray, n: np.ndarray, k: np.ndarray) -> float:
    mu, lb = params
    z = (lx - mu) / math.exp(lb)
    return -float(np.sum(k * log_ndtr(z) + (n - k) * log_ndtr(-z)))


def _mle(lx: np.ndarray, n: np.ndarray, k: np.ndarray, start: tuple[float, float] | None = None) -> tuple[float, float]:
    p = (k + 0.5) / (n + 1.0)
    mu0 = float(np.interp(0.5, p, lx)) if np.all(np.diff(p) >= 0) else float(np.mean(lx))
    spread = float(np.ptp(lx)) or 0.1
    best = None
    starts = (0.05 * spread + 1e-3, 0.3 * spread + 1e-3, spread)
    if start is not None:  # a bootstrap replicate starts from the fit it perturbs
        mu0, starts = math.log(start[0]), (start[1],)
    for b0 in starts:
        r = minimize(_nll, np.array([mu0, math.log(b0)]), args=(lx, n, k), method="Nelder-Mead",
                     options={"xatol": 1e-9, "fatol": 1e-11, "maxiter": 4000})
        if best is None or r.fun < best.fun:
            best = r
    mu, lb = best.x
    return math.exp(mu), max(math.exp(lb), BETA_MIN)


@dataclass(frozen=True)
class LognormalFit:
    """``median`` (theta, intensity units) and ``beta`` of ``Phi(ln(x / theta) / beta)`` with bootstrap
    intervals ``median_ci``, ``beta_ci``; ``n_runs``."""

    median: float
    beta: float
    median_ci: tuple[float, float]
    beta_ci: tuple[float, float]
    n_runs: int
    separated: bool = False

    def probability(self, x) -> np.ndarray:
        return norm.cdf(np.log(np.asarray(x, float) / self.median) / self.beta)

    def describe(self) -> dict:
        return {"median": self.median, "beta": self.beta, "median_ci": list(self.median_ci),
                "beta_ci": list(self.beta_ci), "n_runs": self.n_runs, "separated": self.separated}


def fit_lognormal(points: Sequence[Stripe], n_boot: int = N_BOOT, seed: int = 0) -> LognormalFit:
    """Maximum-likelihood lognormal fragility of ``points`` with bootstrap intervals (module doc).
    Needs at least one run that collapsed and one that did not."""
    x = np.array([s.intensity for s in points], float)
    n = np.array([s.n for s in points], float)
    k = np.array([s.k for s in points], float)
    if np.any(x <= 0):
        raise ArchdemInputError("fragility intensities must be positive")
    if k.sum() == 0 or k.sum() == n.sum():
        raise ArchdemInputError("every run " + ("survived" if k.sum() == 0 else "collapsed")
                                + ": widen the intensities to bracket collapse before a fragility can be fitted")
    lx = np.log(x)
    p = k / n
    if np.all((p == 0) | (p == 1)) and np.all(np.diff(p) >= 0):
        # every stripe all-or-nothing, in order: the likelihood is flat for any median between the
        # bracketing stripes and beta below their spacing; say so rather than report the optimiser's pick
        j = int(np.argmax(p == 1))
        lo, hi = float(x[j - 1]), float(x[j])
        return LognormalFit(math.sqrt(lo * hi), BETA_MIN, (lo, hi), (0.0, math.log(hi / lo)), int(n.sum()), True)
    med, beta = _mle(lx, n, k)
    rng = np.random.default_rng(seed)
    meds, betas = [], []
    for _ in range(int(n_boot)):
        kb = rng.binomial(n.astype(int), k / n).astype(float)
        if kb.sum() == 0 or kb.sum() == n.sum():
            continue
        m, b = _mle(lx, n, kb, (med, beta))
        meds.append(m)
        betas.append(b)
    lo, hi = 100 * (1 - CONFIDENCE) / 2, 100 * (1 + CONFIDENCE) / 2
    mci = (float(np.percentile(meds, lo)), float(np.percentile(meds, hi))) if meds else (math.nan, math.nan)
    bci = (float(np.percentile(betas, lo)), float(np.percentile(betas, hi))) if betas else (math.nan, math.nan)
    return LognormalFit(med, beta, mci, bci, int(n.sum()))
