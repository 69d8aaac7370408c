"""Effective contact in the limit analyses: joints that touch only within their central fraction c.

Independent truths: the continuous ring (exact Green integrals, hinges on the cuts' shrunk ends)
against the discrete enumeration of finely cut curved blocks (polygon masses, shrunk joint ends);
the LP with no sliding against the enumeration; the hinge points' distance from the mean radius.
"""
import math

import numpy as np
import pytest

from analytic.limit.limit_continuous import continuous_collapse, effective_arch, lambda_of_hinges
from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
from analytic.rocking.linkage import minimised_four_bar
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError


@pytest.mark.parametrize("sid", ["Sh02-Sd020", "Sh06-Sd010", "Sh1-Sd025"])
@pytest.mark.slow
def test_lambda_falls_with_contact_and_continuous_meets_fine_discrete(sid):
    arch = get_specimen(sid).arch
    lams = []
    for c in (1.0, 0.8, 0.6):
        cont = continuous_collapse(arch, contact=c)
        disc = enumerate_mechanisms(discretise(arch, config="free", shape="curved", segments=16, contact=c))
        # the discrete hinges are a subset of the continuous ones; 16 chords per voussoir put the
        # discrete ring within 1e-4 of the exact one (as at c = 1)
        assert cont.lam <= disc.lam * (1 + 1e-4)
        # and the continuous minimum at the discrete layout reproduces the enumeration: two
        # implementations of the shrunk hinge points agree
        assert lambda_of_hinges(arch, disc.layout.hinges) == pytest.approx(disc.lam, rel=1e-4)
        assert cont.contact == c
        lams.append(cont.lam)
    assert lams[0] > lams[1] > lams[2] > 0


def test_contact_keeps_the_weight_effective_thickness_does_not():
    """Same hinge points, different weight: c t of contact about Rp with the full ring's weight,
    against the thinner ring of thickness c t (its weight c times the ring's)."""
    arch = get_specimen("Sh06-Sd020").arch
    by_contact = continuous_collapse(arch, contact=0.8)
    thinner = continuous_collapse(arch, effective_thickness=0.8)
    # the thinner ring weighs about c times the full one (exactly so away from the keystone)
    assert effective_arch(arch, 0.8).area() == pytest.approx(0.8 * arch.area(), rel=0.01)
    # ... and its sector centroids sit at Rp (1 + O(Sd^2 / 12)): the multipliers differ only by
    # that order (measured 0.02 % here), so the cheaper thinner-ring rule is a close stand-in
    assert thinner.lam == pytest.approx(by_contact.lam, rel=arch.Sd**2 / 12)
    assert thinner.lam != by_contact.lam


def test_hinge_points_sit_at_the_ends_of_the_central_fraction():
    arch = get_specimen("Sh06-Sd015").arch
    c = 0.7
    kin = enumerate_mechanisms(discretise(arch, config="glued", contact=c))
    for (name, face), p in zip(kin.hinges, kin.hinge_points):
        side = -1 if name.startswith("L") else 1
        r = np.linalg.norm(p - arch.centre(side))
        assert r == pytest.approx(arch.Rp + (0.5 if face == "extrados" else -0.5) * c * arch.t, rel=1e-12)
    # the layout's Hinge objects give the same points
    np.testing.assert_allclose(kin.layout.points(arch), kin.hinge_points, rtol=0, atol=1e-12)


@pytest.mark.parametrize("mu", [0.3, 0.577])
def test_lp_with_friction_honours_contact(mu):
    arch = get_specimen("Sh1-Sd025").arch
    lam = [solve_lp(discretise(arch, config="glued", contact=c), mu, 1.0).lam for c in (1.0, 0.7)]
    no_slide = solve_lp(discretise(arch, config="glued", contact=0.7), math.inf, math.inf).lam
    # friction can only lower the multiplier; a smaller contact lowers the rocking branch
    assert lam[1] <= no_slide * (1 + 1e-9)
    assert lam[1] <= lam[0] * (1 + 1e-9)


def test_four_bar_of_a_reduced_contact_has_its_static_multiplier():
    arch = get_specimen("Sh06-Sd015").arch
    fb = minimised_four_bar(arch, contact=0.8)
    assert fb.lam == pytest.approx(continuous_collapse(arch, contact=0.8).lam, rel=1e-9)


@pytest.mark.parametrize("bad", [0.0, -0.5, 1.5, math.nan, math.inf, "x"])
def test_bad_contact_is_refused(bad):
    arch = get_specimen("Sh06-Sd015").arch
    with pytest.raises(ArchdemInputError, match="effective contact"):
        discretise(arch, contact=bad)
    with pytest.raises(ArchdemInputError, match="effective contact"):
        continuous_collapse(arch, contact=bad)
