import numpy as np
import pytest
import trimesh

from specimens.blocks import discretise
from specimens.catalogue import CATALOGUE, get_specimen
from specimens.mesh import assembly_meshes, export_meshes, prism


@pytest.mark.parametrize("shape", ["linearised", "curved"])
@pytest.mark.parametrize("config", ["free", "glued"])
def test_pieces_watertight_convex_and_mass_consistent(shape, config):
    asm = discretise(get_specimen("Sh1-Sd015").arch, config=config, shape=shape)
    for body, pieces in zip(asm.bodies, assembly_meshes(asm)):
        vol = 0.0
        for m in pieces:
            assert m.is_watertight and m.is_winding_consistent and m.is_convex
            assert m.volume > 0  # outward normals
            vol += m.volume
        # trimesh's mass properties are an independent computation of the same solid
        assert vol * asm.density == pytest.approx(body.mass, rel=1e-10)
        com = sum(m.volume * m.center_mass for m in pieces) / vol
        np.testing.assert_allclose(com, [*body.centroid, 0.0], atol=1e-12)


def test_inertia_matches_trimesh():
    asm = discretise(get_specimen("Sh06-Sd020").arch, config="free")
    body = asm.body("R4")
    (m,) = assembly_meshes(asm)[body.index]
    m.density = asm.density
    # trimesh reports the inertia about the centre of mass, in the mesh frame
    np.testing.assert_allclose(m.moment_inertia, body.inertia, rtol=1e-9, atol=1e-15)


def test_prism_refuses_non_convex():
    asm = discretise(get_specimen("Sh06-Sd020").arch, config="free")
    with pytest.raises(ValueError, match="convex"):
        prism(asm.body("C").outline, 0.1)


@pytest.mark.parametrize("sid", [s.id for s in CATALOGUE])
def test_exported_meshes_load_back(tmp_path, sid):
    asm = discretise(get_specimen(sid).arch, config="glued")
    files = export_meshes(asm, tmp_path, "stl")
    assert len(files) == sum(len(b.pieces) for b in asm.bodies)
    for f in files:
        m = trimesh.load(f)
        assert m.is_watertight and m.is_convex


def test_glb_and_obj_export(tmp_path):
    asm = discretise(get_specimen("Sh02-Sd015").arch, config="free", shape="curved")
    (glb,) = export_meshes(asm, tmp_path / "g", "glb")
    scene = trimesh.load(glb)
    assert len(scene.geometry) == sum(len(b.pieces) for b in asm.bodies)
    assert all(g.is_watertight for g in scene.geometry.values())
    objs = export_meshes(asm, tmp_path / "o", "obj")
    assert trimesh.load(objs[0]).is_watertight
