"""DEM free vibration of a block on compliant joints against the closed forms and analytic.compliant.modes."""
import importlib.util
import math

import pytest

from analytic.compliant.modes import modes
from dem.core.model import single_block
from dem.core.settings import Settings
from dem.experiments.modes.run import free_vibration
from specimens.constants import G
from specimens.frame import single_block as block_structure

B, H, W, RHO, KN = 0.2, 0.4, 0.1, 500.0, 1e6  # ~11 Hz vertical, ~5 Hz rocking
ENGINES = [pytest.param(e, marks=pytest.mark.skipif(importlib.util.find_spec(e) is None, reason=f"{e} not installed"))
           for e in ("pybullet", "mujoco")]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.slow
def test_a_blocks_frequencies_and_damping(engine):
    """Vertical sqrt(k_n A / m); rocking on the springs at the base's ends (friction holds the base),
    sqrt((k_n A b^2 / 4 - m g h/2) / I_o) about the base centre — within 1 % (measured 0.31 % at most), and
    the same as analytic.compliant.modes; the damping ratios beta_R omega / 2 (rocking: times 1 + m g h/2 / (I_o omega²),
    the weight softens the mode, not its dashpots) within 10 % (measured 5.0 % at most: PyBullet's implicit
    contact adds 0.001-0.004 of its own at dt 0.1 ms, up to 8 % of 0.05)."""
    m = RHO * B * H * W
    w_v = math.sqrt(KN * B * W / m)
    Io = m * (B * B + H * H) / 12 + m * (H / 2) ** 2
    f_r = math.sqrt((KN * B * W * B * B / 4 - m * G * H / 2) / Io) / (2 * math.pi)
    beta = 0.1 / w_v  # xi 0.05 in the vertical mode
    r = free_vibration(single_block(B, H, W, RHO), Settings(engine=engine, dt=1e-4, contact_law="compliant", kn=KN,
                                                            damping_beta=beta))
    fm = modes(block_structure(B / 2, H / 2, RHO, W), KN, 1e4 * KN).frequencies_hz
    assert r["vertical"].frequency_hz == pytest.approx(w_v / (2 * math.pi), rel=0.01)
    assert r["rocking"].frequency_hz == pytest.approx(f_r, rel=0.01)
    assert fm[:2] == pytest.approx([f_r, w_v / (2 * math.pi)], rel=1e-3)
    assert r["vertical"].damping == pytest.approx(0.05, rel=0.1)
    w_r = 2 * math.pi * f_r
    assert r["rocking"].damping == pytest.approx(beta * w_r / 2 * (1 + m * G * H / 2 / (Io * w_r**2)), rel=0.1)


def test_rigid_joints_have_no_free_vibration():
    from foundation.errors import ArchdemInputError

    with pytest.raises(ArchdemInputError, match="needs compliant joints"):
        free_vibration(single_block(B, H, W, RHO), Settings())


@pytest.mark.slow
def test_an_arch_crown_vibrates_at_the_symmetric_mode_of_modes():
    """Sh02-Sd025 on soft joints (1e6 Pa/m): the crown's vertical vibration in PyBullet at the first
    mode of analytic.compliant.modes that moves the crown vertically only (the symmetric one), within 3 % (measured 1.8 %)."""
    import numpy as np

    from dem.core.model import as_model

    model = as_model("Sh02-Sd025")
    res = modes(model.assembly, KN, 1e4 * KN)
    c = model.crown
    k = next(k for k in range(len(res.frequencies_hz))
             if abs(res.shapes[3 * c + 1, k]) > 100 * max(abs(res.shapes[3 * c, k]), abs(res.shapes[3 * c + 2, k])))
    r = free_vibration(model, Settings(dt=1e-4, contact_law="compliant", kn=KN, mu_joint=10.0, mu_base=10.0))
    assert k == 1 and np.isfinite(r["vertical"].frequency_hz)
    assert r["vertical"].frequency_hz == pytest.approx(res.frequencies_hz[k], rel=0.03)
