"""PyBullet backend: single-block tilt against closed form (spec §3.4.1), determinism, planar option."""
import numpy as np
import pytest

from dem.engines import get_engine
from dem.load import TiltHold
from dem.model import single_block
from dem.protocols import TiltProtocol, simulate, tilt
from dem.settings import Settings
from specimens.errors import ArchdemInputError

B, H = 0.1, 0.2  # b/h = 0.5


def test_block_slides_at_mu():
    # mu < b/h: the block slides at lambda = mu (Coulomb); 2 % = the tolerance
    mu = 0.3
    r = tilt(single_block(B, H), Settings(mu_joint=1.0, mu_base=mu), TiltProtocol())
    assert r.lam == pytest.approx(mu, rel=0.02)
    assert r.mode == "sliding"
    assert r.joints[0].state == "slide"


def test_block_rocks_at_b_over_h():
    # mu > b/h: the block overturns about its downhill (+x, "extrados") corner at lambda = b/h
    r = tilt(single_block(B, H), Settings(mu_joint=1.0, mu_base=1.0), TiltProtocol())
    assert r.lam == pytest.approx(B / H, rel=0.02)
    assert r.mode == "rocking"
    assert (r.joints[0].state, r.joints[0].face) == ("hinge", "extrados")


def test_determinism_and_two_engines_in_one_process():
    # identical command sequences give bit-identical histories, also with two clients alive
    m = single_block(B, H)
    s = Settings(mu_joint=1.0, mu_base=1.0)
    e1, e2 = get_engine("pybullet"), get_engine("pybullet")
    e1.build(m, s)
    e2.build(m, s)
    try:
        for e in (e1, e2):
            e.set_gravity([3.0, -9.0, 0.0])
            e.step(300)
        (p1, R1), (p2, R2) = e1.poses(), e2.poses()
        assert np.array_equal(p1, p2) and np.array_equal(R1, R2)
    finally:
        e1.close()
        e2.close()
    a = simulate(m, s, TiltHold(0.45, 0.3), 0.5)
    b = simulate(m, s, TiltHold(0.45, 0.3), 0.5)
    assert np.array_equal(a.history.pos, b.history.pos)


def test_planar_option_has_no_out_of_plane_motion():
    # planar: out-of-plane velocities zeroed every step, so z displacements stay at rounding level
    m = single_block(B, H)
    r = simulate(m, Settings(mu_joint=1.0, mu_base=1.0, planar=True), TiltHold(0.6, 0.2), 0.6)
    assert r.collapsed
    assert r.out_of_plane["max_dz_history_m"] < 1e-9


def test_unknown_engine():
    with pytest.raises(ArchdemInputError):
        get_engine("nope")
