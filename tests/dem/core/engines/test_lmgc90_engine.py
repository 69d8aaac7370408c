"""LMGC90 backend specifics: what the binding cannot express is refused in one line, the built blocks
(hull of the key block), contact forces in equilibrium, a worker process per simulation, and the single
block under one-cycle sines against the rocking-block model (docs/validation.md#17-lmgc90; the validation
shared with every engine is in test_engines_shared.py)."""
import math

import numpy as np
import pytest

pytest.importorskip("compas_lmgc90", reason="the lmgc90 extra is not installed (pip install -e '.[lmgc90]')")

from analytic.motions.inputs import SinePulse  # noqa: E402
from dem.core.engines import available_engines, get_engine  # noqa: E402
from dem.core.engines.lmgc90_engine import convex_outline, hull_assembly, substeps  # noqa: E402
from dem.core.loads import Rest  # noqa: E402
from dem.core.model import from_assembly, single_block  # noqa: E402
from dem.core.settings import Settings  # noqa: E402
from dem.core.simulate import simulate  # noqa: E402
from specimens.blocks import discretise  # noqa: E402
from specimens.catalogue import get_specimen  # noqa: E402
from specimens.constants import NO_SLIDING_MU, G  # noqa: E402
from foundation.errors import ArchdemInputError  # noqa: E402

ENGINE = "lmgc90"


def _s(**kw) -> Settings:
    return Settings(engine=ENGINE, **kw)


def test_registered():
    assert ENGINE in available_engines()
    assert get_engine(ENGINE).name == ENGINE


def test_substeps_keep_internal_step_at_most_max_dt():
    for dt in (1e-3, 5e-4, 2.5e-4, 7e-4):
        n = substeps(dt, 2.5e-4)
        assert dt / n <= 2.5e-4 * (1 + 1e-12) and (n == 1 or dt / (n - 1) > 2.5e-4)


@pytest.mark.parametrize("kw, what", [
    ({"mu_joint": 0.577, "mu_base": 0.577, "planar": True}, "no planar option"),
    ({"mu_joint": 0.577, "mu_base": 0.577, "restitution": 0.5}, "plastic impacts only"),
    ({"mu_joint": 0.577, "mu_base": 0.577, "contact_law": "compliant", "kn": 1e9}, "rigid joints only"),
])
def test_what_the_binding_cannot_express_is_refused_in_one_line(kw, what):
    m = from_assembly(discretise(get_specimen("Sh06-Sd015").arch, config="free"))
    with pytest.raises(ArchdemInputError, match=what) as e:
        get_engine(ENGINE).build(m, _s(**kw))
    assert "\n" not in str(e.value)


def _stack(b: float = 0.1, h: float = 0.1, width: float = 0.1, density: float = 2000.0) -> "Model":
    """Two cubes stacked on a wide base: joint B0 (base - block 0), J1 (block 0 - block 1)."""
    from dem.core.model import BaseSpec, BodySpec, JointSpec, Model

    m = density * b * h * width
    inertia = np.diag([m * (h * h + width * width), m * (b * b + width * width), m * (b * b + h * h)]) / 12

    def block(k):
        poly = np.array([[-b / 2, k * h], [b / 2, k * h], [b / 2, (k + 1) * h], [-b / 2, (k + 1) * h]])
        return BodySpec(f"K{k}", (poly,), width, m, np.array([0.0, (k + 0.5) * h, 0.0]), inertia, poly)

    def joint(name, a, y):
        return JointSpec(name, a, a + 1, np.array([-b / 2, y]), np.array([b / 2, y]), np.array([0.0, 1.0]))

    return Model("stack", (block(0), block(1)), (joint("B0", -1, 0.0), joint("J1", 0, h)),
                 BaseSpec((np.array([[-1.0, -0.1], [1.0, -0.1], [1.0, 0.0], [-1.0, 0.0]]),), 0.4), 2 * h, 1)


@pytest.mark.parametrize("mu_joint, mu_base, slides", [(1.0, 0.3, "base"), (0.3, 1.0, "joint")])
def test_joint_and_base_frictions_are_each_their_own(mu_joint, mu_base, slides):
    # two cubes tilted to 0.35 (the stack rocks from 0.5, the top cube from 1): it slides where the friction is 0.3,
    # and only there (the see table written by the worker: the base's contactors in a colour of their own)
    from dem.core.loads import TiltHold

    r = simulate(_stack(), _s(mu_joint=mu_joint, mu_base=mu_base), TiltHold(0.35, 0.1), 0.5, record_every=0.05,
                 stop_on_collapse=False, friction_work=False)
    x0, x1 = (r.history.pos[-1, k, 0] - r.history.pos[0, k, 0] for k in (0, 1))
    base_slip, joint_slip = x0, x1 - x0
    # (0.35 - 0.3) g over ~0.45 s: ~5 cm of slip where it slides
    big, small = (base_slip, joint_slip) if slides == "base" else (joint_slip, base_slip)
    assert big > 0.02 and abs(small) < 0.1 * big


def test_the_key_block_is_built_as_its_hull_with_its_mass():
    # the pointed arch's key block has a cusp at the intrados: its hull adds a sliver (measured 5.17 % free,
    # 22.7 % glued on Sh06-Sd015); the hull assembly keeps every mass and moves only the key's centre of mass
    asm = discretise(get_specimen("Sh06-Sd015").arch, config="free")
    key = next(b for b in asm.bodies if b.name == "C")
    poly, extra = convex_outline(key)
    assert extra == pytest.approx(0.0517, abs=5e-4)
    hull = hull_assembly(asm)
    hkey = next(b for b in hull.bodies if b.name == "C")
    assert hkey.mass == key.mass and len(hkey.pieces) == 1
    assert hkey.centroid[1] < key.centroid[1]  # the sliver is below
    assert all(np.array_equal(a.centroid, b.centroid) for a, b in zip(asm.bodies, hull.bodies) if b.name != "C")


def test_contact_forces_at_rest_carry_the_weight():
    # a block at rest: the normal forces sum to its weight, the net friction force to nothing
    m = single_block(0.1, 0.2)
    e = get_engine(ENGINE)
    e.build(m, _s(mu_joint=1.0, mu_base=1.0))
    try:
        e.step(200)
        c = e.contacts()
        assert set(c.a.tolist()) | set(c.b.tolist()) == {-1, 0}
        w = m.bodies[0].mass * G
        assert c.fn.sum() == pytest.approx(w, rel=1e-6)
        assert np.linalg.norm(c.ft.sum(axis=0)) < 1e-6 * w
        pos, _ = e.poses()
        assert np.abs(pos - m.bodies[0].centroid).max() < 1e-8
    finally:
        e.close()


def test_each_simulation_runs_in_its_own_worker_process():
    import os

    e1, e2 = get_engine(ENGINE), get_engine(ENGINE)
    m = single_block(0.1, 0.2)
    e1.build(m, _s(mu_joint=1.0, mu_base=1.0))
    e2.build(m, _s(mu_joint=1.0, mu_base=1.0))
    try:
        pids = {e1._proc.pid, e2._proc.pid}
        assert len(pids) == 2 and os.getpid() not in pids
    finally:
        e1.close()
        e2.close()
    assert e1._proc is None and e2._proc is None


@pytest.mark.slow  # 2 s of LMGC90
def test_glued_arch_stands_at_rest():
    # the glued crown (built as its hull) with the joints' friction everywhere
    m = from_assembly(discretise(get_specimen("Sh06-Sd015").arch, config="glued"))
    r = simulate(m, _s(mu_joint=0.577, mu_base=0.577), Rest(), 1.0, record_every=0.1, stop_on_collapse=False,
                 friction_work=False)
    assert not r.collapsed and r.history.dmax.max() < 1e-5


# The single block of docs/validation.md#3-single-block (0.1 m x 0.4 m, b/h = 0.25, no sliding), in 3-D (LMGC90
# has no planar option; measured out-of-plane drift <= 2e-5 m): every run 2 % above the rocking-block amplitude
# collapses, every run 2 % below survives (measured at dt 0.5 ms: all six as asserted)
@pytest.mark.slow  # six LMGC90 shakes
@pytest.mark.parametrize("freq", [2.0, 3.0, 5.0])
def test_block_overturning_amplitude_matches_rocking_block_model(freq):
    from analytic.rocking.domain import failure_domain
    from analytic.rocking.rocking_block import RockingBlock
    from dem.experiments.shake.run import ShakeProtocol, shake

    B, H = 0.1, 0.4
    block = single_block(B, H)
    s = _s(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU)
    a_an = failure_domain(RockingBlock(B / 2, H / 2), "sine0", [freq], a_max_ratio=8.0, n_scan=16,
                          workers=1).columns[0].thresholds[0][0]
    proto = ShakeProtocol(tail=2.0)
    lo = shake(block, SinePulse(0.98 * a_an, freq), s, proto)
    hi = shake(block, SinePulse(1.02 * a_an, freq), s, proto)
    assert not lo.collapsed, f"{freq} Hz: collapsed 2 % below the rocking block's {a_an / G:.4f} g"
    assert hi.collapsed, f"{freq} Hz: survived 2 % above the rocking block's {a_an / G:.4f} g"
    assert hi.sim.out_of_plane["max_dz_history_m"] < 1e-3  # it rocks in its plane
    from dem.core.detect import in_plane_angle

    assert float(np.abs(in_plane_angle(hi.sim.history.rotations()[:, 0])).max()) > math.atan(B / H)


# No sliding (friction 10 everywhere), free configuration, against the LP of the blocks LMGC90 runs (the key block's
# hull, hull_assembly): measured +0.05 % (the bisection's) on the 11 catalogue specimens, with the LP's hinges
@pytest.mark.slow
@pytest.mark.parametrize("sid", ["Sh02-Sd015", "Sh02-Sd020", "Sh06-Sd010"])  # the three cheapest: 30-60 s each
def test_no_sliding_tilt_is_the_lp_of_the_same_blocks(sid):
    from analytic.limit.limit_discrete import solve_lp
    from dem.experiments.tilt.run import tilt

    asm = discretise(get_specimen(sid).arch, config="free")
    hull = hull_assembly(asm)
    lp = solve_lp(hull, math.inf, math.inf)
    r = tilt(from_assembly(asm), _s(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU), assembly=hull)
    assert abs(r.lam / lp.lam - 1) <= 0.02  # the 2 % gate of docs/validation.md#17-lmgc90
    assert {j.joint for j in r.joints if j.state.startswith("hinge")} == {j for j, _ in lp.hinges}


# The rocking frame (piers 0.1 x 0.4 m, lintel 0.5 x 0.05 m, heavy lintel gamma 0.63) against its closed form, in 3-D:
# measured survival at 0.95 and collapse at 1.02 of it at 2, 3 and 5 Hz (light lintel, gamma 0.03, likewise)
@pytest.mark.slow
@pytest.mark.parametrize("freq", [2.0, 3.0, 5.0])
def test_frame_overturning_amplitude_matches_the_closed_form(freq):
    from analytic.rocking.domain import domain_column
    from analytic.rocking.rocking_block import rocking_frame_equivalent
    from dem.core.model import frame_model
    from dem.experiments.shake.run import ShakeProtocol, shake
    from specimens.frame import rocking_frame

    B, H = 0.05, 0.2
    f = rocking_frame(B, H, 0.3, 0.05, beam_density=1000.0)
    blk, rest = rocking_frame_equivalent(B, H, f.gamma)
    a_cf = domain_column(blk, "sine0", freq, 0.2 * G, 2 * G, n_scan=12, restitution=rest).thresholds[0][0]
    m, s, proto = frame_model(f), _s(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU), ShakeProtocol(tail=2.0)
    assert shake(m, SinePulse(1.02 * a_cf, freq), s, proto).collapsed
    assert not shake(m, SinePulse(0.95 * a_cf, freq), s, proto).collapsed
