"""Linear kinematic analysis against closed forms: the rocking block and the rocking frame."""

import pytest

from analytic.kinematic import linear_kinematic
from analytic.linkage import mechanism_four_bar, minimised_four_bar
from analytic.rocking_block import RockingBlock
from analytic.spectra import ntc2018
from specimens import get_specimen
from specimens.constants import G
from specimens.errors import ArchdemInputError
from specimens.frame import rocking_frame


def test_a_rocking_block_takes_all_its_mass():
    """One body: M* = m, e* = 1, a0* = g (b/h) / FC."""
    blk = RockingBlock(0.05, 0.2)
    k = linear_kinematic(blk, FC=1.35)
    assert k.alpha0 == pytest.approx(0.25) and k.M_star == pytest.approx(blk.m) and k.e_star == pytest.approx(1.0)
    assert k.a0_star == pytest.approx(0.25 * G / 1.35)


@pytest.mark.parametrize("beam_density", [100.0, 1000.0, 10000.0])
def test_the_rocking_frame_closed_form(beam_density):
    """Piers (m each) turn about their feet, their centroids moving h per unit rotation, the lintel
    (m_b) 2h: M* = (2 m h + 2 m_b h)^2 / (2 m h^2 + 4 m_b h^2) = 2 (m + m_b)^2 / (m + 2 m_b)."""
    f = rocking_frame(0.05, 0.2, 0.3, 0.05, beam_density=beam_density)
    m, mb = f.bodies[0].mass, f.bodies[1].mass
    k = linear_kinematic(mechanism_four_bar(f), FC=1.0)
    assert k.M_star == pytest.approx(2 * (m + mb) ** 2 / (m + 2 * mb), rel=1e-9)
    assert k.e_star == pytest.approx(k.M_star / (2 * m + mb), rel=1e-12) and k.alpha0 == pytest.approx(0.25)
    assert k.a0_star == pytest.approx(0.25 * G / k.e_star, rel=1e-12)


def test_an_arch_check_at_ground_level():
    arch = get_specimen("Sh06-Sd015").arch
    k = linear_kinematic(minimised_four_bar(arch), FC=1.35)
    assert 0 < k.e_star < 1 and k.M_star < k.mass  # three blocks turning differently: part of the mass
    site = ntc2018(0.25 * G, 2.4, 0.3, "C")
    c = k.ground_check(site.pga)
    assert c["capacity_pga"] == pytest.approx(2.0 * k.a0_star) and c["demand_pga"] == pytest.approx(site.pga)
    assert c["safety_index"] == pytest.approx(c["capacity_pga"] / c["demand_pga"])
    assert c["verified"] == (c["safety_index"] >= 1)
    with pytest.raises(ArchdemInputError, match="confidence factor FC must be a number from 1 to 3"):
        linear_kinematic(minimised_four_bar(arch), FC=0.5)
    with pytest.raises(ArchdemInputError, match="site peak ground acceleration"):
        k.ground_check(float("nan"))
