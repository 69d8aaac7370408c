"""FRP strips: the static LP with the strips' tension against the kinematic work of the same mechanism."""
import math

import pytest

from analytic.codes.frp import Strips, strengthened_collapse
from analytic.rocking.linkage import RigidRotation, minimised_four_bar
from specimens import get_specimen
from specimens.constants import G
from specimens.errors import ArchdemInputError
from specimens.piers import Piers


def _kinematic_alpha0(sc):
    """Virtual work of the LP's mechanism: (V'(0) + strip work) / horizontal work of the weights."""
    fb = sc.mechanism
    _, _, dV, S = fb.terms(0.0)
    return (dV + sc.strip_force(0.0)) / (G * -fb.direction * S)


@pytest.mark.parametrize("face", ["extrados", "intrados"])
@pytest.mark.parametrize("piers", [None, Piers(0.4, 0.144, courses=2)])
def test_static_lp_equals_the_strips_work(face, piers):
    """Static and kinematic theorems meet: the LP's multiplier with the strips equals the work balance
    of its own mechanism (strip force T at a distance c from each hinge opening on the strips' side)."""
    arch = get_specimen("Sh06-Sd015").arch
    s = Strips(100e6, 0.01e-3, 0.02, face, design_strength=10e6)  # T = 2 N (the arch weighs ~17 N)
    sc = strengthened_collapse(arch, s, piers=piers)
    assert len(sc.hinges) == 4
    assert sc.lam == pytest.approx(_kinematic_alpha0(sc), rel=1e-8)
    assert sc.strip_force(0.0) > 0  # at least one hinge opens on the strips' side


def test_weak_strips_leave_the_bare_arch_and_strong_ones_hold_it_whole():
    arch = get_specimen("Sh06-Sd015").arch
    bare = minimised_four_bar(arch).lam
    weak = strengthened_collapse(arch, Strips(1e6, 1e-6, 1e-3, design_strength=1e3))  # T = 1e-6 N
    assert weak.lam == pytest.approx(bare, rel=2e-3)  # the fine cut of 96 voussoirs per side
    strong = strengthened_collapse(arch, Strips(2000e6, 0.05e-3, 0.05))
    # the ring no longer opens; it turns whole on a springing (a joint the strips do not cross)
    assert isinstance(strong.mechanism, RigidRotation) and strong.hinges[0][0] in ("L0", "R0")
    assert strong.lam == pytest.approx(_kinematic_alpha0(strong), rel=1e-8) and strong.lam > 3 * bare


def test_bad_strips_are_refused_in_one_line():
    with pytest.raises(ArchdemInputError, match="FRP thickness must be a positive number"):
        Strips(1964e6, -1.0, 0.68)
    with pytest.raises(ArchdemInputError, match="FRP face must be extrados or intrados"):
        Strips(1964e6, 0.047e-3, 0.68, face="inside")
    with pytest.raises(ArchdemInputError, match="FRP design strength"):
        Strips(1964e6, 0.047e-3, 0.68, design_strength=math.inf)
    assert Strips(1964e6, 0.047e-3, 0.68).force == pytest.approx(1964e6 / 1.1 * 0.047e-3 * 0.68)
