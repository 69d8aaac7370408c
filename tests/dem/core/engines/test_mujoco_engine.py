"""MuJoCo backend specifics: construction, options, contact forces in equilibrium, and the
no-sliding lambda and hinges against the discrete limit analysis at MuJoCo's tolerance (the
validation shared with every engine is in test_engines_shared.py)."""
import numpy as np
import pytest

pytest.importorskip("mujoco", reason="the mujoco extra is not installed (pip install -e '.[mujoco]')")

from dem.core.engines import available_engines, get_engine  # noqa: E402
from dem.core.engines.mujoco_engine import (  # noqa: E402
    DEFAULT_OPTIONS,
    MuJoCoOptions,
    mjcf,
    substeps,
)
from dem.core.model import from_assembly, single_block  # noqa: E402
from dem.core.settings import Settings
from dem.experiments.tilt.run import tilt  # noqa: E402
from specimens.blocks import discretise  # noqa: E402
from specimens.catalogue import get_specimen  # noqa: E402
from specimens.constants import NO_SLIDING_MU  # noqa: E402

ENGINE = "mujoco"
B, H = 0.1, 0.2  # b/h = 0.5


def _s(**kw) -> Settings:
    return Settings(engine=ENGINE, **kw)


def test_registered():
    assert ENGINE in available_engines()
    assert get_engine(ENGINE).name == ENGINE


def test_substeps_keep_internal_step_at_most_max_dt():
    # identity: n equal sub-steps of dt/n, each <= max_dt, and no more than needed
    for dt in (1e-3, 5e-4, 2.5e-4, 7e-4, 2e-3):
        n = substeps(dt, 5e-4)
        assert dt / n <= 5e-4 * (1 + 1e-12) and (n == 1 or dt / (n - 1) > 5e-4)


def test_built_geometry_mass_and_friction():
    # the compiled model reproduces the engine-neutral one: vertices of every piece (to 1e-7 m,
    # MuJoCo stores meshes in float32 about their own centroid), masses, inertia, and the
    # friction rule (priority) giving block-block mu_joint and block-base mu_base
    import mujoco

    from specimens.mesh import prism

    m = from_assembly(discretise(get_specimen("Sh06-Sd010").arch, config="free"))
    s = _s(mu_joint=0.577, mu_base=1.0)
    e = get_engine(ENGINE)
    e.build(m, s)
    try:
        M, D = e._m, e._d
        for i, b in enumerate(m.bodies):
            bid = e._bid[i]
            # 10 significant digits: the engine gets masses rounded so that they are the same on
            # every machine (dem.core.engines.inputs.significant), relative change <= 5e-10
            assert M.body_mass[bid] == pytest.approx(b.mass, rel=1e-9)
            # inertia about the centroid: principal moments agree with the model's tensor
            assert np.sort(M.body_inertia[bid]) == pytest.approx(np.linalg.eigvalsh(b.inertia), rel=1e-9)
            assert M.body_ipos[bid] == pytest.approx(np.zeros(3), abs=1e-12)
            for k, poly in enumerate(b.pieces):
                gid = mujoco.mj_name2id(M, mujoco.mjtObj.mjOBJ_GEOM, f"b{i}p{k}")
                mid = M.geom_dataid[gid]
                v = M.mesh_vert[M.mesh_vertadr[mid]:M.mesh_vertadr[mid] + M.mesh_vertnum[mid]]
                w = D.geom_xpos[gid] + v @ D.geom_xmat[gid].reshape(3, 3).T
                ref = np.asarray(prism(poly, b.width, s.engine_options.inflate).vertices)
                assert np.sort(w, axis=0) == pytest.approx(np.sort(ref, axis=0), abs=1e-7)
        mujoco.mj_forward(M, D)
        assert D.ncon > 0
        for k in range(D.ncon):
            c = D.contact[k]
            base = -1 in (e._index[M.geom_bodyid[c.geom1]], e._index[M.geom_bodyid[c.geom2]])
            assert c.friction[0] == pytest.approx(1.0 if base else 0.577, rel=1e-12)
    finally:
        e.close()


def test_contact_forces_balance_the_weight_at_rest():
    # equilibrium (independent of the solver): the base reactions on the blocks carry the total
    # weight and have no net horizontal part. Averaged over 20 steps: single-step impulses of the
    # soft contacts fluctuate by ~0.5 N on a 6.8 N thrust at 0.25 ms; 1 % of the weight
    m = from_assembly(discretise(get_specimen("Sh1-Sd025").arch, config="glued"))
    s = _s()
    e = get_engine(ENGINE)
    e.build(m, s)
    try:
        e.step(500)
        tot = np.zeros(3)
        for _ in range(20):
            e.step(1)
            c = e.contacts()
            f = c.fn[:, None] * c.normal + c.ft  # force on a from b
            tot += f[c.b == -1].sum(0) - f[c.a == -1].sum(0)
        on_blocks = tot / 20
        assert on_blocks[1] == pytest.approx(m.total_mass * s.g, rel=0.01)
        assert abs(on_blocks[0]) < 0.01 * m.total_mass * s.g
    finally:
        e.close()


import analytic.limit.limit_discrete as lim  # noqa: E402 (the LP the MuJoCo tests below check against)


# representative subset: the thinnest pointed arch free (PyBullet's worst case, -4 %) and the thickest
# sharp arch glued (measured -0.4 % and -0.07 %); Sh02-Sd020 glued runs in test_compare_engines.py
# and all 11 glued specimens in `archdem compare-engines` (max |error| 0.46 %)
@pytest.mark.parametrize("sid,config", [("Sh06-Sd010", "free"), ("Sh1-Sd025", "glued")])
@pytest.mark.slow
def test_no_sliding_lambda_and_hinges_match_lp(sid, config):
    asm = discretise(get_specimen(sid).arch, config=config)
    m = from_assembly(asm, name=sid)
    ns = tilt(m, _s(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU))
    lp = lim.solve_lp(asm, float("inf"), float("inf"))
    # the tolerance is 3 % (aim 1 %); the hold protocol's bisection tolerance is 0.5 %
    assert abs(ns.lam - lp.lam) / lp.lam <= 0.01
    hinges = tuple((j.joint, j.face) for j in ns.joints if j.state in ("hinge", "hinge+slide"))
    assert hinges == lp.hinges
    assert ns.mode == "rocking"


def test_options_reach_the_model():
    # the MJCF carries the documented options; a smaller settings.dt refines the internal step
    m = single_block(B, H)
    xml = mjcf(m, _s(dt=2.5e-4), MuJoCoOptions(noslip_iterations=7))
    assert 'timestep="0.00025"' in xml and 'noslip_iterations="7"' in xml and 'cone="elliptic"' in xml
    v = get_engine(ENGINE)
    v.build(m, _s())
    try:
        assert v.versions()["engine"] == ENGINE and v.versions()["mujoco"]
        assert v._m.opt.timestep == pytest.approx(DEFAULT_OPTIONS.max_dt)  # 0.5 ms -> 2 x 0.25 ms
    finally:
        v.close()
    # options given to get_engine (Settings.engine_options) reach the model and its provenance
    o = MuJoCoOptions(noslip_iterations=7, max_dt=1.25e-4)
    v = get_engine(ENGINE, o)
    v.build(m, _s(engine_options=o))
    try:
        assert v._m.opt.noslip_iterations == 7 and v._m.opt.timestep == pytest.approx(1.25e-4)
        assert v.versions()["mujoco_options"] == o.to_dict()
    finally:
        v.close()


def test_restitution_is_refused_not_dropped():
    """MuJoCo's soft contacts have no restitution coefficient: a setting it cannot run is refused in one line."""
    from dem.core.engines import get_engine
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from foundation.errors import ArchdemInputError
    from specimens.catalogue import get_specimen
    from specimens.blocks import discretise

    eng = get_engine("mujoco")
    with pytest.raises(ArchdemInputError, match="plastic impacts only"):
        eng.build(from_assembly(discretise(get_specimen("Sh06-Sd015").arch)), Settings(engine="mujoco", restitution=0.3))
