"""The driven-base load (the base moved by the ground displacement under plain gravity) against
the default uniform inertial field (fixed base, horizontal gravity): both must give the same
relative motion and the same shake threshold (issue: within 2 %, one case)."""
import math

import numpy as np
import pytest

from analytic.motions.inputs import SinePulse
from dem.core.engines import available_engines, get_engine
from dem.core.model import from_assembly
from dem.core.settings import Settings
from dem.experiments.shake.run import ShakeProtocol, shake
from dem.experiments.shake.thresholds import threshold
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from specimens.constants import G
from foundation.errors import ArchdemInputError

ENGINES = [e for e in ("pybullet", "mujoco") if e in available_engines()]


@pytest.fixture(scope="module")
def arch():
    return from_assembly(discretise(get_specimen("Sh02-Sd020").arch, config="glued"))


@pytest.mark.parametrize("engine", ENGINES)
def test_base_follows_prescribed_displacement(arch, engine):
    # 0.5 s of a 4 Hz, 5 mm displacement with the arch standing on the base: the heavy base lands
    # on the prescribed position every step (0.3 um measured for such a base, docs/physics/dem.md#13-driven-base-or-inertial-field; 1 um
    # is the bound asserted, 1/100 of the 0.1 mm at-rest drift allowed for the arch)
    s = Settings(engine=engine)
    e = get_engine(engine)
    e.build(arch, s, driven_base=True)
    try:
        w, amp, err = 2 * math.pi * 4.0, 5e-3, 0.0
        for k in range(1, int(0.5 / s.dt) + 1):
            t = k * s.dt
            e.drive_base(amp * math.sin(w * t), amp * w * math.cos(w * t))
            e.step(1)
            err = max(err, abs(e.base_motion()[0] - amp * math.sin(w * t)))
    finally:
        e.close()
    assert err < 1e-6


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.slow
def test_below_rocking_onset_the_arch_moves_with_the_base(arch, engine):
    # 0.3 g at 4 Hz is below this arch's static onset (lambda 0.35): the arch must ride on the base.
    # The ground moves ~5 mm (a / omega^2), so an arch left behind by a base that does not drag it
    # would show mm of table-frame displacement; 0.1 mm is the at-rest drift bound (docs/validation.md#2-at-rest).
    m = SinePulse(0.3 * G, 4.0)
    # the whole duration (no end at rest, which the two loads reach at different records), so that
    # the recorded fields can be compared record by record
    runs = {ld: shake(arch, m, Settings(engine=engine), ShakeProtocol(load=ld, tail=0.25, rest_after=None))
            for ld in ("inertial", "driven-base")}
    for ld, r in runs.items():
        assert not r.collapsed, ld
        assert r.sim.history.dmax.max() < 1e-4, ld
    assert runs["driven-base"].summary()["load"] == "driven-base"
    assert runs["driven-base"].sim.load["load"] == "driven-base"
    # the recorded field is the table-frame equivalent in both cases (what the animation shows)
    np.testing.assert_allclose(runs["driven-base"].sim.history.gravity, runs["inertial"].sim.history.gravity)


@pytest.mark.slow
def test_threshold_same_with_driven_base(arch):
    """Least collapsing one-cycle 4 Hz sine of Sh02-Sd020 (glued, reference friction, PyBullet):
    inertial field and driven base within 2 % (the issue's tolerance; measured +0.8 %: 0.4554 g
    and 0.4592 g from a full scan). The scan is narrowed to 0.40-0.60 g around that ~0.45 g
    (docs/validation.md#11-driven-base-against-inertial-field) to keep the test near one minute;
    each bracket is bisected to 1 %."""
    res = {ld: threshold(arch, 4.0, Settings(), ShakeProtocol(load=ld), a_min_g=0.40, a_max_g=0.60,
                         scan_ratio=1.1, tol=0.01)
           for ld in ("inertial", "driven-base")}
    a_i, a_d = res["inertial"].amplitude_g, res["driven-base"].amplitude_g
    assert a_i is not None and a_d is not None
    assert abs(a_d / a_i - 1) <= 0.02, (a_i, a_d)


def test_unknown_load_is_an_input_error():
    with pytest.raises(ArchdemInputError, match="shake load"):
        ShakeProtocol(load="moving-table")
