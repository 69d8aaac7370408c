from fractions import Fraction

import numpy as np
import pytest

from specimens.blocks import discretise, joint_angles
from specimens.catalogue import CATALOGUE, get_specimen
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from specimens.sections import is_convex, signed_area

IDS = [s.id for s in CATALOGUE]


def shoelace(poly):
    x, y = np.asarray(poly).T
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def test_body_counts():
    a = get_specimen("Sh06-Sd015").arch
    glued, free = discretise(a, config="glued"), discretise(a, config="free")
    assert glued.n_bodies == 15 and free.n_bodies == 17
    assert len(free.blocks) == 17 and len(glued.blocks) == 17
    assert len(free.joints) == 18 and len(glued.joints) == 16
    assert [j.name for j in glued.joints] == [f"L{k}" for k in range(8)] + [f"R{k}" for k in range(7, -1, -1)]
    # base joints connect to the base (-1) at both ends
    assert free.joints[0].a == -1 and free.joints[-1].b == -1


@pytest.mark.parametrize("config", ["glued", "free"])
def test_total_mass_is_the_exact_sum_rounded_once(config):
    """The same digits on every Python: builtin sum compensates its rounding from 3.12 on and
    differed from 3.11's in the last bits (the catalogue's masses)."""
    for s in CATALOGUE:
        asm = discretise(s.arch, config=config)
        assert asm.total_mass == float(sum(Fraction(b.mass) for b in asm.bodies)), s.id


def test_joint_angles_spec_rule():
    a = get_specimen("Sh02-Sd020").arch
    psi = joint_angles(a)
    assert psi[-1] == pytest.approx(8 * a.psi_i / 8.5)
    # the crown is as wide at the intrados as a voussoir: two half parts
    assert a.psi_i - psi[-1] == pytest.approx((psi[1] - psi[0]) / 2)


@pytest.mark.parametrize("sid", IDS)
def test_linearised_areas_sum_to_corner_polygon(sid):
    a = get_specimen(sid).arch
    asm = discretise(a, config="free")
    psi = asm.joint_angles
    right_i = a.point(psi, a.Ri)
    right_e = a.point(psi, a.Re)
    left_i, left_e = right_i * [-1, 1], right_e * [-1, 1]
    # polygon through all joint corners and the two apex points, built independently here
    poly = np.vstack([left_i, [a.apex_intrados], right_i[::-1], right_e, [a.apex_extrados], left_e[::-1]])
    total = sum(b.area for b in asm.bodies)
    assert total == pytest.approx(shoelace(poly), rel=1e-12)  # both exact: round-off only


@pytest.mark.parametrize("sid", IDS)
def test_curved_areas_sum_to_exact_arch_area(sid):
    a = get_specimen(sid).arch
    asm = discretise(a, config="free", shape="curved")
    total = sum(b.area for b in asm.bodies)
    # docs/physics/geometry.md#11-identities-the-tests-check: polygonisation changes the area by < 0.5 %
    assert total == pytest.approx(a.area(), rel=5e-3)
    # chords cut area off the extrados and add some under the intrados; the extrados (larger radius) wins
    assert total < a.area()


@pytest.mark.parametrize("shape", ["linearised", "curved"])
@pytest.mark.parametrize("config", ["free", "glued"])
def test_mass_and_centroid_against_fine_shoelace(shape, config):
    # independent route: densify every body outline and use the plain shoelace/centroid formula
    a = get_specimen("Sh1-Sd015").arch
    asm = discretise(a, config=config, shape=shape)
    for b in asm.bodies:
        poly = b.outline
        A = shoelace(poly)
        x, y = poly.T
        xn, yn = np.roll(x, -1), np.roll(y, -1)
        cr = x * yn - xn * y
        cx = np.sum((x + xn) * cr) / (6 * signed_area(poly))
        cy = np.sum((y + yn) * cr) / (6 * signed_area(poly))
        assert b.mass == pytest.approx(asm.density * a.width * A, rel=1e-12)
        np.testing.assert_allclose(b.centroid, [cx, cy], atol=1e-12)


def test_curved_mass_within_half_percent_of_exact_arcs():
    from specimens.geometry import ring_segment_properties

    a = get_specimen("Sh06-Sd020").arch
    asm = discretise(a, config="free", shape="curved")
    psi = asm.joint_angles
    for k in range(1, len(psi)):
        exact = ring_segment_properties(a, (1, psi[k]), (1, psi[k - 1]))
        body = asm.body(f"R{k}")
        assert body.area == pytest.approx(exact.area, rel=5e-3)  # spec tolerance
        assert np.linalg.norm(body.centroid - exact.centroid) < 5e-3 * a.t


def test_inertia_of_a_rectangle_voussoir_limit():
    # a single very flat voussoir of a huge arch is nearly a rectangle t x (R dpsi):
    # in-plane inertia -> m (t^2 + l^2) / 12
    a = PointedArch.round(100.0, 0.5, width=0.3)
    asm = discretise(a, n_voussoirs=400, config="free")
    b = asm.body("R200")
    l = a.Rp * (asm.joint_angles[1] - asm.joint_angles[0])
    assert b.I_z == pytest.approx(b.mass * (a.t**2 + l**2) / 12, rel=1e-4)
    assert b.inertia[0, 0] + b.inertia[1, 1] == pytest.approx(b.I_z + 2 * b.mass * a.width**2 / 12, rel=1e-12)


@pytest.mark.parametrize("config", ["free", "glued"])
@pytest.mark.parametrize("shape", ["linearised", "curved"])
def test_left_right_mirror_symmetry(config, shape):
    asm = discretise(get_specimen("Sh02-Sd025").arch, config=config, shape=shape)
    n = asm.n_bodies
    for k in range(n):
        b, m = asm.bodies[k], asm.bodies[n - 1 - k]
        assert b.mass == pytest.approx(m.mass, rel=1e-12)
        assert b.centroid[0] == pytest.approx(-m.centroid[0], abs=1e-12)
        assert b.centroid[1] == pytest.approx(m.centroid[1], abs=1e-12)
        assert b.inertia[0, 1] == pytest.approx(-m.inertia[0, 1], abs=1e-15)
    assert asm.centroid[0] == pytest.approx(0.0, abs=1e-12)
    nj = len(asm.joints)
    for k in range(nj):
        j, m = asm.joints[k], asm.joints[nj - 1 - k]
        np.testing.assert_allclose(j.p_i * [-1, 1], m.p_i, atol=1e-14)
        np.testing.assert_allclose(j.normal * [1, -1], m.normal, atol=1e-14)


def test_pieces_convex_and_crown_not_hulled():
    for shape in ("linearised", "curved"):
        asm = discretise(get_specimen("Sh1-Sd025").arch, config="free", shape=shape)
        crown = asm.body("C")
        assert len(crown.pieces) >= 2
        assert not is_convex(crown.outline)  # the apex notch
        assert sum(shoelace(p) for p in crown.pieces) == pytest.approx(crown.area, rel=1e-12)
        for b in asm.bodies:
            for p in b.pieces:
                assert is_convex(p) and signed_area(p) > 0


def test_joint_geometry():
    a = get_specimen("Sh06-Sd015").arch
    asm = discretise(a, config="free")
    for j in asm.joints:
        assert j.length == pytest.approx(a.t, rel=1e-12)  # radial cuts span the thickness
        assert np.dot(j.normal, j.tangent) == pytest.approx(0.0, abs=1e-12)
        # normal points from body a to body b
        if j.a >= 0:
            assert np.dot(asm.bodies[j.a].centroid - j.p_i, j.normal) < 0
        if j.b >= 0:
            assert np.dot(asm.bodies[j.b].centroid - j.p_i, j.normal) > 0
    assert asm.joints[0].p_i[1] == 0.0 and asm.joints[-1].p_e[1] == 0.0


def test_round_arch_discretisation():
    a = PointedArch.round(0.2, 0.04)
    asm = discretise(a, config="free")
    crown = asm.body("C")
    assert crown.centroid[0] == pytest.approx(0.0, abs=1e-14)
    # with e = 0 every voussoir is the same trapezoid and the joints divide a quarter circle
    masses = [asm.body(f"R{k}").mass for k in range(1, 9)]
    assert np.ptp(masses) < 1e-12 * masses[0]
    assert asm.joint_angles[-1] == pytest.approx(8 * (np.pi / 2) / 8.5)
    # the linearised crown joins the apex points: two convex halves (spec rule, also for e = 0)
    assert len(crown.pieces) == 2 and all(is_convex(p) for p in crown.pieces)


@pytest.mark.parametrize("kw,match", [
    (dict(n_voussoirs=0), "voussoirs"), (dict(shape="round"), "shape"), (dict(config="x"), "configuration"),
    (dict(density=-1.0), "density"), (dict(crown_fraction=0.0), "crown"),
])
def test_bad_discretisation(kw, match):
    with pytest.raises(ArchdemInputError, match=match):
        discretise(get_specimen("Sh06-Sd015").arch, **kw)


# --- effective contact: relieved joints -------------------------------------------------------
@pytest.mark.parametrize("shape", ["linearised", "curved"])
@pytest.mark.parametrize("config", ["free", "glued"])
def test_full_contact_leaves_the_blocks_as_sawn(shape, config):
    a = get_specimen("Sh06-Sd010").arch
    full, default = discretise(a, config=config, shape=shape, contact=1.0), discretise(a, config=config, shape=shape)
    for b1, b2 in zip(full.bodies, default.bodies):
        assert len(b1.pieces) == len(b2.pieces)
        for p1, p2 in zip(b1.pieces, b2.pieces):
            assert np.array_equal(p1, p2)
    assert all(np.array_equal(j.contact_points[0], j.p_i) and np.array_equal(j.contact_points[1], j.p_e)
               for j in full.joints)


def _on_segment(p, a, b, tol):
    """Distance of ``p`` from the line a-b, and its position along a-b (0 at a, 1 at b)."""
    d = b - a
    s = float(np.dot(p - a, d) / np.dot(d, d))
    return abs(float(d[0] * (p - a)[1] - d[1] * (p - a)[0])) / np.linalg.norm(d), s


@pytest.mark.parametrize("sid", ["Sh02-Sd015", "Sh1-Sd025"])
@pytest.mark.parametrize("shape", ["linearised", "curved"])
@pytest.mark.parametrize("config", ["free", "glued"])
@pytest.mark.parametrize("c", [0.8, 0.5, 0.2])
def test_relieved_joints_touch_only_within_the_central_fraction(sid, shape, config, c):
    a = get_specimen(sid).arch
    full = discretise(a, config=config, shape=shape)
    asm = discretise(a, config=config, shape=shape, contact=c)
    tol = 1e-9 * a.Rp
    for b, bf in zip(asm.bodies, full.bodies):
        # masses, centroids and inertias are the full blocks'
        assert b.mass == bf.mass and np.array_equal(b.inertia, bf.inertia) and np.array_equal(b.outline, bf.outline)
        # each relieved piece is convex, smaller than its sawn piece, and every vertex lies on the
        # sawn piece's boundary (so, being convex, it lies inside it)
        assert len(b.pieces) == len(bf.pieces)
        for p, pf in zip(b.pieces, bf.pieces):
            assert is_convex(p) and 0 < signed_area(p) <= signed_area(pf)
            edges = list(zip(pf, np.roll(pf, -1, axis=0)))
            for q in p:
                assert any(_on_segment(q, e0, e1, tol)[0] < tol and -1e-12 <= _on_segment(q, e0, e1, tol)[1] <= 1 + 1e-12
                           for e0, e1 in edges)
    for j in asm.joints:
        c_i, c_e = j.contact_points
        # the ends of the central fraction: c x depth apart, centred on the joint
        assert np.linalg.norm(c_e - c_i) == pytest.approx(c * j.length, rel=1e-12)
        np.testing.assert_allclose(0.5 * (c_i + c_e), 0.5 * (j.p_i + j.p_e), atol=tol)
        on_joint = []
        for k in (j.a, j.b):
            if k < 0:
                continue
            for p in asm.bodies[k].pieces:
                for q in p:
                    dist, s = _on_segment(q, j.p_i, j.p_e, tol)
                    if dist < tol:
                        on_joint.append(s)
        # every point of either body on the joint's plane is within the contact, and both ends are there
        s_lo, s_hi = (1 - c) / 2, (1 + c) / 2
        assert on_joint and min(on_joint) == pytest.approx(s_lo, abs=1e-9) and max(on_joint) == pytest.approx(s_hi, abs=1e-9)
        assert all(s_lo - 1e-9 <= s <= s_hi + 1e-9 for s in on_joint)
