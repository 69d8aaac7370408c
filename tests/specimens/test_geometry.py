import math

import numpy as np
import pytest

from specimens.catalogue import _TABLE, CATALOGUE, full_scale_set, get_specimen
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch

# Sh, Sd of the spec's table (01 §1.3), an independent statement of the rows
TABLE_SH_SD = {
    "Sh02-Sd015": (0.2, 0.15), "Sh02-Sd020": (0.2, 0.20), "Sh02-Sd025": (0.2, 0.25),
    "Sh06-Sd010": (0.6, 0.10), "Sh06-Sd015": (0.6, 0.15), "Sh06-Sd020": (0.6, 0.20), "Sh06-Sd025": (0.6, 0.25),
    "Sh1-Sd010": (1.0, 0.10), "Sh1-Sd015": (1.0, 0.15), "Sh1-Sd020": (1.0, 0.20), "Sh1-Sd025": (1.0, 0.25),
}


def test_catalogue_has_the_eleven_specimens():
    assert [s.id for s in CATALOGUE] == list(TABLE_SH_SD)


@pytest.mark.parametrize("sid", list(TABLE_SH_SD))
def test_sh_sd_of_every_row(sid):
    a = get_specimen(sid).arch
    sh, sd = TABLE_SH_SD[sid]
    # the table's radii are whole millimetres, so its ratios hold to round-off
    assert a.Sh == pytest.approx(sh, abs=1e-12)
    assert a.Sd == pytest.approx(sd, abs=1e-12)
    assert a.Rc == pytest.approx(0.200, abs=1e-12)
    assert a.width == 0.1


@pytest.mark.parametrize("row", _TABLE)
def test_constructors_agree(row):
    sid, Ri, Re, e = row
    a = PointedArch.from_radii(Ri / 1e3, Re / 1e3, e / 1e3)
    b = PointedArch.from_ratios(a.Sh, a.Sd, a.Rc)
    for k in ("Ri", "Re", "e", "t", "Rp", "Rc", "psi_i", "psi_e", "span", "rise"):
        assert getattr(a, k) == pytest.approx(getattr(b, k), rel=1e-12)


def test_profile_points_reach_the_axis_at_psi_i_and_psi_e():
    a = get_specimen("Sh06-Sd015").arch
    assert a.point(a.psi_i, a.Ri)[0] == pytest.approx(0.0, abs=1e-15)
    assert a.point(a.psi_e, a.Re)[0] == pytest.approx(0.0, abs=1e-15)
    assert a.psi_e > a.psi_i
    # springing: intrados at Rc - t/2, extrados at Rc + t/2
    assert a.point(0.0, a.Ri)[0] == pytest.approx(a.Rc - a.t / 2)
    assert a.point(0.0, a.Re)[0] == pytest.approx(a.Rc + a.t / 2)


def test_distance_formula_matches_polar_points():
    a = get_specimen("Sh1-Sd015").arch
    psi = np.linspace(0.0, a.psi_i, 50)
    p = a.point(psi, a.Ri)
    beta = np.arctan2(p[:, 1], p[:, 0])
    np.testing.assert_allclose(a.intrados_distance(beta), np.hypot(p[:, 0], p[:, 1]), rtol=1e-12)
    q = a.point(psi, a.Ri, side=-1)
    beta_l = np.arctan2(q[:, 1], q[:, 0])
    np.testing.assert_allclose(a.intrados_distance(beta_l), np.hypot(q[:, 0], q[:, 1]), rtol=1e-12)


def test_round_arch_limit():
    a = PointedArch.round(0.2, 0.04)
    assert a.Sh == 0 and a.psi_i == pytest.approx(math.pi / 2) and a.psi_e == pytest.approx(math.pi / 2)
    assert a.rise == pytest.approx(a.Ri)
    # area of a half annulus
    assert a.area() == pytest.approx(math.pi / 2 * (a.Re**2 - a.Ri**2), rel=1e-13)


def test_exact_area_by_sectors_and_keystone():
    # docs/physics/geometry.md#11-identities-the-tests-check: 2 x sector up to psi_i + keystone zone; keystone computed here by shoelace
    # on a very fine polygon (independent route), sectors in closed form
    a = get_specimen("Sh1-Sd020").arch
    sector = 0.5 * (a.Re**2 - a.Ri**2) * a.psi_i
    s = np.linspace(a.psi_i, a.psi_e, 20001)
    arc = a.point(s, a.Re)
    key = np.vstack([a.apex_intrados, arc])  # region right of the axis beyond the psi_i cut
    x, y = key.T
    key_area = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
    assert a.area() == pytest.approx(2 * (sector + key_area), rel=1e-7)  # 20000 chords: error ~1e-9


@pytest.mark.parametrize(
    "kwargs,match",
    [
        (dict(e=0.04, t=-0.01, Rp=0.24), "thickness"),
        (dict(e=0.04, t=0.0, Rp=0.24), "thickness"),
        (dict(e=-0.01, t=0.03, Rp=0.24), "eccentricity"),
        (dict(e=0.3, t=0.03, Rp=0.24), "eccentricity"),
        (dict(e=0.04, t=float("nan"), Rp=0.24), "finite"),
        (dict(e=0.04, t=0.03, Rp=float("inf")), "finite"),
        (dict(e=0.04, t=0.03, Rp=0.24, width=0.0), "width"),
    ],
)
def test_validation_errors(kwargs, match):
    with pytest.raises(ArchdemInputError, match=match):
        PointedArch(**kwargs)


def test_from_radii_rejects_swapped_radii():
    with pytest.raises(ArchdemInputError, match="exceed"):
        PointedArch.from_radii(0.3, 0.2, 0.05)


def test_full_scale_set():
    s = full_scale_set()
    assert len(s) == 48
    assert len({x.id for x in s}) == 48
    spans = sorted({round(2 * x.arch.Rc, 9) for x in s})
    assert spans == [5.0, 10.0, 20.0]
