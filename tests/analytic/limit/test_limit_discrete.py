"""Discrete limit analysis: static LP against the kinematic enumeration and closed forms."""
import math

import numpy as np
import pytest

from analytic.limit.limit_discrete import (
    ContactModel,
    enumerate_mechanisms,
    four_hinge_lambda,
    solve_contact_lp,
    solve_lp,
)
from specimens.blocks import discretise
from specimens.catalogue import CATALOGUE, get_specimen
from foundation.errors import ArchdemInputError

CASES = [(s.id, cfg) for s in CATALOGUE for cfg in ("free", "glued")]


@pytest.mark.parametrize("sid,config", CASES)
def test_lp_without_sliding_equals_enumeration(sid, config):
    asm = discretise(get_specimen(sid).arch, config=config)
    kin = enumerate_mechanisms(asm)
    lp = solve_lp(asm, 1e3, 1e3)
    # uniqueness theorem: static = kinematic; 1e-6 relative is the tolerance (HiGHS
    # feasibility tolerances are set to 1e-10 on forces normalised by the total weight)
    assert lp.success and kin.stands
    assert lp.lam == pytest.approx(kin.lam, rel=1e-6)
    # the mechanism read from the LP duals hinges at the same four joint corners
    assert lp.hinges == kin.hinges


@pytest.mark.parametrize("sid", ["Sh02-Sd015", "Sh1-Sd025"])
def test_symmetric_arch_same_multiplier_both_directions(sid):
    asm = discretise(get_specimen(sid).arch, config="free")
    # the arch is symmetric: lambda(-x) = lambda(+x) to round-off
    assert enumerate_mechanisms(asm, load_sign=-1).lam == pytest.approx(enumerate_mechanisms(asm).lam, rel=1e-9)
    assert solve_lp(asm, 0.577, 1.0, load_sign=-1).lam == pytest.approx(solve_lp(asm, 0.577, 1.0).lam, rel=1e-6)


def test_lambda_non_decreasing_in_mu():
    asm = discretise(get_specimen("Sh1-Sd020").arch, config="free")
    lams = [solve_lp(asm, mu, 1.0).lam for mu in (0.2, 0.3, 0.4, 0.577, 0.8, 1.2, math.inf)]
    # a larger friction coefficient enlarges the admissible force set: lambda cannot decrease
    assert all(b >= a - 1e-9 for a, b in zip(lams, lams[1:]))
    assert lams[-1] == pytest.approx(enumerate_mechanisms(asm).lam, rel=1e-6)


def test_sliding_states_reported_for_low_friction():
    asm = discretise(get_specimen("Sh06-Sd025").arch, config="free")
    lp = solve_lp(asm, 0.3, 1.0)
    states = set(lp.joint_states.values())
    assert states & {"sliding", "hinge+sliding"}
    # at a sliding joint the shear sits at the friction limit (associative Coulomb)
    for name, st in lp.joint_states.items():
        if st == "sliding":
            f = lp.forces[name]
            V, N = f["V_intrados"] + f["V_extrados"], f["N_intrados"] + f["N_extrados"]
            assert abs(V) == pytest.approx(0.3 * N, rel=1e-6, abs=1e-9)


def test_effective_contact_lowers_lambda_and_lp_agrees():
    arch = get_specimen("Sh06-Sd015").arch
    full = enumerate_mechanisms(discretise(arch, config="glued"))
    asm = discretise(arch, config="glued", contact=0.8)
    red = enumerate_mechanisms(asm)
    assert red.lam < full.lam and red.contact == 0.8
    # identity: the LP with no sliding is the kinematic minimum, at any contact (LP tolerance 1e-6)
    lp = solve_lp(asm, math.inf, math.inf)
    assert lp.lam == pytest.approx(red.lam, rel=1e-6) and lp.contact == 0.8


def test_macro_block_mass_properties():
    """Macro-block = union of its bodies: mass and centroid equal the polygon union's (shoelace)."""
    from specimens.sections import combine
    asm = discretise(get_specimen("Sh06-Sd015").arch, config="free")
    kin = enumerate_mechanisms(asm)
    j = [asm.joint(n) for n, _ in kin.hinges]
    for k, blk in enumerate(kin.layout.blocks):
        bodies = asm.bodies[j[k].b:j[k + 1].a + 1]
        sec = combine([b.section for b in bodies])
        rho_w = asm.density * asm.arch.width
        assert blk.mass == pytest.approx(rho_w * sec.area, rel=1e-12)
        assert np.allclose(blk.centroid, sec.centroid, atol=1e-12)
        assert blk.inertia == pytest.approx(rho_w * sec.polar, rel=1e-9)


def _block_model(b, h, mu):
    """A rectangular block 2b x 2h on the base: one base joint (left corner = 'intrados')."""
    return ContactModel(("blk",), np.array([1.0]), np.array([[0.0, h]]), ("base",), np.array([-1]), np.array([0]),
                        np.array([[-b, 0.0]]), np.array([[b, 0.0]]), np.array([[0.0, 1.0]]), np.array([mu]))


@pytest.mark.parametrize("b,h", [(0.1, 0.4), (0.2, 0.3)])
def test_rectangular_block(b, h):
    # rocking about the toe at a = g b/h when mu > b/h (Housner's static threshold), closed form
    assert solve_contact_lp(_block_model(b, h, 10.0)).lam == pytest.approx(b / h, rel=1e-8)
    lp = solve_contact_lp(_block_model(b, h, 10.0))
    assert lp.joint_states["base"] == "hinge-extrados"  # the right corner ('extrados' end) carries it
    # sliding at a = mu g when mu < b/h
    mu = 0.5 * b / h
    lp = solve_contact_lp(_block_model(b, h, mu))
    assert lp.lam == pytest.approx(mu, rel=1e-8)
    assert lp.joint_states["base"] == "sliding"


def test_portal_frame():
    """Two columns (2b x H) and a lintel: sway mechanism lambda = 2b / H (closed form, virtual work)."""
    b, H, L, hl = 0.1, 0.8, 1.0, 0.2
    xs = (-L / 2 + b, L / 2 - b)
    mass = np.array([2 * b * H, 2 * b * H, L * hl])
    cent = np.array([[xs[0], H / 2], [xs[1], H / 2], [0.0, H + hl / 2]])
    names = ("base-left", "base-right", "top-left", "top-right")
    a = np.array([-1, -1, 0, 1])
    bb = np.array([0, 1, 2, 2])
    p1 = np.array([[xs[0] - b, 0], [xs[1] - b, 0], [xs[0] - b, H], [xs[1] - b, H]], float)
    p2 = p1 + np.array([2 * b, 0.0])
    n = np.tile([0.0, 1.0], (4, 1))
    model = ContactModel(("c1", "c2", "lintel"), mass, cent, names, a, bb, p1, p2, n, np.full(4, 100.0))
    lp = solve_contact_lp(model)
    assert lp.lam == pytest.approx(2 * b / H, rel=1e-8)
    # low friction: the lintel slides on the columns at lambda = mu (its own sliding mechanism)
    model_mu = ContactModel(("c1", "c2", "lintel"), mass, cent, names, a, bb, p1, p2, n, np.full(4, 0.1))
    assert solve_contact_lp(model_mu).lam == pytest.approx(0.1, rel=1e-8)


def test_four_hinge_kernel_compatibility():
    """Velocities of the three blocks agree at H2 and H3 (independent check of the closed form)."""
    rng = np.random.default_rng(1)
    H = rng.normal(size=(4, 2))
    w = four_hinge_lambda(H, H + 0.1, np.tile([1.0, 0.0], (4, 1)), np.ones(3), np.ones(3), np.ones(3))
    th1, th2, th3 = w.theta
    perp = lambda v: np.array([-v[1], v[0]])  # noqa: E731
    v_H2 = th1 * perp(H[1] - H[0])
    v2_H3 = v_H2 + th2 * perp(H[2] - H[1])
    v3_H3 = th3 * perp(H[2] - H[3])
    assert np.allclose(v2_H3, v3_H3, atol=1e-12)


def test_unstable_geometry_is_reported_not_raised():
    # a very thin pointed ring cannot stand under self-weight
    from specimens.geometry import PointedArch
    arch = PointedArch.from_ratios(0.2, 0.03, 1.0)
    asm = discretise(arch, config="free")
    lp = solve_lp(asm, math.inf, math.inf)
    kin = enumerate_mechanisms(asm)
    assert not lp.stands and not kin.stands
    assert "cannot stand" in lp.message and "cannot stand" in kin.message


def test_bad_input():
    asm = discretise(get_specimen("Sh06-Sd015").arch)
    with pytest.raises(ArchdemInputError):
        solve_lp(asm, -1.0, 1.0)
    with pytest.raises(ArchdemInputError):
        enumerate_mechanisms(asm, load_sign=0)


@pytest.mark.parametrize("config", ["glued", "free"])
def test_mechanism_lambda_reproduces_the_enumeration_minimum(config):
    from analytic.limit.limit_discrete import enumerate_mechanisms, mechanism_lambda
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    asm = discretise(get_specimen("Sh06-Sd020").arch, config=config)
    k = enumerate_mechanisms(asm)
    # the same virtual-work kernel on the same layout: identical up to round-off
    assert mechanism_lambda(asm, k.hinges) == pytest.approx(k.lam, rel=1e-12)
    # the face-swapped layout is not a collapse mechanism for loads along +x
    swapped = tuple((j, "extrados" if f == "intrados" else "intrados") for j, f in k.hinges)
    assert mechanism_lambda(asm, swapped) > k.lam
    assert np.isnan(mechanism_lambda(asm, k.hinges[:3]))
