"""Drawing files: round trips bit for bit, units and planes, closed forms drawn in DXF, bad files."""
import math

import ezdxf
import numpy as np
import pytest
import trimesh

from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
from analytic.rocking.impact import energy_restitution
from analytic.rocking.linkage import mechanism_four_bar
from analytic.rocking.rocking_block import rocking_frame_equivalent
from specimens import ArchdemInputError, Piers, discretise, get_specimen
from specimens.constants import DRAWN_DENSITY
from specimens.exchange import read_assembly, write_assembly
from specimens.mesh import prism

ARCH = get_specimen("Sh06-Sd015").arch


def assert_same(a, b):
    """Bodies (outline, pieces, mass, centroid, inertia, depth), joints (names, bodies, ends, normals)
    and the analyses' lengths identical to the bit."""
    assert [x.name for x in a.bodies] == [x.name for x in b.bodies]
    for x, y in zip(a.bodies, b.bodies):
        assert np.array_equal(x.outline, y.outline) and len(x.pieces) == len(y.pieces)
        assert all(np.array_equal(p, q) for p, q in zip(x.pieces, y.pieces))
        assert (x.mass, x.width) == (y.mass, y.width)
        assert np.array_equal(x.centroid, y.centroid) and np.array_equal(x.inertia, y.inertia)
    assert [j.name for j in a.joints] == [j.name for j in b.joints]
    for j, k in zip(a.joints, b.joints):
        assert (j.a, j.b) == (k.a, k.b)
        assert np.array_equal(j.p_i, k.p_i) and np.array_equal(j.p_e, k.p_e) and np.array_equal(j.normal, k.normal)
    assert (a.length_scale, a.size, a.crown_index) == (b.length_scale, b.size, b.crown_index)


@pytest.mark.parametrize("fmt", ["dxf", "csv", "obj"])
@pytest.mark.parametrize("config, piers", [("glued", None), ("free", None), ("glued", Piers(0.3, 0.1, courses=3)),
                                           ("free", Piers(0.2, 0.08, offset=0.01, courses=2))])
def test_a_catalogue_arch_written_and_read_back_is_the_same_assembly_and_lp(tmp_path, fmt, config, piers):
    asm = discretise(ARCH, config=config, piers=piers)
    back = read_assembly(write_assembly(asm, tmp_path / f"arch.{fmt}"))
    assert_same(asm, back)
    assert back.is_chain and back.arch is None
    for mu in ((0.577, 1.0), (math.inf, math.inf)):
        lp, lq = solve_lp(asm, *mu), solve_lp(back, *mu)
        assert lp.lam == lq.lam and lp.joint_states == lq.joint_states and lp.forces == lq.forces
    kin, kq = enumerate_mechanisms(asm), enumerate_mechanisms(back)
    assert kin.lam == kq.lam and kin.hinges == kq.hinges


def test_a_written_file_is_never_overwritten(tmp_path):
    asm = discretise(ARCH)
    p = write_assembly(asm, tmp_path / "a.dxf")
    with pytest.raises(ArchdemInputError, match="exists"):
        write_assembly(asm, p)
    with pytest.raises(ArchdemInputError, match="contact 1"):
        write_assembly(discretise(ARCH, contact=0.8), tmp_path / "b.dxf")


def _dxf(path, polys, units=6, layer="blocks", labels=(), extra=None):
    doc = ezdxf.new(units=units)
    msp = doc.modelspace()
    for k, q in enumerate(polys):
        lay = layer[k] if isinstance(layer, (list, tuple)) else layer
        msp.add_lwpolyline(np.asarray(q, float).tolist(), format="xy", close=True, dxfattribs={"layer": lay})
    for text, at in labels:
        msp.add_text(text, dxfattribs={"insert": at, "layer": "labels"})
    if extra:
        extra(msp)
    doc.saveas(str(path))
    return path


def rect(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def test_a_single_block_drawn_in_mm_rocks_at_b_over_h(tmp_path):
    """A block 200 x 800 mm drawn on the ground (the lowest edge), depth from its layer: lambda = b/h."""
    p = _dxf(tmp_path / "block.dxf", [rect(0, 0, 200, 800)], units=4, layer="block depth 100", labels=[("B", (100, 400))])
    asm = read_assembly(p)
    b = asm.bodies[0]
    assert b.name == "B" and b.width == pytest.approx(0.1) and b.mass == pytest.approx(DRAWN_DENSITY * 0.2 * 0.8 * 0.1)
    assert [j.is_base for j in asm.joints] == [True] and asm.joints[0].length == pytest.approx(0.2)
    assert solve_lp(asm, math.inf, math.inf).lam == pytest.approx(0.25, rel=1e-9)
    assert solve_lp(asm, 0.2, 0.2).lam == pytest.approx(0.2, rel=1e-9)  # slides first when mu < b/h
    with pytest.raises(ArchdemInputError, match="states its units as mm, and units m were given"):
        read_assembly(p, units="m")


@pytest.mark.parametrize("beam_density", [500.0, 5000.0])
def test_the_rocking_frame_drawn_in_dxf_is_the_closed_form_frame(tmp_path, beam_density):
    """Piers 2b x 2h under a lintel, each block on its own layer depth; the drawn lintel is denser by its
    depth (the same mass ratio gamma as the closed form): onset b/h, the frame's restitution and frequency."""
    b, h, span, d = 0.05, 0.2, 0.3, 0.05
    xi, xo = span / 2, span / 2 + 2 * b
    gamma_depth = 0.1 * beam_density / 500.0
    p = _dxf(tmp_path / "frame.dxf", [rect(-xo, -2 * h, -xi, 0), rect(-xo, 0, xo, d), rect(xi, -2 * h, xo, 0),
                                      rect(-1, -2 * h - 0.1, 1, -2 * h)],
             layer=["piers depth 0.1", f"lintel depth {gamma_depth!r}", "piers depth 0.1", "ground"])
    asm = read_assembly(p)
    assert asm.is_chain and len(asm.joints) == 4
    gamma = asm.bodies[1].mass / (asm.bodies[0].mass + asm.bodies[2].mass)
    kin, lp = enumerate_mechanisms(asm), solve_lp(asm, math.inf, math.inf)
    assert kin.lam == pytest.approx(b / h, rel=1e-12) and lp.lam == pytest.approx(b / h, rel=1e-9)
    fb, (blk, r) = mechanism_four_bar(asm), rocking_frame_equivalent(b, h, gamma)
    assert energy_restitution(fb, fb.face_swapped()) == pytest.approx(r, rel=1e-9)
    assert fb.omega0 == pytest.approx(blk.omega0, rel=1e-9) and fb.phi_cr == pytest.approx(math.atan(b / h), rel=1e-7)


def test_a_drawing_in_the_xz_plane_with_3d_polylines(tmp_path):
    doc = ezdxf.new(units=6)
    msp = doc.modelspace()
    for q in (rect(0, 0, 0.2, 0.4), rect(0, 0.4, 0.2, 0.8)):
        msp.add_polyline3d([(x, 5.0, z) for x, z in q], close=True)
    doc.saveas(str(tmp_path / "xz.dxf"))
    asm = read_assembly(tmp_path / "xz.dxf", depth=0.1)
    assert [b.name for b in asm.bodies] == ["B1", "B2"] and asm.total_mass == pytest.approx(DRAWN_DENSITY * 0.1 * 0.16)
    assert solve_lp(asm, math.inf, math.inf).lam == pytest.approx(0.25, rel=1e-9)


def test_a_csv_in_mm_and_an_stl_of_the_same_blocks(tmp_path):
    (tmp_path / "w.csv").write_text("block,x,z\nA,0,0\nA,200,0\nA,200,400\nA,0,400\nB,0,400\nB,200,400\nB,200,800\nB,0,800\n")
    asm = read_assembly(tmp_path / "w.csv", units="mm", depth=0.1)
    assert asm.total_mass == pytest.approx(DRAWN_DENSITY * 0.1 * 0.16) and solve_lp(asm, math.inf, math.inf).lam == pytest.approx(0.25)
    scene = trimesh.util.concatenate([prism(b.outline, 0.1) for b in asm.bodies])
    scene.export(tmp_path / "w.stl")
    stl = read_assembly(tmp_path / "w.stl")  # float32 vertices: the same blocks to single precision
    assert stl.total_mass == pytest.approx(asm.total_mass, rel=1e-6)
    assert solve_lp(stl, math.inf, math.inf).lam == pytest.approx(0.25, rel=1e-6)


def test_a_non_convex_block_read_from_a_drawing_is_split(tmp_path):
    ell = [[0, 0], [0.6, 0], [0.6, 0.2], [0.2, 0.2], [0.2, 0.6], [0, 0.6]]
    asm = read_assembly(_dxf(tmp_path / "l.dxf", [ell]), depth=0.1)
    assert len(asm.bodies[0].pieces) == 2 and asm.total_mass == pytest.approx(DRAWN_DENSITY * 0.1 * 0.2)


@pytest.mark.parametrize("name, content, message", [
    ("g.dxf", "this is not a drawing\n", "not a readable DXF file"),
    ("g.csv", "a,b\n1,2\n", "the header must name the columns block, x, z"),
    ("n.csv", "block,x,z\nA,0,zero\n", "row 2: x and z must be numbers"),
    ("t.csv", "block,x,z\nA,0,0\nA,1,0\nB,0,1\nA,1,1\n", "block 'A' appears in two places"),
    ("e.csv", "", "empty"),
    ("g.obj", "v 0 0\nf 1 2 3\n", "a vertex needs three numbers"),
    ("f.obj", "o A\nf 1 2 3\n", "a face refers to a vertex not defined before it"),
    ("g.stl", "solid nothing\nendsolid\n", "STL"),
    ("g.step", "ISO-10303-21;", "unknown drawing format"),
])
def test_garbage_files_are_refused_in_one_line(tmp_path, name, content, message):
    (tmp_path / name).write_text(content)
    with pytest.raises(ArchdemInputError, match=message) as exc:
        read_assembly(tmp_path / name, depth=0.1)
    assert "\n" not in str(exc.value)


def test_open_polylines_and_arcs_are_refused_in_one_line(tmp_path):
    def open_one(msp):
        msp.add_lwpolyline([(0, 0.2), (0.2, 0.2), (0.2, 0.4)], dxfattribs={"layer": "walls"})

    with pytest.raises(ArchdemInputError, match="open polyline on layer 'walls'"):
        read_assembly(_dxf(tmp_path / "o.dxf", [rect(0, 0, 0.2, 0.2)], extra=open_one), depth=0.1)

    def arc(msp):
        msp.add_lwpolyline([(0, 0.2, 0), (0.2, 0.2, 0.5), (0.2, 0.4, 0)], format="xyb", close=True)

    with pytest.raises(ArchdemInputError, match="has arc segments"):
        read_assembly(_dxf(tmp_path / "a.dxf", [rect(0, 0, 0.2, 0.2)], extra=arc), depth=0.1)
    with pytest.raises(ArchdemInputError, match="no such file"):
        read_assembly(tmp_path / "missing.dxf")
    with pytest.raises(ArchdemInputError, match="no closed polylines"):
        read_assembly(_dxf(tmp_path / "empty.dxf", []))


def test_a_drawing_states_its_density_or_takes_masonry_s(tmp_path):
    """No density in the file: masonry's (DRAWN_DENSITY), said in the source; the file's archdem:density, or the
    one given, otherwise. A uniform density scales the masses and changes no multiplier."""
    p = _dxf(tmp_path / "block.dxf", [rect(0, 0, 200, 800)], units=4, layer="block depth 100")
    asm = read_assembly(p)
    assert (asm.density, asm.source["density_from"]) == (DRAWN_DENSITY, "default") != (500.0, "default")
    assert asm.total_mass == pytest.approx(DRAWN_DENSITY * 0.2 * 0.8 * 0.1)
    given = read_assembly(p, density=2400.0)
    assert (given.density, given.source["density_from"]) == (2400.0, "given")
    assert given.total_mass == pytest.approx(asm.total_mass * 2400 / DRAWN_DENSITY)
    assert solve_lp(given, 0.3, 1.0).lam == solve_lp(asm, 0.3, 1.0).lam

    def stated(doc_path):
        doc = ezdxf.readfile(str(doc_path))
        doc.header.custom_vars.append("archdem:density", "1800")
        doc.saveas(str(tmp_path / "stated.dxf"))
        return tmp_path / "stated.dxf"

    s = read_assembly(stated(p))
    assert (s.density, s.source["density_from"]) == (1800.0, "file")
    assert read_assembly(stated(p), density=2400.0).density == 2400.0  # the option overrides the file
    (tmp_path / "w.csv").write_text("# archdem: density=2200\nblock,x,z\nA,0,0\nA,0.2,0\nA,0.2,0.4\nA,0,0.4\n")
    assert read_assembly(tmp_path / "w.csv", depth=0.1).density == 2200.0
    (tmp_path / "bad.csv").write_text("# archdem: density=-1\nblock,x,z\nA,0,0\nA,0.2,0\nA,0.2,0.4\nA,0,0.4\n")
    with pytest.raises(ArchdemInputError, match="archdem:density must be a positive number"):
        read_assembly(tmp_path / "bad.csv", depth=0.1)


@pytest.mark.parametrize("suffix", [".dxf", ".csv", ".obj"])
def test_archdem_writes_the_density_so_a_catalogue_arch_keeps_its_masses(tmp_path, suffix):
    asm = discretise(ARCH)
    back = read_assembly(write_assembly(asm, tmp_path / f"a{suffix}"))
    assert (back.density, back.source["density_from"]) == (asm.density, "file") == (500.0, "file")
    assert [b.mass for b in back.bodies] == [b.mass for b in asm.bodies]
