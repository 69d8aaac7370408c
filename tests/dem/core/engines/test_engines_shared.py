"""The validation every engine passes (docs/validation.md#1-how-to-reproduce), one test parametrised over the engines:
single block slides at mu / rocks at b/h under tilt, rest drift of two specimens, determinism
(also with two instances alive in one process), and the planar option.

Engine-specific checks (construction, options, contact forces, the no-sliding lambda against the
discrete LP with each engine's measured tolerance) stay in test_engine_<name>.py and
test_tilt_validation.py."""
import numpy as np
import pytest

from dem.core.engines import available_engines, engine_installed, get_engine
from dem.core.loads import Rest, TiltHold
from dem.core.model import from_assembly, single_block
from dem.core.settings import Settings
from dem.core.simulate import simulate
from dem.experiments.tilt.run import TiltProtocol, tilt
from specimens.blocks import discretise
from specimens.catalogue import get_specimen

B, H = 0.1, 0.2  # b/h = 0.5


ENGINES = [pytest.param(e, marks=[pytest.mark.skipif(not engine_installed(e), reason=f"{e} is not installed")]
                        + ([pytest.mark.slow] if e == "lmgc90" else []))  # a worker process per simulation
           for e in available_engines()]


@pytest.fixture(params=ENGINES)
def engine(request) -> str:
    return request.param


def test_every_engine_is_covered():
    assert {"pybullet", "mujoco", "lmgc90"} <= set(available_engines())


@pytest.mark.slow
def test_block_slides_at_mu(engine):
    # mu < b/h: the block slides at lambda = mu (Coulomb); 2 % = the tolerance
    mu = 0.3
    r = tilt(single_block(B, H), Settings(engine=engine, mu_joint=1.0, mu_base=mu), TiltProtocol())
    assert r.lam == pytest.approx(mu, rel=0.02)
    assert r.mode == "sliding"
    assert r.joints[0].state == "slide"


def test_block_rocks_at_b_over_h(engine):
    # mu > b/h: the block overturns about its downhill (+x, "extrados") corner at lambda = b/h
    r = tilt(single_block(B, H), Settings(engine=engine, mu_joint=1.0, mu_base=1.0), TiltProtocol())
    assert r.lam == pytest.approx(B / H, rel=0.02)  # the validation rule (docs/validation.md#1-how-to-reproduce)
    # this case: measured +0.20 % with both engines; 1 % = twice the bisection's 0.5 % bracket
    assert r.lam == pytest.approx(B / H, rel=0.01)
    assert r.mode == "rocking"
    assert (r.joints[0].state, r.joints[0].face) == ("hinge", "extrados")


# representative subset: the thin pointed arch free (its crown joints are nearest to the friction
# limit) and the thickest glued one; all 22 cases run in benchmarks/validate_dem.py
@pytest.mark.parametrize("sid,config", [("Sh06-Sd010", "free"), ("Sh1-Sd025", "glued")])
@pytest.mark.slow
def test_rest_drift(engine, sid, config):
    m = from_assembly(discretise(get_specimen(sid).arch, config=config))
    r = simulate(m, Settings(engine=engine), Rest(), 5.0, record_every=0.1, stop_on_collapse=False,
                 friction_work=False)
    assert not r.collapsed
    assert r.history.dmax.max() < 1e-4  # 0.1 mm in 5 s, the gate


def test_determinism_and_two_instances_in_one_process(engine):
    # identical command sequences give bit-identical histories, also with two instances alive
    m = single_block(B, H)
    s = Settings(engine=engine, mu_joint=1.0, mu_base=1.0)
    e1, e2 = get_engine(engine), get_engine(engine)
    e1.build(m, s)
    e2.build(m, s)
    try:
        for e in (e1, e2):
            e.set_gravity([6.0, -8.0, 0.0])  # lambda 0.75 > b/h: it rocks
            e.step(300)
        (p1, R1), (p2, R2) = e1.poses(), e2.poses()
        assert np.array_equal(p1, p2) and np.array_equal(R1, R2)
        assert np.abs(p1 - m.bodies[0].centroid).max() > 1e-3  # something happened
    finally:
        e1.close()
        e2.close()
    a = simulate(m, s, TiltHold(0.45, 0.3), 0.5)
    b = simulate(m, s, TiltHold(0.45, 0.3), 0.5)
    assert np.array_equal(a.history.pos, b.history.pos)


def test_planar_option_has_no_out_of_plane_motion(engine):
    # planar: out-of-plane motion removed (PyBullet: projected every step; MuJoCo: planar joints)
    if engine == "lmgc90":
        pytest.skip("compas_lmgc90 exposes no planar constraint: the lmgc90 engine refuses planar (test_lmgc90_engine.py)")
    m = single_block(B, H)
    r = simulate(m, Settings(engine=engine, mu_joint=1.0, mu_base=1.0, planar=True), TiltHold(0.6, 0.2), 0.6)
    assert r.collapsed
    assert r.out_of_plane["max_dz_history_m"] < 1e-9
