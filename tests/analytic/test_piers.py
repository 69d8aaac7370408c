"""Limit analysis and linkages of arches on piers, against the rocking frame's closed forms."""
import math

import pytest

from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
from analytic.rocking.domain import domain_column
from analytic.rocking.impact import energy_restitution
from analytic.rocking.linkage import mechanism_four_bar
from analytic.rocking.rocking_block import rocking_frame_equivalent
from specimens import Piers, discretise, get_specimen
from specimens.constants import G
from specimens.frame import rocking_frame

B, H = 0.05, 0.2  # half-width and half-height of the frame's piers [m]


def frame(beam_density: float):
    return rocking_frame(B, H, 0.3, 0.05, beam_density=beam_density)


@pytest.mark.parametrize("beam_density", [0.5, 500.0, 5000.0, 50000.0])
def test_frame_onset_is_b_over_h_whatever_the_lintel(beam_density):
    f = frame(beam_density)
    kin, lp = enumerate_mechanisms(f), solve_lp(f, math.inf, math.inf)
    assert kin.lam == pytest.approx(B / H, rel=1e-12) and lp.lam == pytest.approx(B / H, rel=1e-9)
    # each pier rocks on its base corner towards the load and carries the lintel on its opposite top corner
    assert kin.hinges == (("LP0", "intrados"), ("L0", "extrados"), ("R0", "intrados"), ("RP0", "extrados"))
    assert lp.hinges == kin.hinges
    assert mechanism_four_bar(f).lam == pytest.approx(B / H, rel=1e-9)


@pytest.mark.parametrize("beam_density", [50.0, 500.0, 5000.0])
def test_frame_four_bar_is_the_closed_form_rocking_frame(beam_density):
    f = frame(beam_density)
    fb, (blk, r) = mechanism_four_bar(f), rocking_frame_equivalent(B, H, f.gamma)
    alpha = math.atan(B / H)
    assert energy_restitution(fb, fb.face_swapped()) == pytest.approx(r, rel=1e-9)
    assert fb.omega0 == pytest.approx(blk.omega0, rel=1e-9) and fb.phi_cr == pytest.approx(alpha, rel=1e-7)


@pytest.mark.parametrize("freq", [1.0, 2.0, 4.0])
@pytest.mark.slow
def test_frame_overturning_amplitude_matches_the_equivalent_block(freq):
    """One-cycle sine: the four-bar of the frame's discrete mechanism and the closed-form frame (a
    block of the same slenderness, R (1 + 3 gamma)/(1 + 2 gamma), with the frame's restitution)
    overturn from the same amplitude (both bisected to 0.1 %); a heavier lintel needs a larger one."""
    thresholds = []
    for beam_density in (50.0, 2000.0):
        f = frame(beam_density)
        a_fb = domain_column(mechanism_four_bar(f), "sine0", freq, 0.2 * G, 3 * G, n_scan=12).thresholds[0][0]
        blk, r = rocking_frame_equivalent(B, H, f.gamma)
        a_cf = domain_column(blk, "sine0", freq, 0.2 * G, 3 * G, n_scan=12, restitution=r).thresholds[0][0]
        assert a_fb == pytest.approx(a_cf, rel=2e-3)
        thresholds.append(a_cf)
    assert thresholds[1] > thresholds[0]


ARCH = get_specimen("Sh06-Sd015").arch


@pytest.mark.parametrize("piers", [Piers(0.1, 0.1), Piers(0.2, 0.08, courses=2), Piers(0.35, 0.1, offset=0.01, courses=4, load=10.0)])
def test_lp_without_sliding_is_the_enumeration_on_piers(piers):
    asm = discretise(ARCH, piers=piers)
    kin, lp = enumerate_mechanisms(asm), solve_lp(asm, math.inf, math.inf)
    assert lp.lam == pytest.approx(kin.lam, rel=1e-7) and lp.hinges == kin.hinges
    assert solve_lp(asm, 0.577, 1.0).lam <= lp.lam + 1e-9  # friction only takes strength away
    assert mechanism_four_bar(asm).lam == pytest.approx(kin.lam, rel=1e-9)  # symmetric: either direction


def test_taller_piers_lower_lambda_and_take_the_hinges():
    lams, hinges = [], []
    for h in (0.0, 0.1, 0.2, 0.3, 0.4):
        asm = discretise(ARCH) if h == 0 else discretise(ARCH, piers=Piers(h, 2 * ARCH.t, courses=4))
        kin = enumerate_mechanisms(asm)
        lams.append(kin.lam)
        hinges.append({j for j, _ in kin.hinges})
    assert all(b <= a + 1e-12 for a, b in zip(lams, lams[1:])) and lams[-1] < 0.8 * lams[0]
    assert lams[1] == pytest.approx(lams[0], rel=1e-12)  # short stout piers: the ring's own mechanism
    assert not any(j.startswith(("LP", "RP")) for j in hinges[0]) and "RP0" in hinges[-1]


def test_a_heavy_pier_load_leaves_the_pier_rocking_under_its_top_mass():
    """With loads far above the weights, the loaded pier rocks on its outer foot with the load at
    its top's centre: lambda = (B / 2) / H."""
    height, width = 0.4, 3 * ARCH.t
    lams = [solve_lp(discretise(ARCH, piers=Piers(height, width, courses=4, load=p)), math.inf, math.inf).lam
            for p in (0.0, 20.0, 1e7)]
    assert lams[0] > lams[1] > lams[2]  # the load's inertia overturns the pier (masonry above, not a prestress)
    assert lams[2] == pytest.approx(width / 2 / height, rel=1e-5)


def test_hinges_anywhere_on_piers():
    """The fine LP finds the continuous ring's own multiplier on short stout piers, and on tall piers
    a multiplier below the voussoirs' with the last hinge at the pier's foot; halving the cut moves it
    by less than 0.1 %."""
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.limit.limit_piers import continuous_on_piers

    short = continuous_on_piers(ARCH, Piers(0.1, 3 * ARCH.t, courses=2))
    assert short.lam == pytest.approx(continuous_collapse(ARCH).lam, rel=1e-4)
    assert not any("pier" in h for h in short.hinges) and short.pier_courses % 2 == 0
    tall_piers = Piers(0.54, 3 * ARCH.t, courses=4)
    tall = continuous_on_piers(ARCH, tall_piers)
    assert tall.lam <= enumerate_mechanisms(discretise(ARCH, piers=tall_piers)).lam
    assert abs(tall.lam / tall.lam_half - 1) < 1e-3
    assert tall.hinges[-1] == {"joint": "RP0", "face": "extrados", "pier": "right", "height_m": 0.0}
