"""Modes on compliant joints against the closed forms of a block on an elastic foundation."""
import math

import numpy as np
import pytest

from analytic.compliant.modes import mass_matrix, modes
from specimens import get_specimen
from specimens.blocks import discretise
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.frame import single_block

B, H, W, RHO, KN = 0.05, 0.2, 0.1, 500.0, 4.34e8


@pytest.mark.parametrize("springs", ["bed", "ends"])
@pytest.mark.parametrize("kn", [KN, 1e6])
def test_a_block_vertical_and_rocking_frequencies(kn, springs):
    """Vertical: sqrt(k_n A / m). Rocking without sliding (shear springs far stiffer) about the base
    centre: sqrt((k_rot - m g h) / (I_c + m h^2)) — the foundation's rotational stiffness, k_n w (2/3) b^3
    for a continuous bed or k_n A b^2 for the springs at the base's two ends, less the weight's
    overturning term, which soft joints (1e6 Pa/m) make a third of it."""
    blk = single_block(B, H, RHO, W)
    m = RHO * W * 4 * B * H
    res = modes(blk, kn, 1e4 * kn, springs=springs)
    f_vert = math.sqrt(kn * 2 * B * W / m) / (2 * math.pi)
    Ic = m * ((2 * B) ** 2 + (2 * H) ** 2) / 12
    k_rot = kn * W * 2 * B ** 3 / 3 if springs == "bed" else kn * 2 * B * W * B ** 2
    f_rock = math.sqrt((k_rot - m * G * H) / (Ic + m * H * H)) / (2 * math.pi)
    assert res.frequencies_hz[1] == pytest.approx(f_vert, rel=1e-9)
    assert res.frequencies_hz[0] == pytest.approx(f_rock, rel=1e-4)
    if kn < KN and springs == "bed":  # where the weight's term counts, it is the one that is there
        assert m * G * H > 0.3 * k_rot
        assert abs(res.frequencies_hz[0] / (math.sqrt(k_rot / (Ic + m * H * H)) / (2 * math.pi)) - 1) > 0.1


def test_mass_normalised_shapes_and_stiffer_joints():
    asm = discretise(get_specimen("Sh06-Sd015").arch, config="free")
    r1, r4 = modes(asm, KN), modes(asm, 4 * KN)
    M = mass_matrix(asm)
    assert np.allclose(r1.shapes.T @ M @ r1.shapes, np.eye(r1.shapes.shape[1]), atol=1e-8)
    assert len(r1.frequencies_hz) == 3 * len(asm.bodies) and r1.unstable == 0
    # four times stiffer joints: frequencies about twice (not exactly: the weight's term stays)
    assert np.allclose(r4.frequencies_hz / r1.frequencies_hz, 2.0, rtol=0.02)


def test_bad_stiffness_or_springs():
    with pytest.raises(ArchdemInputError, match="joint springs 'corners' is not one of bed, ends"):
        modes(single_block(B, H), KN, springs="corners")
    with pytest.raises(ArchdemInputError, match="normal joint stiffness kn must be a positive"):
        modes(single_block(B, H), -1.0)
    with pytest.raises(ArchdemInputError, match="shear joint stiffness ks"):
        modes(single_block(B, H), KN, float("nan"))
