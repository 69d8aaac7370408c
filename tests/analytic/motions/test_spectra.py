"""Elastic response spectra of NTC 2018 and EN 1998-1: the codes' parameters and shape."""
import math

import numpy as np
import pytest

from analytic.motions.spectra import damping_correction, ec8, ntc2018
from specimens.constants import G
from foundation.errors import ArchdemInputError


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


def test_a_user_spectrum_file(tmp_path):
    import numpy as np

    from analytic.motions.spectra import read_spectrum, rebuild

    f = tmp_path / "s.csv"
    f.write_text("# period, Se\n0, 0.2\n0.2; 0.5\n1.0\t0.1  # tail\n")
    s = read_spectrum(str(f))
    assert s.pga == pytest.approx(0.2 * G) and float(s.Se(0.6)) == pytest.approx(0.3 * G)
    assert float(s.SDe(1.0)) == pytest.approx(0.1 * G / (2 * np.pi) ** 2)
    s2 = rebuild(s, ag=0.4 * G, damping=10.0)
    assert float(s2.Se(0.0)) == pytest.approx(0.4 * G)  # the peak ground acceleration is not damped
    assert float(s2.Se(0.6)) == pytest.approx(0.6 * G * np.sqrt(10 / 15))
    for text, msg in (("0 0.2\n0.1\n", "line 2: expected two numbers"), ("0.1 0.2\n0.2 0.3\n", "first period must be 0"),
                      ("0 0.2\n0.3 0.4\n0.2 0.1\n", "line 3: periods must increase"), ("0 0.2\n", "at least two rows"),
                      ("0 0.2\n1 nan\n", "line 2: Se must be in"), ("0 0.2\n11 0.1\n", "periods up to 10 s"),
                      ("0 0.2\n1 x\n", "line 2: not numbers")):
        f.write_text(text)
        with pytest.raises(ArchdemInputError, match=msg):
            read_spectrum(str(f))
    with pytest.raises(ArchdemInputError, match="periods must be in"):
        s.Se(1.5)


def test_the_floor_spectrum_of_the_first_mode():
    """At T = 0 the floor's peak acceleration; on [0.8 T1, 1.1 T1) the plateau 1.1 xi1^-0.5 eta a_Z;
    never below the ground spectrum beyond T1."""
    import numpy as np

    from analytic.motions.spectra import floor_spectrum

    site = ec8(0.25 * G, "B")
    T1, n, z = 0.4, 3, 0.7
    aZ = float(site.Se(T1)) * (3 * n / (2 * n + 1)) * z * np.sqrt(1 + 0.0004 * 25)
    assert float(floor_spectrum(site, 0.0, 5.0, z, T1, n)) == pytest.approx(aZ)
    top = 1.1 * 0.05 ** -0.5 * aZ
    assert floor_spectrum(site, [0.33, 0.4, 0.43], 5.0, z, T1, n) == pytest.approx([top] * 3)
    T = np.linspace(0.41, 4.0, 200)
    assert np.all(floor_spectrum(site, T, 5.0, z, T1, n) >= site.Se(T) - 1e-12)
