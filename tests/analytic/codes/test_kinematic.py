"""Kinematic analysis against closed forms (the rocking block, the rocking frame) and a hand computation."""
import math

import numpy as np
import pytest

from analytic.codes.kinematic import Height, capacity_curve, linear_kinematic
from analytic.motions.spectra import ntc2018
from analytic.rocking.linkage import mechanism_four_bar, minimised_four_bar
from analytic.rocking.rocking_block import RockingBlock
from specimens import get_specimen
from specimens.constants import G
from foundation.errors import ArchdemInputError
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
    site = ntc2018(0.25 * G, 2.4, 0.3, "A")  # soil A: S = 1 whatever ag
    c = k.check(site)
    assert c["capacity_pga"] == pytest.approx(2.0 * k.a0_star) and c["demand_pga"] == pytest.approx(site.pga)
    assert c["safety_index"] == pytest.approx(c["capacity_pga"] / c["demand_pga"])
    assert c["verified"] == (c["safety_index"] >= 1)
    with pytest.raises(ArchdemInputError, match="confidence factor FC must be a number from 1 to 3"):
        linear_kinematic(minimised_four_bar(arch), FC=0.5)
    with pytest.raises(ArchdemInputError, match="behaviour factor q must be"):
        k.check(site, q=float("nan"))


def test_an_arch_mechanism_by_hand():
    """e*, M*, a0* of the discrete four-bar of Sh06-Sd015 from its hinge points and blocks, by hand:
    block 1 turns about H1 at rate 1, block 3 about H4 at w3, block 2 at w2, with H2 and H3 moving
    alike on both blocks; a body turning at w about P moves its centroid G horizontally by -w (yG - yP)."""
    from analytic.rocking.linkage import mechanism_four_bar
    from specimens.blocks import discretise

    fb = mechanism_four_bar(discretise(get_specimen("Sh06-Sd015").arch, n_voussoirs=8, config="free"))
    (H1, H2, H3, H4), (m1, m2, m3), (G1, G2, G3) = fb.points, fb.masses, fb.centroids
    w1 = float(fb.sense)
    # H3: v(H2) + w2 J (H3 - H2) = w3 J (H3 - H4), v(H2) = w1 J (H2 - H1), J (x, y) = (-y, x)
    v2 = np.array([-w1 * (H2[1] - H1[1]), w1 * (H2[0] - H1[0])])
    A = np.array([[-(H3[1] - H2[1]), (H3[1] - H4[1])], [(H3[0] - H2[0]), -(H3[0] - H4[0])]])
    w2, w3 = np.linalg.solve(A, -v2)
    dx = np.array([-w1 * (G1[1] - H1[1]), v2[0] - w2 * (G2[1] - H2[1]), -w3 * (G3[1] - H4[1])])
    m = np.array([m1, m2, m3])
    M_star = (m @ dx) ** 2 / (m @ dx ** 2)
    k = linear_kinematic(fb, FC=1.2)
    assert k.M_star == pytest.approx(M_star, rel=1e-9) and k.e_star == pytest.approx(M_star / m.sum(), rel=1e-9)
    assert k.a0_star == pytest.approx(fb.lam * G / (M_star / m.sum() * 1.2), rel=1e-9)


@pytest.mark.parametrize("b, h", [(0.05, 0.2), (0.02, 0.4)])
def test_the_rocking_block_capacity_curve(b, h):
    """alpha(theta) = tan(atan(b/h) - theta) exactly, d0* = b (the centroid above the pivot), e* = 1;
    the codes' linear curve alpha0 (1 - d/d0) is within (b/h)^2 / 2 of it (exact as b/h -> 0)."""
    blk = RockingBlock(b, h)
    c = capacity_curve(blk, FC=1.0)
    assert np.max(np.abs(c.alpha - np.tan(blk.alpha - c.phi))) < 1e-12
    assert c.d0_star == pytest.approx(b, rel=1e-9) and c.e_star == pytest.approx(1.0) and c.d_star[0] == 0
    assert c.a0_star == pytest.approx(b / h * G)
    assert np.max(np.abs(c.a_star - c.linear(c.d_star))) <= 0.5 * (b / h) ** 2 * c.a0_star * (1 + 1e-9)


def test_the_block_displacement_check_by_hand():
    """SLV: d_u = 0.4 b, a(d_u) from the exact curve, T = 1.68 pi sqrt(d_u / a(d_u)), demand SDe(T) at 8 %
    (EC8 ground A, TC < T < TD); the capacity ag scales the demand to d_u (S = 1, linear in ag)."""
    from analytic.motions.spectra import ec8

    blk = RockingBlock(0.05, 0.2)
    c = capacity_curve(blk, FC=1.0)
    site = ec8(0.3 * G, "A")
    r = c.check(site, "SLV")
    d_u = 0.4 * 0.05
    u = math.asin((0.05 - d_u) / blk.R)  # centroid d_u beyond rest: R sin(u) = b - d_u
    a_u = math.tan(u) * G
    T = 1.68 * math.pi * math.sqrt(d_u / a_u)
    eta = math.sqrt(10 / 13)
    demand = 0.3 * G * eta * 2.5 * 0.4 / T * (T / (2 * math.pi)) ** 2
    assert 0.4 < T < 2.0
    assert r["a_u_star"] == pytest.approx(a_u, rel=1e-4) and r["period"] == pytest.approx(T, rel=1e-4)
    assert r["demand_displacement"] == pytest.approx(demand, rel=1e-4)
    assert r["capacity_ag"] == pytest.approx(0.3 * G * d_u / demand, rel=1e-4)
    assert r["safety_index"] == pytest.approx(d_u / demand, rel=1e-4) and r["verified"] is False


def test_a_mechanism_at_a_height_sees_the_floor_acceleration():
    """Linear check at z/H: the floor's peak acceleration Se(T1) gamma psi sqrt(1 + 0.0004 xi^2) equals a0*
    at the SLD ag; with S = 1 it scales linearly with ag."""
    from analytic.motions.spectra import ec8

    blk = RockingBlock(0.05, 0.2)
    k = linear_kinematic(blk, FC=1.0)
    site = ec8(0.3 * G, "A")
    r = k.check(site, height=Height(0.5, 0.3, 4))
    gamma = 3 * 4 / 9
    aZ = float(site.Se(0.3)) * gamma * 0.5 * math.sqrt(1.01)
    assert r["demand_acceleration"] == pytest.approx(aZ)
    assert r["capacity_ag"] == pytest.approx(2 * site.ag * k.a0_star / aZ, rel=1e-8)
    with pytest.raises(ArchdemInputError, match="building period T1"):
        Height(0.5, -1.0, 3)
