"""Arches on piers: geometry, naming, mass properties and bad input."""
import math

import numpy as np
import pytest

from specimens import ArchdemInputError, Piers, discretise, get_specimen
from specimens.frame import rocking_frame
from specimens.mesh import assembly_meshes

ARCH = get_specimen("Sh06-Sd015").arch


@pytest.fixture(scope="module")
def on_piers():
    return discretise(ARCH, piers=Piers(0.3, 0.1, depth=0.15, offset=0.01, courses=3))


def test_the_ring_is_the_bare_arch_unchanged(on_piers):
    bare = discretise(ARCH)
    ring = [b for b in on_piers.bodies if not b.name[1:2] == "P"]
    assert [b.name for b in ring] == [b.name for b in bare.bodies]
    for a, b in zip(ring, bare.bodies):
        assert a.mass == b.mass and np.array_equal(a.outline, b.outline) and np.array_equal(a.inertia, b.inertia)
    for name in ("L3", "L7", "R7"):
        assert np.array_equal(on_piers.joint(name).p_i, bare.joint(name).p_i)
    assert bare.piers is None and "piers" not in bare.parameters()


def test_bodies_and_joints_run_along_the_chain(on_piers):
    names = [b.name for b in on_piers.bodies]
    assert names[:3] == ["LP1", "LP2", "LP3"] and names[-3:] == ["RP3", "RP2", "RP1"]
    joints = [j.name for j in on_piers.joints]
    assert joints[:4] == ["LP0", "LP1", "LP2", "L0"] and joints[-4:] == ["R0", "RP2", "RP1", "RP0"]
    # every joint joins consecutive bodies; only the two pier bases touch the ground
    for k, j in enumerate(on_piers.joints):
        assert (j.a, j.b) == (k - 1, k if k < on_piers.n_bodies else -1)
    assert [j.name for j in on_piers.joints if j.is_base] == ["LP0", "RP0"]
    assert [j.in_pier for j in on_piers.joints].count(True) == 6


def test_pier_joints_are_horizontal_bed_joints_from_the_inner_face(on_piers):
    xi = ARCH.Ri - ARCH.e - 0.01
    for k, y in enumerate((-0.3, -0.2, -0.1)):
        left, right = on_piers.joint(f"LP{k}"), on_piers.joint(f"RP{k}")
        assert left.p_i == pytest.approx([-xi, y]) and left.p_e == pytest.approx([-xi - 0.1, y])
        assert right.p_i == pytest.approx([xi, y]) and right.p_e == pytest.approx([xi + 0.1, y])
        assert left.normal == pytest.approx([0, 1]) and right.normal == pytest.approx([0, -1])


def test_pier_courses_have_the_mass_of_their_prism(on_piers):
    course = on_piers.body("LP2")
    assert course.mass == pytest.approx(500.0 * 0.15 * 0.1 * 0.1) and course.width == 0.15
    assert course.centroid == pytest.approx([-(ARCH.Ri - ARCH.e - 0.01) - 0.05, -0.15])
    assert on_piers.total_mass == pytest.approx(discretise(ARCH).total_mass + 6 * course.mass)
    assert on_piers.parameters()["piers"] == {"height": 0.3, "width": 0.1, "depth": 0.15, "offset": 0.01, "courses": 3}


def test_a_pier_load_is_mass_at_the_top_of_the_pier():
    bare = discretise(ARCH, piers=Piers(0.3, 0.1, courses=3))
    loaded = discretise(ARCH, piers=Piers(0.3, 0.1, courses=3, load=19.62))
    top, top0 = loaded.body("RP3"), bare.body("RP3")
    m = 19.62 / 9.81
    p = np.array([ARCH.Ri - ARCH.e + 0.05, 0.0])  # the centre of the pier's top
    assert top.mass == pytest.approx(top0.mass + m)
    assert top.centroid == pytest.approx((top0.mass * top0.centroid + m * p) / top.mass)
    # in-plane inertia about the new centre of mass: parallel axes of the course and the point mass
    d0, dp = top0.centroid - top.centroid, p - top.centroid
    assert top.I_z == pytest.approx(top0.I_z + top0.mass * d0 @ d0 + m * dp @ dp)
    assert np.allclose(top.inertia, top.inertia.T) and np.all(np.linalg.eigvalsh(top.inertia) > 0)
    assert loaded.body("RP2").mass == bare.body("RP2").mass and loaded.body("LP3").mass == top.mass
    assert loaded.parameters()["piers"]["load"] == 19.62 and "load" not in bare.parameters()["piers"]
    with pytest.raises(ArchdemInputError, match="pier load must be a finite force >= 0 N"):
        Piers(0.3, 0.1, load=-1)
    with pytest.raises(ArchdemInputError, match="pier load must be a finite force"):
        Piers(0.3, 0.1, load=float("nan"))


def test_meshes_take_each_body_depth(on_piers):
    meshes = assembly_meshes(on_piers)
    z = [np.ptp(m.vertices[:, 2]) for pieces in meshes for m in pieces]
    assert min(z) == pytest.approx(ARCH.width) and max(z) == pytest.approx(0.15)
    assert all(m.is_watertight for pieces in meshes for m in pieces)


def test_pier_joints_take_contact_bands():
    asm = discretise(ARCH, piers=Piers(0.2, 0.1, courses=2), bands={"LP1": (0.2, 1.0)})
    lo, hi = asm.joint("LP1").contact_points
    assert lo == pytest.approx([-(ARCH.Ri - ARCH.e) - 0.02, -0.1])
    # the course below is relieved at that joint's inner corner; the masses stay the full blocks'
    assert len(asm.body("LP1").pieces[0]) == 5 and asm.body("LP1").mass == pytest.approx(500 * 0.1 * 0.1 * 0.1)


@pytest.mark.parametrize("kw, msg", [
    (dict(height=-1, width=0.1), "pier height must be a finite length > 0"),
    (dict(height=float("nan"), width=0.1), "pier height must be a finite length"),
    (dict(height=0.2, width=float("inf")), "pier width must be a finite length"),
    (dict(height=0.2, width=0.1, depth=0), "pier depth must be a finite length > 0"),
    (dict(height=0.2, width=0.1, offset=-0.01), "pier offset must be a finite length >= 0"),
    (dict(height=0.2, width=0.1, courses=0), "pier courses must be a whole number from 1 to 50"),
    (dict(height=0.2, width=0.1, courses=2.5), "pier courses must be a whole number"),
    (dict(height=0.2, width=0.1, courses=True), "pier courses must be a whole number"),
    (dict(height="tall", width=0.1), "pier height must be a length in m"),
])
def test_bad_piers_are_refused_in_one_line(kw, msg):
    with pytest.raises(ArchdemInputError, match=msg.replace("(", r"\(")) as exc:
        Piers(**kw)
    assert "\n" not in str(exc.value)


def test_a_pier_narrower_than_the_springing_or_closing_the_opening_is_refused():
    with pytest.raises(ArchdemInputError, match="narrower than the ring's springing"):
        discretise(ARCH, piers=Piers(0.2, ARCH.t * 0.99))
    with pytest.raises(ArchdemInputError, match="narrower than the ring's springing"):
        discretise(ARCH, piers=Piers(0.2, ARCH.t, offset=0.01))
    with pytest.raises(ArchdemInputError, match="closes the opening"):
        discretise(ARCH, piers=Piers(0.2, 1.0, offset=ARCH.Ri - ARCH.e))
    with pytest.raises(ArchdemInputError, match="must be a specimens.piers.Piers"):
        discretise(ARCH, piers={"height": 0.2})
    assert discretise(ARCH, piers=Piers(0.2, ARCH.t)).n_bodies == discretise(ARCH).n_bodies + 2


def test_the_rocking_frame_is_named_like_an_arch_on_one_course_piers():
    f = rocking_frame(0.05, 0.2, 0.3, 0.05, beam_density=1000)
    assert [b.name for b in f.bodies] == ["LP1", "C", "RP1"]
    assert [(j.name, j.a, j.b) for j in f.joints] == [("LP0", -1, 0), ("L0", 0, 1), ("R0", 1, 2), ("RP0", 2, -1)]
    # lintel 0.5 x 0.05 at 1000 kg/m^3 on two 0.1 x 0.4 piers at 500 kg/m^3
    assert f.gamma == pytest.approx((1000 * 0.5 * 0.05) / (2 * 500 * 0.1 * 0.4))
    assert math.isclose(f.joints[1].p_e[0], -0.25) and f.bodies[0].centroid == pytest.approx([-0.2, -0.2])
    with pytest.raises(ArchdemInputError, match="frame b must be a positive number"):
        rocking_frame(-0.05, 0.2, 0.3, 0.05)
