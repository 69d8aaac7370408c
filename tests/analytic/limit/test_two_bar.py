"""Two-bar rocking-sliding model."""
import numpy as np
import pytest

from analytic.limit.limit_continuous import continuous_collapse
from analytic.limit.two_bar import lambda_slide, lambda_two_bar, mu_star, two_bar_geometry
from specimens.catalogue import CATALOGUE, get_specimen
from foundation.errors import ArchdemInputError
from specimens.geometry import ring_half_boundary
from specimens.sections import region_properties


@pytest.mark.parametrize("sid", [s.id for s in CATALOGUE])
def test_frictionless_closed_form_and_static(sid):
    arch = get_specimen(sid).arch
    yG = region_properties(ring_half_boundary(arch, 0.0, None)).centroid[1]
    # symmetric halves rotating about A (intrados) and B (extrados): lambda = t / (2 y_G)
    assert lambda_two_bar(arch) == pytest.approx(arch.t / (2 * yG), rel=1e-12)
    # the static (moment-equilibrium) form with mu = 0 is the same number
    assert lambda_slide(arch, 0.0) == pytest.approx(lambda_two_bar(arch), rel=1e-12)


def test_slider_point_and_hinges():
    arch = get_specimen("Sh06-Sd015").arch
    g = two_bar_geometry(arch)
    # S is the extrados end of the left apex cut (psi = psi_i on the left half)
    assert np.allclose(g.S, arch.point(arch.psi_i, arch.Re, -1), atol=1e-14)
    assert g.A[0] == pytest.approx(-(arch.Rc - arch.t / 2)) and g.B[0] == pytest.approx(arch.Rc + arch.t / 2)
    assert g.mass_left == pytest.approx(g.mass_right, rel=1e-12)


def test_lambda_slide_increasing_and_mu_star():
    arch = get_specimen("Sh1-Sd020").arch
    lams = [lambda_slide(arch, mu) for mu in np.linspace(0, 1.5, 16)]
    assert all(b > a for a, b in zip(lams, lams[1:]))
    lr = continuous_collapse(arch).lam
    ms = mu_star(arch, lr)
    # the closed-form threshold is where lambda_slide crosses the rocking multiplier
    assert lambda_slide(arch, ms) == pytest.approx(lr, rel=1e-10)
    assert mu_star(arch) == pytest.approx(ms, rel=1e-9)


def test_bad_mu():
    with pytest.raises(ArchdemInputError):
        lambda_slide(get_specimen("Sh1-Sd020").arch, -0.1)
