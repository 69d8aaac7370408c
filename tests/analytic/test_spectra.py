"""Elastic response spectra of NTC 2018 and EN 1998-1: the codes' parameters and shape."""
import math

import numpy as np
import pytest

from analytic.spectra import damping_correction, ec8, ntc2018
from specimens.constants import G
from specimens.errors import ArchdemInputError


def test_damping_correction():
    assert damping_correction(5.0) == 1.0
    assert damping_correction(10.0) == pytest.approx(math.sqrt(10 / 15))
    assert damping_correction(30.0) == 0.55  # the codes' floor (reached from xi = 28.06 %)


def test_ec8_type1_ground_c():
    s = ec8(0.25 * G, "C", 1)
    assert (s.S, s.TB, s.TC, s.TD, s.F0) == (1.15, 0.20, 0.60, 2.0, 2.5)
    top = 0.25 * G * 1.15 * 2.5
    assert float(s.Se(0.0)) == pytest.approx(s.pga) and s.pga == pytest.approx(0.25 * G * 1.15)
    assert float(s.Se(0.4)) == pytest.approx(top)
    assert float(s.Se(1.0)) == pytest.approx(top * 0.6 / 1.0)
    assert float(s.Se(3.0)) == pytest.approx(top * 0.6 * 2.0 / 9.0)
    # the displacement spectrum between TC and TD grows linearly: ag S eta F0 TC T / (4 pi^2)
    assert float(s.SDe(1.5)) == pytest.approx(top * 0.6 * 1.5 / (4 * math.pi ** 2))
    assert ec8(0.25 * G, "d", 2).describe()["TC"] == 0.30


def test_ntc2018_worked_example():
    """ag 0.25 g, F0 2.4, Tc* 0.3 s, soil C, slope T2, 5 %: S_S = 1.70 - 0.60 x 2.4 x 0.25 = 1.34,
    C_C = 1.05 x 0.3^-0.33, S = 1.34 x 1.2, TC = C_C Tc*, TB = TC / 3, TD = 4 x 0.25 + 1.6 = 2.6 s."""
    s = ntc2018(0.25 * G, 2.4, 0.3, "C", "T2")
    cc = 1.05 * 0.3 ** -0.33
    assert s.params["S_S"] == pytest.approx(1.34) and s.params["C_C"] == pytest.approx(cc)
    assert s.S == pytest.approx(1.34 * 1.2) and s.TC == pytest.approx(cc * 0.3)
    assert s.TB == pytest.approx(cc * 0.1) and s.TD == pytest.approx(2.6)
    assert float(s.Se(s.TC)) == pytest.approx(0.25 * G * 1.34 * 1.2 * 2.4)
    assert s.t_max == 6.0  # soil C: the displacement spectrum is Se (T / 2 pi)^2 up to TE = 6 s


def test_ntc2018_soil_factor_is_clipped():
    assert ntc2018(0.01 * G, 2.5, 0.3, "D").params["S_S"] == 1.80  # 2.40 - 1.50 x 0.025 capped
    assert ntc2018(0.60 * G, 2.5, 0.3, "D").params["S_S"] == 0.90  # 2.40 - 1.50 x 1.5 floored
    assert ntc2018(0.30 * G, 2.5, 0.3, "A").S == 1.0 and ntc2018(0.3 * G, 2.5, 0.3, "A", "T4").S == 1.4


@pytest.mark.parametrize("s", [ntc2018(0.2 * G, 2.5, 0.35, "B", "T3", damping=10.0), ec8(0.3 * G, "E", 2, 2.0)])
def test_the_spectrum_is_continuous_at_its_corners(s):
    for Tc in (s.TB, s.TC, s.TD):
        left, right = s.Se([Tc * (1 - 1e-12), Tc])
        assert left == pytest.approx(right, rel=1e-9)
    T = np.linspace(0, s.t_max, 2001)
    assert np.all(np.diff(s.Se(T)[T >= s.TC]) <= 0) and np.all(np.diff(s.SDe(T)) >= -1e-15)


@pytest.mark.parametrize("call, msg", [
    (lambda: ntc2018(0.25 * G, 2.4, 0.3, "F"), "soil category must be one of A, B, C, D, E"),
    (lambda: ntc2018(0.25 * G, 2.4, 0.3, "C", "T5"), "topographic category must be one of"),
    (lambda: ntc2018(float("nan"), 2.4, 0.3), r"ag \[m/s\^2\] must be in"),
    (lambda: ec8(0.25 * G, "A", 3), "EC8 spectrum type must be 1 or 2"),
    (lambda: ec8(0.25 * G, "A", 1, damping=-1), "damping ratio must be a percentage"),
    (lambda: ec8(0.25 * G, "A").Se(4.5), r"periods must be in \[0, 4\] s"),
])
def test_bad_input_is_refused_in_one_line(call, msg):
    with pytest.raises(ArchdemInputError, match=msg) as exc:
        call()
    assert "\n" not in str(exc.value)
