"""Records matched to a site spectrum: the response spectrum (pyrotd) against the closed form of a
damped oscillator, the Arias window, the least-squares scale."""
import math
import subprocess
import sys

import numpy as np
import pytest

from analytic.motions.inputs import SampledMotion
from analytic.motions.matching import match_record, response_spectrum, significant_window
from analytic.motions.spectra import ec8
from specimens.constants import G
from foundation.errors import ArchdemInputError


def test_a_long_sine_at_resonance_and_a_stiff_oscillator():
    """Steady state of a 5 % oscillator driven at its own frequency: Sa = a / (2 zeta) (within the
    transient's share); a very stiff one follows the ground: Sa -> PGA."""
    dt, f, a = 0.005, 2.0, 1.0
    t = np.arange(0, 40, dt)
    m = SampledMotion(a * np.sin(2 * math.pi * f * t), dt, name="sine")
    Sa = response_spectrum(m, [1 / f, 0.011])
    assert Sa[0] == pytest.approx(a / (2 * 0.05), rel=0.02)
    assert Sa[1] == pytest.approx(a, rel=0.02)


def test_the_spectrum_runs_without_a_warning():
    """pyrotd imports pkg_resources (setuptools < 82, declared), which warns that it is deprecated:
    not shown to users. A fresh process, as pyrotd warns only on its first import."""
    code = ("import numpy as np; from analytic.motions.inputs import SampledMotion; "
            "from analytic.motions.matching import response_spectrum; "
            "print(response_spectrum(SampledMotion(np.sin(np.arange(0, 4, 0.01)), 0.01), [0.5])[0])")
    out = subprocess.run([sys.executable, "-W", "error", "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stderr == "" and float(out.stdout) > 0


def test_the_significant_window_and_the_scale():
    rng = np.random.default_rng(3)
    dt = 0.01
    t = np.arange(0, 30, dt)
    env = np.exp(-((t - 10) / 3) ** 2)  # strong motion around 10 s
    m = SampledMotion(env * rng.normal(size=len(t)), dt, name="synthetic")
    w = significant_window(m)
    assert 3 < w.duration < 12
    ia = np.cumsum(w.values ** 2)
    assert ia[-1] >= 0.89 * np.sum(m.values ** 2)
    site = ec8(0.2 * G, "B")
    r = match_record(m, site, (0.1, 1.0))
    ln = np.log(site.Se(r.periods)) - np.log(response_spectrum(w, r.periods))
    assert r.scale == pytest.approx(math.exp(ln.mean()), rel=1e-9)
    # the scaled record's own spectrum is the scaled spectrum (linearity), misfit around zero on average
    assert np.mean(np.log(response_spectrum(r.motion, r.periods) / r.Se)) == pytest.approx(0.0, abs=1e-9)
    assert r.misfit_max >= r.misfit_mean > 0
    with pytest.raises(ArchdemInputError, match="matching periods must satisfy"):
        match_record(m, site, (1.0, 0.1))
    with pytest.raises(ArchdemInputError, match="periods below 2 dt"):
        response_spectrum(m, [0.01])
