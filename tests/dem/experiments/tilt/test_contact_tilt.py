"""Tilt test of relieved blocks (effective contact c < 1) against the LP at the same contact
(docs/physics/geometry.md#12-effective-contact); the catalogue runs in benchmarks/validate_dem.py --contact C."""
import math

import pytest

import analytic.limit.limit_discrete as lim
from dem.core.model import from_assembly
from dem.core.settings import Settings
from dem.experiments.tilt.run import tilt
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from specimens.constants import NO_SLIDING_MU

pytestmark = pytest.mark.slow  # every test here simulates, spawns processes or runs a campaign

# the thinnest specimen, where PyBullet's hull rounding of relieved faces cost 4.9 % before the pads
# of docs/engines.md#9-joint-faces-on-pads-in-pybullet
SID, CONTACT = "Sh06-Sd010", 0.7


@pytest.fixture(scope="module")
def blocks():
    asm = discretise(get_specimen(SID).arch, config="glued", contact=CONTACT)
    return asm, lim.solve_lp(asm, math.inf, math.inf)


@pytest.mark.slow
@pytest.mark.parametrize("engine", ["pybullet", "mujoco"])
def test_relieved_joints_tilt_at_the_lp_of_the_same_contact(blocks, engine):
    asm, lp = blocks
    full_lp = lim.solve_lp(discretise(asm.arch, config="glued"), math.inf, math.inf).lam
    assert lp.lam < 0.5 * full_lp  # the relief matters: the test would catch full-contact collisions
    res = tilt(from_assembly(asm, name=SID), Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, engine=engine),
               assembly=asm)
    # the tolerance, as for full joints: 3 % of the LP
    assert abs(res.lam - lp.lam) / lp.lam <= 0.03
    hinges = tuple((j.joint, j.face) for j in res.joints if j.state in ("hinge", "hinge+slide"))
    assert hinges == lp.hinges and res.mode == "rocking"
    assert res.summary()["contact"] == CONTACT
