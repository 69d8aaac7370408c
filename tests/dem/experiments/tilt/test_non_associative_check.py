"""The three-way check at the reference friction: where the DEM tilt's mechanism is the non-associative
one, its multiplier lies within the tilt's tolerance of it (docs/validation.md#21)."""
from types import SimpleNamespace

import pytest

from analytic.limit.non_associative import solve_non_associative
from dem.experiments.tilt.check import LP_TOLERANCE, na_joints, same_mechanism
from dem.experiments.tilt.run import tilt
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT


# Sh02-Sd025 free: the crown joint slides and the associative LP lies 1.8 % above the non-associative
# multiplier; Sh06-Sd025 glued: three hinges and a sliding joint, both rules equal
@pytest.mark.slow
@pytest.mark.parametrize("sid,config", [("Sh02-Sd025", "free"), ("Sh06-Sd025", "glued")])
def test_dem_tilt_meets_the_non_associative_multiplier(sid, config):
    asm = discretise(get_specimen(sid).arch, config=config)
    na = solve_non_associative(asm, REFERENCE_MU_JOINT, REFERENCE_MU_BASE)
    assert na.optimal and na.sliding
    r = tilt(asm, label=sid)
    assert same_mechanism(r.joints, na), (r.joints, na_joints(na))
    assert abs(r.lam / na.lam - 1) <= LP_TOLERANCE


def test_same_mechanism_compares_joint_by_joint():
    na = SimpleNamespace(joint_states={"L0": "hinge-intrados", "L6": "hinge-extrados", "L8": "sliding",
                                       "R0": "hinge-extrados", "R3": "closed", "R5": "hinge+sliding"})
    moving = [("L0", "hinge"), ("L6", "hinge"), ("L8", "slide"), ("R0", "hinge"), ("R5", "hinge+slide")]
    assert same_mechanism(moving + [("R3", "closed")], na)
    assert same_mechanism([SimpleNamespace(joint=j, state=st) for j, st in moving], na)
    assert not same_mechanism(moving[:-1], na)
    assert not same_mechanism([(j, "hinge") for j, _ in moving], na)
