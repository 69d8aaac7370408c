"""Tie-rods: the LP with a tension member against a closed form (a pair of piers with a tie), and the
LP's multiplier against the work balance of its own mechanism (an arch on piers with a tie)."""
import dataclasses
import math
from types import SimpleNamespace

import numpy as np
import pytest

from analytic.codes.frp import Strips, strengthened_collapse
from analytic.limit.limit_discrete import solve_lp
from analytic.limit.ties import Tie, tie_link
from specimens import get_specimen
from specimens.constants import G
from foundation.errors import ArchdemInputError
from specimens.frame import rocking_frame
from specimens.monuments import NOH_GUMBAD
from specimens.piers import Piers


def _pair(bL, bR, h, span):
    """Two free-standing piers, 2 bL and 2 bR wide, 2h tall, ``span`` apart (clear), no lintel."""
    left = rocking_frame(bL, h, span, 0.01)
    right = rocking_frame(bR, h, span, 0.01)
    LP1, LP0 = left.bodies[0], left.joints[0]
    RP1 = dataclasses.replace(right.bodies[2], index=1)
    RP0 = dataclasses.replace(right.joints[3], index=1, a=1)
    return SimpleNamespace(bodies=(LP1, RP1), joints=(LP0, RP0), length_scale=2 * h, contact=1.0)


@pytest.mark.parametrize("T, regime", [(0.0, "right"), (1.0, "right"), (2.0, "right"), (5.0, "both"), (50.0, "both")])
def test_a_pair_of_piers_with_a_tie(T, regime):
    """Piers b_L = 0.1, b_R = 0.03, h = 0.2 (2h tall), a tie at z = 0.3 above their feet of yield force T.
    Loads along +x, each pier rocks about its right foot: the right pier alone lengthens the tie at
    z per unit rotation, lambda_R = b_R / h + T z / (m_R g h); both together at one rate leave it
    unstrained, lambda_2 = (m_L b_L + m_R b_R) / ((m_L + m_R) h); the left alone shortens it (slack),
    lambda_L = b_L / h. The least governs."""
    bL, bR, h, z = 0.1, 0.03, 0.2, 0.3
    s = _pair(bL, bR, h, 0.4)
    mL, mR = s.bodies[0].mass, s.bodies[1].mass
    link = tie_link(s, Tie(z - 2 * h, 1e-6, max(T, 1e-9) / 1e-6))
    assert link.a == 0 and link.b == 1 and link.p_a[0] < 0 < link.p_b[0]
    lam_R = bR / h + T * z / (mR * G * h)
    lam_2 = (mL * bL + mR * bR) / ((mL + mR) * h)
    lp = solve_lp(s, math.inf, math.inf, load_sign=1, ties=(link,))
    assert (lam_R < lam_2) == (regime == "right") and bL / h > lam_2
    assert lp.lam == pytest.approx(min(lam_R, lam_2, bL / h), rel=1e-8)
    if lam_R < lam_2:  # the right pier rocks alone and the tie yields
        assert lp.tie_forces[0] == pytest.approx(T, rel=1e-6, abs=1e-9)


def test_bad_ties_are_refused_in_one_line():
    s = _pair(0.1, 0.03, 0.2, 0.4)
    with pytest.raises(ArchdemInputError, match="tie area must be positive"):
        Tie(0.0, -1e-4, 235e6)
    with pytest.raises(ArchdemInputError, match="tie prestress must be in"):
        Tie(0.0, 1e-4, 235e6, prestress=1e6)
    with pytest.raises(ArchdemInputError, match="at or above the crown"):
        tie_link(s, Tie(0.5, 1e-4, 235e6))
    with pytest.raises(ArchdemInputError, match="at or below the structure's base"):
        tie_link(s, Tie(-1.0, 1e-4, 235e6))
    assert np.isfinite(Tie(0.0, 1e-4, 235e6).force)


def _work_alpha0(sc):
    """Virtual work of the LP's mechanism: (V'(0) + the strips' and the tie's work) / horizontal work of the weights."""
    fb = sc.mechanism
    _, _, dV, S = fb.terms(0.0)
    return (dV + sc.extra_force(0.0)) / (G * -fb.direction * S)


@pytest.mark.parametrize("case, height, T, with_strips", [
    ("lab", -0.2, 2.0, False), ("lab", -0.2, 1.0, True), ("noh half", 0.0, 5e3, False),
    ("noh full", -3.03, 20e3, False), ("noh full", 0.662, 5e3, True)])
def test_an_arch_on_piers_with_a_yielding_tie(case, height, T, with_strips):
    """The LP's multiplier with a tie (at the pier tops, in the piers or across the ring) equals the work
    balance of its own mechanism, the tie yielding where the mechanism lengthens it, to 1e-8; it lies
    above the untied structure's."""
    if case == "lab":
        arch, piers, rho = get_specimen("Sh06-Sd015").arch, Piers(0.4, 0.144, courses=2), 500.0
        strips = Strips(100e6, 0.01e-3, 0.02, design_strength=10e6) if with_strips else None
    else:
        arch, rho = NOH_GUMBAD.arch, NOH_GUMBAD.density
        piers = NOH_GUMBAD.configurations["half-height piers" if case == "noh half" else "full-height piers"]
        strips = Strips(1964e6, 0.047e-3, 0.68, design_strength=700e6) if with_strips else None
    bare = strengthened_collapse(arch, strips, rho, piers, load_sign=1).lam
    sc = strengthened_collapse(arch, strips, rho, piers, load_sign=1, tie=Tie(height, 1e-4, T / 1e-4))
    assert len(sc.hinges) == 4 and sc.tie_lp_force == pytest.approx(T, rel=1e-6)  # the tie yields
    assert sc.lam == pytest.approx(_work_alpha0(sc), rel=1e-8) and sc.tie_force(0.0) > 0
    assert sc.lam > bare


def test_a_tie_that_holds_is_refused_by_the_kinematic_analysis():
    """A strong tie at the lab arch's pier tops does not yield: the LP's mechanism keeps its length with five
    hinges, which the one-degree-of-freedom analysis does not build; said in one line."""
    with pytest.raises(ArchdemInputError, match="5 hinges.*the tie holds without yielding"):
        strengthened_collapse(get_specimen("Sh06-Sd015").arch, None, piers=Piers(0.4, 0.144, courses=2), load_sign=1,
                              tie=Tie(0.0, 1e-4, 20.0 / 1e-4))
