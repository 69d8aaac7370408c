"""A failure domain as ``archdem domain`` asks for it (:class:`DomainSpec`, :func:`run`), called from
Python: its checks, its grids and defaults, and the analytic answer printed by its result."""
from __future__ import annotations

import inspect
import math
import re

import pytest

from analytic.rocking.domain import failure_domain
from analytic.rocking.rocking_block import RockingBlock
from dem.common.request import ArchRequest
from dem.core.settings import DYNAMICS_ENGINE
from dem.experiments.shake.domain import AnalyticDomain, dem_failure_domain
from dem.experiments.shake.domain_spec import A_MAX, DEM_A_MAX, DomainSpec, run
from dem.experiments.shake.step_shake import SHAKE_FREQS
from foundation.errors import ArchdemInputError

BLOCK = ArchRequest(block=(0.1, 0.5))
ARCH = ArchRequest(id="Sh02-Sd020")


def test_the_analytic_domain_of_a_block_is_the_librarys():
    res = run(DomainSpec(request=BLOCK, model="block", input="A", durations="0.2,0.4", scan=10, tol=1e-3, amax=20,
                         workers=1))
    assert isinstance(res, AnalyticDomain)
    lib = failure_domain(RockingBlock(0.1, 0.5), "A", [0.2, 0.4], a_max_ratio=20, n_scan=10, tol=1e-3, workers=1)
    out = res.to_json()
    assert out["points"] == lib.points() and out["lambda"] == pytest.approx(0.2, rel=1e-12)
    assert out["restitution"] == pytest.approx(1 - 1.5 * math.sin(math.atan(0.2)) ** 2, rel=1e-12)
    lines = res.lines()
    assert len(lines) == 3 and lines[1].startswith("       0.2 s: collapse from")


def test_grids_and_defaults():
    assert DomainSpec(request=BLOCK).xs == [1.0 + 0.5 * k for k in range(39)]  # 1:20:0.5 Hz
    assert DomainSpec(request=BLOCK, input="B").xs[:2] == [0.05, 0.1]  # s
    dem = DomainSpec(request=ARCH, engine="dem")
    assert dem.xs == list(SHAKE_FREQS) and dem.physics_engine == DYNAMICS_ENGINE
    # the analytic scan's top means the DEM's own there; another value is kept
    assert A_MAX != DEM_A_MAX and dem.dem_a_max == DEM_A_MAX == inspect.signature(dem_failure_domain).parameters["a_max_ratio"].default
    assert DomainSpec(request=ARCH, engine="dem", amax=3.0).dem_a_max == 3.0


@pytest.mark.parametrize("kw, msg", [
    ({"input": "A", "freq": "2"}, "pulses A/B take --durations, not --freq"),
    ({"durations": "0.2"}, "sine inputs take --freq, not --durations"),
    ({"tol": 0.0}, "--tol must be a relative tolerance in"),
    ({"amax": 1.0}, "--amax must be a ratio to the static onset in"),
    ({"scan": 1}, "--scan must be 2 to"),
    ({"freq": "200"}, "values must be in"),
    ({"restitution": "2"}, "--restitution must be in"),
    ({"engine": "dem", "request": BLOCK}, "--engine dem takes an arch"),
    ({"engine": "dem", "input": "A"}, "--engine dem runs one-cycle sines only"),
    ({"engine": "dem", "durations": "0.2"}, "--engine dem takes --freq, not --durations"),
    ({"engine": "dem", "tol": 0.02, "given": frozenset({"tol"})}, "--tol does nothing here"),
    ({"engine": "dem", "freq": "4,,6"}, "--freq: expected a list"),
    ({"engine": "dem", "freq": "2,1e20"}, "--freq [Hz] values must be in [0.01, 100]"),
])
def test_a_domain_spec_refuses_in_one_line(kw, msg):
    with pytest.raises(ArchdemInputError, match=re.escape(msg)):
        DomainSpec(**({"request": ARCH} | kw))
