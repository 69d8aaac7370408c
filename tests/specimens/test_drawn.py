"""Assemblies from drawn polygons: joints from the geometry, order and orientation, and bad drawings."""
import json
import math

import numpy as np
import pytest

from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
from specimens import ArchdemInputError, discretise
from specimens.constants import DRAWN_DENSITY
from specimens.drawn import DrawnBlock, assemble, convex_pieces, from_dict
from specimens.exchange import EXAMPLE_DRAWING, read_assembly
from specimens.imperfection import Imperfection, realise_drawn
from specimens.sections import is_convex, polygon_properties, signed_area


def rect(x0, y0, x1, y1):
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], float)


def block(name, poly, depth=0.1):
    return DrawnBlock(name, np.asarray(poly, float), None, depth)


def test_a_block_on_a_wider_one_touches_along_its_own_face():
    """Partial overlap: the joint is the common part of the two faces, its ends the upper block's corners."""
    asm = assemble([block("A", rect(0, 0, 1, 0.2)), block("B", rect(0.3, 0.2, 0.5, 0.6))])
    assert [b.name for b in asm.bodies] == ["B", "A"]  # not a chain: left to right by centroid
    inner = [j for j in asm.joints if not j.is_base]
    assert len(inner) == 1 and {tuple(inner[0].p_i), tuple(inner[0].p_e)} == {(0.3, 0.2), (0.5, 0.2)}
    assert (inner[0].a, inner[0].b) == (0, 1) and inner[0].normal == pytest.approx([0, -1])  # from B (a) down to A (b)
    base = [j for j in asm.joints if j.is_base]
    assert len(base) == 1 and base[0].length == pytest.approx(1.0)  # the lowest edge is the ground
    # masses of the prisms, depth 0.1 m, a drawing's density
    assert asm.body("B").mass == pytest.approx(DRAWN_DENSITY * 0.1 * 0.2 * 0.4)
    assert asm.total_mass == pytest.approx(DRAWN_DENSITY * 0.1 * 0.28)


def test_a_stack_rocks_as_one_block_and_a_tree_of_blocks_is_no_chain():
    """Two equal blocks stacked on a support: they rock together about the foot, lambda = b / h_total."""
    asm = assemble([block("top", rect(0, 0.4, 0.2, 0.8)), block("bottom", rect(0, 0, 0.2, 0.4))],
                   supports=[rect(-0.5, -0.2, 0.7, 0.0)])
    assert asm.is_chain is False  # one base joint: not a chain from ground to ground
    lp = solve_lp(asm, math.inf, math.inf)
    assert lp.lam == pytest.approx(0.2 / 0.8, rel=1e-9)
    tree = assemble([block("A", rect(0, 0, 1, 0.2)), block("B", rect(0, 0.2, 0.5, 0.6)), block("C", rect(0.5, 0.2, 1, 0.6))])
    assert len(tree.joints) == 4 and not tree.is_chain and solve_lp(tree, math.inf, math.inf).lam == pytest.approx(1 / 0.6)
    with pytest.raises(ArchdemInputError, match="four-hinge enumeration needs the blocks in one chain"):
        enumerate_mechanisms(tree)


def test_a_non_convex_block_is_split_into_convex_pieces_with_the_outline_mass():
    ell = np.array([[0, 0], [0.6, 0], [0.6, 0.2], [0.2, 0.2], [0.2, 0.6], [0, 0.6]], float)
    pieces = convex_pieces(ell)
    assert len(pieces) == 2 and all(is_convex(p) for p in pieces)
    assert sum(signed_area(p) for p in pieces) == pytest.approx(signed_area(ell), rel=1e-12)
    asm = assemble([block("L", ell)])
    b = asm.bodies[0]
    assert b.mass == pytest.approx(DRAWN_DENSITY * 0.1 * polygon_properties(ell).area) and len(b.pieces) == 2


def test_blocks_are_oriented_ccw_whatever_the_drawing():
    asm = assemble([block("A", rect(0, 0, 1, 0.2)[::-1])])
    assert signed_area(asm.bodies[0].outline) > 0


def test_a_contact_within_the_tolerance_is_a_joint_and_beyond_it_is_not():
    gap = 1e-4
    blocks = [block("A", rect(0, 0, 0.2, 0.4)), block("B", rect(0, 0.4 + gap, 0.2, 0.8))]
    asm = assemble(blocks, tol=2 * gap)
    assert sum(not j.is_base for j in asm.joints) == 1
    with pytest.raises(ArchdemInputError, match="block B touches no other block and no support"):
        assemble(blocks, tol=gap / 2)


def test_a_drawn_assembly_says_in_one_line_that_it_has_no_arch():
    asm = assemble([block("A", rect(0, 0, 0.2, 0.4))])
    with pytest.raises(ArchdemInputError, match="holds blocks, not a two-centred arch: this needs the arch.s parameters") as exc:
        asm.Sh  # noqa: B018
    assert "\n" not in str(exc.value)
    with pytest.raises(AttributeError):
        asm.no_such_thing  # noqa: B018


def test_discretise_takes_a_drawn_assembly_as_drawn_with_its_contact():
    asm = assemble([block("A", rect(0, 0, 1, 0.2)), block("B", rect(0.3, 0.2, 0.5, 0.6))])
    assert discretise(asm) is asm and discretise(asm, config="free") is asm
    relieved = discretise(asm, contact=0.8)
    assert relieved.contact == 0.8 and all(j.band == pytest.approx((0.1, 0.9)) for j in relieved.joints)
    assert [b.mass for b in relieved.bodies] == [b.mass for b in asm.bodies]
    with pytest.raises(ArchdemInputError, match="the number of voussoirs does not apply"):
        discretise(asm, n_voussoirs=4)
    with pytest.raises(ArchdemInputError, match="give the density when reading"):
        discretise(asm, density=2400.0)


@pytest.mark.parametrize("blocks, supports, message", [
    ([block("A", rect(0, 0, 1, 0.2)), block("B", rect(2, 0.5, 3, 0.7))], (), "block B touches no other block and no support"),
    ([block("A", rect(0, 0, 1, 0.2)), block("B", rect(0.5, 0.1, 1.5, 0.3))], (), "blocks overlap: block A and block B"),
    ([block("A", rect(0, 0, 1, 0.2)), block("Z", [[0, 0.2], [1, 0.2], [0.5, 0.2]])], (), "block Z has zero area"),
    ([block("A", rect(0, 0, 1, 0.2)), block("Z", [[0, 0.2], [1, 0.2]])], (), "block Z has fewer than 3 distinct vertices"),
    ([block("A", rect(0, 0, 1, 0.2)), block("X", [[0, 0.2], [1, 0.2], [0, 0.6], [1, 0.6]])], (), "block X: its outline crosses itself"),
    ([block("A", rect(0, 0, 1, 0.2)), block("A", rect(0, 0.2, 1, 0.4))], (), "block name 'A' is given to more than one block"),
    ([block("A", rect(0, 0, 1, 0.2), depth=None)], (), "block A has no depth"),
    ([block("A", rect(0, 0, 1, 0.2)), block("B", rect(0, 0.2, 1, 0.4))], [rect(-1, -1, 2, -0.5)],
     "no block stands on a support or on the ground"),
    ([block("A", rect(0, 0, 1, 0.2)), block("B", rect(3, 1, 4, 1.2)), block("C", rect(3, 1.2, 4, 1.4))],
     [rect(-1, -0.5, 2, 0.0)], "blocks B, C touch each other but not the ground or a support"),
    ([block("A", [[0, 0], [1, 0], [1, np.nan]])], (), "coordinates that are not finite numbers"),
    ([], (), "no blocks"),
])
def test_bad_drawings_are_refused_in_one_line(blocks, supports, message):
    with pytest.raises(ArchdemInputError, match=message) as exc:
        assemble(blocks, supports)
    assert "\n" not in str(exc.value)


def test_a_drawn_assembly_described_and_rebuilt_is_the_same_to_the_bit():
    asm = read_assembly(EXAMPLE_DRAWING)
    back = from_dict(json.loads(json.dumps(asm.to_dict())))
    for x, y in zip(asm.bodies, back.bodies):
        assert (x.name, x.mass, x.width) == (y.name, y.mass, y.width) and np.array_equal(x.inertia, y.inertia)
        assert all(np.array_equal(p, q) for p, q in zip(x.pieces, y.pieces))
    for j, k in zip(asm.joints, back.joints):
        assert (j.name, j.a, j.b) == (k.name, k.a, k.b) and np.array_equal(j.normal, k.normal)
    assert (back.length_scale, back.size, back.is_chain, back.crown_index) == (asm.length_scale, asm.size, True,
                                                                                asm.crown_index)
    assert solve_lp(back, 0.577, 1.0).lam == solve_lp(asm, 0.577, 1.0).lam


def test_an_imperfect_realisation_of_a_drawing_loses_its_edges_joint_by_joint():
    asm = read_assembly(EXAMPLE_DRAWING)
    assert realise_drawn(asm, Imperfection(0.0, 1e-3), None) is asm
    nominal = realise_drawn(asm, Imperfection(5e-3, 1e-3), None)  # 5 mm off each edge of every joint
    for j in nominal.joints:
        lo, hi = j.band
        assert lo * j.length == pytest.approx(5e-3) and (1 - hi) * j.length == pytest.approx(5e-3)
    one, again = (realise_drawn(asm, Imperfection(5e-3, 1e-3), 7, 3) for _ in range(2))
    assert [j.band for j in one.joints] == [j.band for j in again.joints] != [j.band for j in nominal.joints]
    assert [b.mass for b in one.bodies] == [b.mass for b in asm.bodies]  # relieved pieces, the full blocks' masses
    assert solve_lp(one, math.inf, math.inf).lam < solve_lp(asm, math.inf, math.inf).lam
    with pytest.raises(ArchdemInputError, match="leaves less than"):
        realise_drawn(asm, Imperfection(0.2, 0.0), None)


def ring(gap=0.0, n=8, ri=1.0, re=1.25):
    """A semicircular ring of n voussoirs B1..Bn on the ground [m]; its right half moved ``gap`` to the right."""
    out = []
    for k in range(n):
        a0, a1 = math.pi * (1 - k / n), math.pi * (1 - (k + 1) / n)
        q = np.array([[ri * math.cos(a0), ri * math.sin(a0)], [ri * math.cos(a1), ri * math.sin(a1)],
                      [re * math.cos(a1), re * math.sin(a1)], [re * math.cos(a0), re * math.sin(a0)]])
        out.append(block(f"B{k + 1}", q + [gap if k >= n // 2 else 0.0, 0.0], depth=0.3))
    return out


def test_a_joint_drawn_open_is_a_gap_named_with_the_parts_it_leaves():
    """5 mm between the crown voussoirs: each half stands on the ground, so the drawing is read, its gap
    named; the LP has no equilibrium, and the refusal names the gap and the two halves no joint joins."""
    asm = assemble(ring(0.005))
    (g,) = asm.gaps
    assert (g.a, g.b, g.kind) == ("B4", "B5", "block") and g.distance_m == pytest.approx(0.005, rel=1e-9)
    assert g.describe() == "blocks B4 and B5 are 5.0 mm apart"
    assert asm.parts() == [("B1", "B2", "B3", "B4"), ("B5", "B6", "B7", "B8")]
    lp = solve_lp(asm, math.inf, math.inf)
    assert not lp.stands and lp.status == 2
    msg = asm.cannot_stand("ring")
    assert msg == ("ring cannot stand under its own weight (no equilibrium even without sliding): blocks B4 and B5 "
                   "are 5.0 mm apart (no joint between them); its blocks stand in 2 parts that no joint joins: "
                   "B1, B2, B3, B4 | B5, B6, B7, B8")
    # carried whole to a worker, and into the result files
    assert from_dict(json.loads(json.dumps(asm.to_dict()))).gaps == asm.gaps
    assert asm.parameters()["gaps"][0]["text"] == "blocks B4 and B5 are 5.0 mm apart"
    closed = assemble(ring())
    assert closed.gaps == () and len(closed.parts()) == 1 and solve_lp(closed, math.inf, math.inf).stands
    assert "gaps" not in closed.to_dict() and "gaps" not in closed.parameters()


@pytest.mark.parametrize("blocks, supports, message", [
    # a block drawn 5 mm above the one it should rest on, on a support 5 mm below a block
    ([block("bottom", rect(0, 0, 0.2, 0.4)), block("top", rect(0, 0.405, 0.2, 0.8))], (),
     r"block top touches no other block and no support \(blocks bottom and top are 5.0 mm apart\)"),
    ([block("A", rect(0, 0, 0.2, 0.4)), block("B", rect(0, 0.4, 0.2, 0.8))], [rect(-0.5, -0.2, 0.7, -0.005)],
     r"no block stands on a support or on the ground \(block A is 5.0 mm from support 1\)"),
    ([block("A", rect(0, 0, 1, 0.2)), block("B", rect(1.002, 0.2, 1.2, 0.4)), block("C", rect(1.002, 0.4, 1.2, 0.6))],
     [rect(-0.5, -0.5, 1.0, 0.0)], r"blocks B, C touch each other but not the ground or a support "
                                   r"\(blocks A and B are 2.0 mm apart\)"),
])
def test_a_gap_that_leaves_blocks_without_support_is_named_in_the_refusal(blocks, supports, message):
    with pytest.raises(ArchdemInputError, match=message) as exc:
        assemble(blocks, supports)
    assert "\n" not in str(exc.value)


def test_gaps_to_a_support_and_to_the_ground_line():
    """A lintel on one pier and 3 mm above the other; a pier standing 4 mm short of the ground line."""
    piers = [block("L", rect(0, 0, 0.2, 1)), block("R", rect(0.8, 0, 1, 0.997))]
    on_one = assemble([*piers, block("T", rect(0, 1, 1, 1.2))])
    assert [g.describe() for g in on_one.gaps] == ["blocks R and T are 3.0 mm apart"]
    assert not solve_lp(on_one, math.inf, math.inf).stands  # the lintel overhangs its one pier by 0.8 m
    short = assemble([block("L", rect(0, 0, 0.2, 1)), block("R", rect(0.2, 0.004, 0.4, 1))])
    assert [(g.describe(), g.kind) for g in short.gaps] == [("block R is 4.0 mm above the ground", "ground")]
    pad = assemble([block("A", rect(0, 0, 0.2, 0.4)), block("B", rect(0.2, 0.001, 0.4, 0.4))],
                   supports=[rect(-0.5, -0.2, 0.7, 0.0)])
    assert [(g.describe(), g.kind) for g in pad.gaps] == [("block B is 1.0 mm from support 1", "support")]


def test_blocks_a_course_apart_or_with_a_shim_between_are_no_gap():
    """A gap is measured against the thinner block, and only where nothing is drawn between: a tall wall of
    thin courses, a corner contact and a 5 mm shim between two blocks are no gaps."""
    wall = [block(f"W{r}-{c}", rect(c * 0.3, r * 0.05, (c + 1) * 0.3, (r + 1) * 0.05)) for r in range(200) for c in range(2)]
    assert assemble(wall).gaps == ()
    corner = assemble([block("A", rect(0, 0, 0.2, 0.2)), block("B", rect(0.2, 0, 0.4, 0.2)),
                       block("C", rect(0.2, 0.2, 0.4, 0.4))])
    assert corner.gaps == ()  # A and C touch at a corner only: no gap, no joint
    shim = assemble([block("A", rect(0, 0, 0.3, 0.3)), block("S", rect(0, 0.3, 0.3, 0.305)),
                     block("B", rect(0, 0.305, 0.3, 0.6))])
    assert shim.gaps == () and len(shim.joints) == 3
