"""The linkage a command asks for (:class:`LinkageOptions`) and one time history of it (:class:`RockSpec`,
:func:`rock`, :class:`RockResult`), called from Python as ``archdem rock`` calls them."""
from __future__ import annotations

import math
import re

import pytest

from analytic.rocking.domain import make_input
from analytic.rocking.dynamics import simulate
from analytic.rocking.rocking_block import RockingBlock
from dem.common.request import ArchRequest
from dem.experiments.shake.linkage import LinkageOptions, RockSpec, rock
from foundation.errors import ArchdemInputError
from specimens.constants import G

BLOCK = ArchRequest(block=(0.1, 0.5))


def test_a_block_rocks_as_the_library_simulates_it():
    res = rock(RockSpec(request=BLOCK, model="block", freq=2.0, amplitude=0.3))
    blk = RockingBlock(0.1, 0.5)
    lib = simulate(blk, make_input("sine", 0.3 * G, 2.0, abs(blk.onset))).summary()
    out = res.to_json()
    assert {k: out[k] for k in lib} == lib and out["model"] == res.mechanism.summary()
    head, verdict = res.lines()
    assert head == f"block b=0.1 h=0.5  {res.mechanism.label}  lambda 0.2000  phi_cr {res.mechanism.phi_cr:.4g} rad"
    assert verdict.startswith("COLLAPSE" if lib["collapsed"] else "survival")
    assert f"impacts {lib['n_impacts']}" in verdict


@pytest.mark.parametrize("kw, msg", [
    ({"freq": 2.0}, "--amplitude (in g) must be a positive number up to 100, got None"),
    ({"amplitude": 0.3}, "--freq (Hz) is needed for sines"),
    ({"input": "A", "amplitude": 0.3}, "--duration (s) is needed for pulses A/B"),
    ({"freq": 0.0, "amplitude": 0.3}, "--freq [Hz] must be in [0.01, 100], got 0"),
    ({"freq": 2.0, "amplitude": 0.3, "restitution": "1.5"}, "--restitution must be in [0, 1], got 1.5"),
    ({"record": "r.csv"}, "--scale (a positive factor) is needed with --record"),
    ({"freq": 2.0, "amplitude": 0.3, "scale": 2.0, "given": frozenset({"scale"})}, "--scale does nothing here"),
])
def test_a_rock_spec_refuses_in_one_line(kw, msg):
    with pytest.raises(ArchdemInputError, match="^" + re.escape(msg)):
        RockSpec(request=BLOCK, **kw)


def test_the_phased_sine_below_the_onset_is_refused():
    with pytest.raises(ArchdemInputError, match="needs amplitude >= onset lambda = 0.2000 g"):
        rock(RockSpec(request=BLOCK, freq=2.0, amplitude=0.1))


@pytest.mark.parametrize("kw, msg", [({"model": "three-bar"}, "--model must be one of four-bar, two-bar, block"),
                                     ({"input": "C"}, "--input must be one of sine, sine0, A, B")])
def test_a_choice_outside_the_options_is_refused(kw, msg):
    with pytest.raises(ArchdemInputError, match=msg):
        LinkageOptions(**kw)


def test_restitution_auto_is_the_momentum_balance():
    assert LinkageOptions().energy_restitution is None
    assert LinkageOptions(restitution="0.9").energy_restitution == 0.9
    with pytest.raises(ArchdemInputError, match="'auto' or a number"):
        LinkageOptions(restitution="x").energy_restitution  # noqa: B018


@pytest.mark.parametrize("kw, msg", [
    ({"request": BLOCK, "model": "two-bar"}, "--block goes with --model block"),
    ({"request": ArchRequest(id="Sh06-Sd015"), "model": "block"}, "--model block needs --block B H"),
    ({"request": ArchRequest(id="Sh06-Sd015"), "layout": "1,2"}, "--layout"),
    ({"request": ArchRequest(id="Sh06-Sd015", contact=0.8), "model": "two-bar"}, "--contact is not modelled"),
    ({"request": BLOCK, "layout": "oppenheim", "given": frozenset({"layout"})}, "--layout does nothing here"),
])
def test_a_linkage_that_cannot_be_built_is_refused(kw, msg):
    with pytest.raises(ArchdemInputError, match=msg):
        LinkageOptions(**kw).mechanism()


def test_the_four_bar_by_default():
    label, fb = LinkageOptions(request=ArchRequest(id="Sh06-Sd015")).mechanism()
    assert label == "Sh06-Sd015" and fb.label.startswith("four-bar")
    assert math.isfinite(fb.lam) and fb.lam > 0
