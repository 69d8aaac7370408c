"""The DEM of arches on piers and of the rocking frame against limit analysis and the closed forms
(docs/validation.md#15-arches-on-piers)."""
import math

import pytest

from analytic.limit.limit_discrete import solve_lp
from analytic.motions.inputs import SinePulse
from analytic.rocking.domain import domain_column
from analytic.rocking.rocking_block import rocking_frame_equivalent
from dem.core.model import frame_model, from_assembly
from dem.core.settings import Settings
from dem.experiments.shake.run import ShakeProtocol, shake
from dem.experiments.tilt.run import tilt
from specimens import Piers, discretise, get_specimen
from specimens.constants import NO_SLIDING_MU, G
from specimens.frame import rocking_frame

B, H = 0.05, 0.2  # half-width and half-height of the frame's piers [m]


def _settings(engine: str, **kw) -> Settings:
    if engine == "mujoco":
        pytest.importorskip("mujoco", reason="the mujoco extra is not installed (pip install -e '.[mujoco]')")
    return Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, engine=engine, **kw)


@pytest.mark.parametrize("engine", ["pybullet", "mujoco"])
@pytest.mark.slow
def test_frame_tilt_is_b_over_h_whatever_the_lintel(engine):
    # measured +0.05 % in both engines for gamma 0.1 and 1.9; 1 %: the bisection's 0.5 % bracket and the
    # single block's +0.2 % rocking offset (docs/validation.md#3-single-block), with room
    for beam_density in (100.0, 5000.0):
        res = tilt(frame_model(rocking_frame(B, H, 0.3, 0.05, beam_density=beam_density)), _settings(engine))
        assert res.lam == pytest.approx(B / H, rel=0.01) and res.mode == "rocking"
        assert {j.joint for j in res.joints if j.state == "hinge"} == {"LP0", "L0", "R0", "RP0"}


@pytest.mark.parametrize("engine", ["pybullet", "mujoco"])
@pytest.mark.slow
def test_arch_on_four_course_loaded_piers_tilts_at_the_lp(engine):
    arch = get_specimen("Sh06-Sd015").arch
    asm = discretise(arch, piers=Piers(0.4, 3 * arch.t, courses=4, load=20.0))
    lp = solve_lp(asm, math.inf, math.inf)
    res = tilt(from_assembly(asm), _settings(engine))
    # the 3 % (measured: -0.43 % PyBullet, +0.05 % MuJoCo), with the hinges of the LP, one at the pier's foot
    assert abs(res.lam / lp.lam - 1) <= 0.03
    assert {j.joint for j in res.joints if j.state == "hinge"} == {j for j, _ in lp.hinges}
    assert "RP0" in {j for j, _ in lp.hinges}


def _closed_form_threshold(f, freq: float) -> float:
    """Overturning amplitude [m/s^2] of a plain one-cycle sine for the closed-form frame: the block of
    the same slenderness and R (1 + 3 gamma) / (1 + 2 gamma), with the frame's restitution."""
    blk, r = rocking_frame_equivalent(B, H, f.gamma)
    return domain_column(blk, "sine0", freq, 0.2 * G, 2 * G, n_scan=12, restitution=r).thresholds[0][0]


# Measured (planar, no sliding, piers 0.1 x 0.4 m, lintel 0.5 x 0.05 m; ratios 0.5 to 1.1 of the closed
# form at 2, 3 and 5 Hz): MuJoCo survives at every ratio up to 0.95 and collapses from 1.02 on, for a
# light (gamma 0.03) and a heavy (gamma 0.63) lintel: -5 % must survive, +2 % must collapse.
# PyBullet agrees at 2 Hz (collapse from 0.95, survival at 0.90 and below) but collapses far below the
# closed form at higher frequencies (5 Hz: from 0.70 with the light lintel, already at 0.50 with the
# heavy one): at an impact its piers leave the parallelogram and the lintel falls
# (docs/validation.md#15-arches-on-piers); only its 2 Hz agreement is checked.
@pytest.mark.parametrize("engine, beam_density, freq", [
    ("mujoco", 1000.0, 2.0), ("mujoco", 1000.0, 3.0), ("mujoco", 1000.0, 5.0), ("mujoco", 50.0, 5.0),
    ("pybullet", 1000.0, 2.0),
])
@pytest.mark.slow
def test_frame_overturning_amplitude_matches_the_closed_form(engine, beam_density, freq):
    f = rocking_frame(B, H, 0.3, 0.05, beam_density=beam_density)
    a_cf = _closed_form_threshold(f, freq)
    m, s, proto = frame_model(f), _settings(engine, planar=True), ShakeProtocol(tail=2.0)
    below = 0.05 if engine == "mujoco" else 0.10
    assert shake(m, SinePulse(1.02 * a_cf, freq), s, proto).collapsed
    assert not shake(m, SinePulse((1 - below) * a_cf, freq), s, proto).collapsed


def test_the_dem_domain_on_piers_stands_beside_the_four_bar_through_the_piers():
    from analytic.rocking.linkage import mechanism_four_bar
    from dem.experiments.shake.domain import analytic_domains

    arch, piers = get_specimen("Sh06-Sd015").arch, Piers(0.4, 0.144, courses=2)
    doms = analytic_domains(arch, [2.0], piers=piers)
    assert list(doms) == ["four-bar"]  # the two-bar has no piers
    assert doms["four-bar"].lam == pytest.approx(mechanism_four_bar(discretise(arch, piers=piers)).lam, rel=1e-12)
