"""The tilt of an assembly on compliant joints by statics, against a closed form and the rigid limit."""
import math

import pytest
from scipy.optimize import brentq

from analytic.compliant.elastic_tilt import elastic_tilt
from analytic.limit.limit_discrete import solve_lp
from specimens import get_specimen
from specimens.blocks import discretise
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.frame import single_block

B, H, W, RHO = 0.05, 0.2, 0.1, 500.0


@pytest.mark.parametrize("kn", [1e6, 1e8, 4.3e8])
def test_a_block_lifts_off_when_its_turn_on_the_springs_has_eaten_its_lever_arm(kn):
    """The block turns on its two base springs (k_n w b each) until the uphill one unloads; then it turns
    about the other, and the tilt it stood is the largest: tan alpha = b/h - tan phi, with the turn
    2 b sin phi = m g cos alpha / (k_n w b) (the shear spring at the base's centre adds the b sin phi
    lever of the friction force)."""
    blk = single_block(B, H, RHO, W)
    m = blk.bodies[0].mass

    def gap(a: float) -> float:
        phi = math.asin(m * G * math.cos(a) / (2 * B * kn * W * B))
        return math.tan(a) - (B / H - math.tan(phi))

    expected = math.tan(brentq(gap, 1e-6, math.atan(B / H)))
    res = elastic_tilt(blk, kn)
    assert res.lam == pytest.approx(expected, rel=3e-5)
    assert res.lam < B / H


@pytest.fixture(scope="module")
def thin_arch():
    asm = discretise(get_specimen("Sh06-Sd010").arch, config="glued")
    return asm, solve_lp(asm, math.inf, math.inf).lam


@pytest.mark.slow
def test_stiff_joints_give_the_rigid_limit_load_and_the_drop_goes_as_the_compliance(thin_arch):
    """lambda tends to the LP's with no sliding as k_n grows, its shortfall proportional to 1 / k_n."""
    asm, lp = thin_arch
    drops = {kn: 1.0 - elastic_tilt(asm, kn).lam / lp for kn in (4.3e8, 4.3e9, 1e10)}
    assert 0 < drops[1e10] < 1e-3
    assert drops[4.3e8] / drops[4.3e9] == pytest.approx(10.0, rel=0.1)


@pytest.mark.slow
def test_the_shear_stiffness_hardly_matters(thin_arch):
    asm, _ = thin_arch
    a, b = (elastic_tilt(asm, 4.3e8, ks).lam for ks in (0.347 * 4.3e8, 4.3e11))
    assert a == pytest.approx(b, rel=1e-3)


def test_bad_stiffness():
    with pytest.raises(ArchdemInputError, match="kn"):
        elastic_tilt(single_block(B, H), -1.0)
