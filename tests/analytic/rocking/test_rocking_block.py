"""Rectangular rocking block (analytic/rocking/rocking_block.py): closed forms of Housner's model."""
from __future__ import annotations

import math

import numpy as np
import pytest

from analytic.rocking.dynamics import integrate
from analytic.rocking.impact import energy_restitution, post_impact
from analytic.rocking.rocking_block import RockingBlock
from specimens.constants import G
from foundation.errors import ArchdemInputError


@pytest.mark.parametrize("b,h", [(0.1, 0.5), (0.3, 0.4), (0.02, 1.0)])
def test_onset_is_g_b_over_h(b, h):
    blk = RockingBlock(b, h)
    assert blk.onset == pytest.approx(G * b / h, rel=1e-13)  # closed form, round-off
    assert blk.direction == 1 and RockingBlock(b, h, pivot=1).direction == -1
    assert blk.phi_cr == pytest.approx(math.atan2(b, h), rel=1e-12)  # V' = m g R sin(alpha - phi)
    # omega0 = sqrt(m g R cos(alpha) / I_O): Housner's p times sqrt(cos alpha) (exact linearisation)
    assert blk.omega0 == pytest.approx(blk.housner_p * math.sqrt(math.cos(blk.alpha)), rel=1e-12)


@pytest.mark.parametrize("b,h", [(0.1, 0.5), (0.3, 0.4), (0.5, 0.5), (0.02, 1.0)])
def test_restitution_is_housner(b, h):
    blk = RockingBlock(b, h)
    e = energy_restitution(blk, post_impact(blk).after)
    assert e == pytest.approx(1 - 1.5 * math.sin(blk.alpha) ** 2, rel=1e-13)  # closed form


def test_energy_conserved_without_input_or_impact():
    blk = RockingBlock(0.1, 0.5)
    y0 = (0.05, 0.4)
    sol = integrate(blk, y0, (0.0, 0.4), dense_output=True)
    E0 = blk.energy(*y0)
    E = np.array([blk.energy(p, v) for p, v in zip(sol.y[0], sol.y[1])])
    assert np.all(sol.y[0] > 0)  # no impact in this window
    # DOP853 at rtol 1e-10: energy drift well below 1e-8 of the initial energy
    assert np.max(np.abs(E - E0)) < 1e-8 * abs(E0)


def test_bad_block_input():
    with pytest.raises(ArchdemInputError):
        RockingBlock(-0.1, 0.5)
    with pytest.raises(ArchdemInputError):
        RockingBlock(0.1, 0.5, pivot=0)


def test_the_rocking_frame_without_lintel_is_the_block():
    """gamma = 0: the frame's equivalent is the pier itself with Housner's restitution."""
    from analytic.rocking.rocking_block import rocking_frame_equivalent

    blk, r = rocking_frame_equivalent(0.05, 0.2, 0.0)
    assert (blk.b, blk.h) == (0.05, 0.2) and r == pytest.approx(1 - 1.5 * math.sin(blk.alpha) ** 2, rel=1e-14)
    heavy, r_heavy = rocking_frame_equivalent(0.05, 0.2, 1e9)  # all lintel: size x 3/2, ratio -> cos 2 alpha
    assert heavy.R == pytest.approx(1.5 * blk.R, rel=1e-8) and r_heavy == pytest.approx(math.cos(2 * blk.alpha), rel=1e-8)
