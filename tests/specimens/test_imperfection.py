"""The imperfect-fit model: nominal contact, seeded realisations of the joints' edge losses."""
import math

import numpy as np
import pytest

from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError
from specimens.imperfection import MIN_CONTACT, Imperfection, realise

ARCH = get_specimen("Sh06-Sd020").arch  # t = 64 mm


def _same(a, b):
    assert [j.band for j in a.joints] == [j.band for j in b.joints]
    for x, y in zip(a.bodies, b.bodies):
        assert all(np.array_equal(p, q) for p, q in zip(x.pieces, y.pieces)) and len(x.pieces) == len(y.pieces)


def test_nominal_contact_is_one_minus_twice_the_edge_loss_over_t():
    imp = Imperfection(edge_loss=0.005)
    assert imp.contact(ARCH) == pytest.approx(1 - 2 * 0.005 / ARCH.t, rel=1e-12)
    _same(realise(ARCH, imp, None, config="glued"), discretise(ARCH, config="glued", contact=imp.contact(ARCH)))


def test_zero_scatter_reproduces_the_nominal_blocks_bit_for_bit():
    imp = Imperfection(edge_loss=0.004, edge_loss_sd=0.0)
    _same(realise(ARCH, imp, seed=3, realisation=5, config="glued"), realise(ARCH, imp, None, config="glued"))


def test_realisations_are_reproducible_from_seed_and_index():
    imp = Imperfection(0.005, 0.0015)
    a = realise(ARCH, imp, seed=11, realisation=2, config="glued")
    _same(a, realise(ARCH, imp, seed=11, realisation=2, config="glued"))
    b = realise(ARCH, imp, seed=11, realisation=3, config="glued")
    assert [j.band for j in a.joints] != [j.band for j in b.joints]
    assert a.imperfect and a.parameters()["bands"]["L0"] == list(a.joint("L0").band)


def test_drawn_edge_losses_have_the_stated_mean_and_scatter():
    imp = Imperfection(0.005, 0.0012)
    nominal = discretise(ARCH, config="glued", contact=imp.contact(ARCH))
    losses = []
    for k in range(150):
        bands = imp.bands(nominal, seed=1, realisation=k)
        for j in nominal.joints:
            lo, hi = bands[j.name]
            losses += [lo * j.length, (1 - hi) * j.length]
    x = np.array(losses)  # 4800 draws; the truncation at 0 is 4 sd away
    se = imp.edge_loss_sd / math.sqrt(len(x))
    assert abs(x.mean() - imp.edge_loss) < 4 * se
    assert x.std(ddof=1) == pytest.approx(imp.edge_loss_sd, rel=0.05)  # sd of an sd estimate: 1 %


def test_a_realised_joint_keeps_the_least_contact():
    imp = Imperfection(0.02, 0.02)  # losses near half the joint: some joints are scaled back
    asm = realise(ARCH, imp, seed=5, realisation=0, config="glued")
    assert min(j.contact for j in asm.joints) >= MIN_CONTACT - 1e-12
    assert all(0 <= j.band[0] < j.band[1] <= 1 for j in asm.joints)


@pytest.mark.parametrize("kw", [{"edge_loss": -0.001}, {"edge_loss": math.nan}, {"edge_loss_sd": -1e-3},
                                {"edge_loss_sd": math.inf}])
def test_bad_imperfection_is_refused(kw):
    with pytest.raises(ArchdemInputError, match="edge loss"):
        Imperfection(**kw)


def test_an_edge_loss_that_leaves_no_joint_is_refused():
    with pytest.raises(ArchdemInputError, match="leaves less than"):
        Imperfection(edge_loss=0.031).contact(ARCH)


def test_bands_of_unknown_joints_are_refused():
    with pytest.raises(ArchdemInputError, match="does not have"):
        discretise(ARCH, config="glued", bands={"L9": (0.1, 0.9)})
    with pytest.raises(ArchdemInputError, match="0 <= lo < hi <= 1"):
        discretise(ARCH, config="glued", bands={"L1": (0.6, 0.4)})
