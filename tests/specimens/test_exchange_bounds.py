"""Every drawing reader is total and bounded: a damaged file, an entity it does not take, a depth that
is no length, a drawing too large or with too many blocks: one line naming the file, nothing else."""
import tempfile
import time
import warnings
from pathlib import Path

import ezdxf
import pytest
import trimesh
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from specimens import ArchdemInputError, Piers, discretise, get_specimen
from specimens.constants import MAX_LENGTH_M
from specimens.drawn import MAX_BLOCKS
from specimens.exchange import EXAMPLE_DRAWING, read_assembly, write_assembly
from specimens.mesh import prism

ARCH = get_specimen("Sh06-Sd015").arch


def _valid_files() -> dict[str, bytes]:
    """The shipped DXF, a catalogue arch on piers written as DXF, CSV and OBJ, and a wall of two blocks as STL."""
    asm = discretise(ARCH, piers=Piers(0.3, 0.1, courses=2))
    out = {"survey.dxf": EXAMPLE_DRAWING.read_bytes()}
    with tempfile.TemporaryDirectory() as d:
        for fmt in ("dxf", "csv", "obj"):
            out[f"arch.{fmt}"] = write_assembly(asm, Path(d) / f"arch.{fmt}").read_bytes()
        blocks = [[(0, 0), (0.2, 0), (0.2, 0.4), (0, 0.4)], [(0, 0.4), (0.2, 0.4), (0.2, 0.8), (0, 0.8)]]
        trimesh.util.concatenate([prism(b, 0.1) for b in blocks]).export(Path(d) / "wall.stl")
        out["wall.stl"] = (Path(d) / "wall.stl").read_bytes()
    return out


VALID = _valid_files()
NOISE = [b"", b"-", b"nan", b"inf", b"1e999", b"-1e308", b"0", b"\x00", b"\xff\xfe", b"\n", b"0\nSECTION\n", b"x"]


def _read_quietly(path: Path):
    """read_assembly(path) succeeds or says one line naming the file; it never warns."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            read_assembly(path, depth=0.1)
        except ArchdemInputError as exc:
            msg = str(exc)
            assert "\n" not in msg and msg.startswith(f"{path.name}: "), msg
    assert [str(w.message) for w in caught] == []


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(VALID)), data=st.data())
def test_truncated_and_mutated_drawings_are_read_or_refused_in_one_line(name, data):
    raw = VALID[name]
    how = data.draw(st.sampled_from(["truncate", "replace", "delete", "duplicate"]))
    at = data.draw(st.integers(0, len(raw)))
    if how == "truncate":
        bad = raw[:at]
    elif how == "replace":
        n = data.draw(st.integers(1, 40))
        bad = raw[:at] + data.draw(st.sampled_from(NOISE)) + raw[at + n:]
    else:  # a run of lines deleted or doubled
        lines = raw.splitlines(keepends=True)
        k = data.draw(st.integers(0, max(len(lines) - 1, 0)))
        n = data.draw(st.integers(1, 12))
        bad = b"".join(lines[:k] + (lines[k:k + n] * 2 if how == "duplicate" else []) + lines[k + n:])
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / name
        path.write_bytes(bad)
        _read_quietly(path)


def test_the_valid_files_are_read():
    with tempfile.TemporaryDirectory() as d:
        for name, raw in VALID.items():
            (Path(d) / name).write_bytes(raw)
            assert read_assembly(Path(d) / name).bodies


def test_a_truncated_dxf_is_one_line_naming_the_file(tmp_path):
    p = tmp_path / "truncated.dxf"
    p.write_bytes(EXAMPLE_DRAWING.read_bytes()[:3000])
    with pytest.raises(ArchdemInputError, match=r"^truncated\.dxf: not a readable DXF file, truncated or damaged"):
        read_assembly(p)


def test_an_arc_on_a_layer_of_blocks_is_refused_naming_it_and_its_layer(tmp_path):
    doc = ezdxf.readfile(str(EXAMPLE_DRAWING))
    doc.modelspace().add_arc((0, 0), 100, 0, 90, dxfattribs={"layer": "ring depth 450"})
    doc.saveas(str(tmp_path / "arc.dxf"))
    with pytest.raises(ArchdemInputError, match=r"^arc\.dxf: ARC \w+ on layer 'ring depth 450': archdem reads blocks "
                                                r"as closed polylines"):
        read_assembly(tmp_path / "arc.dxf")
    doc = ezdxf.readfile(str(EXAMPLE_DRAWING))
    doc.modelspace().add_line((0, 0), (100, 0), dxfattribs={"layer": "ground"})
    doc.saveas(str(tmp_path / "line.dxf"))
    with pytest.raises(ArchdemInputError, match=r"LINE \w+ on layer 'ground'"):
        read_assembly(tmp_path / "line.dxf")


WALL = "block,x,z,layer\nA,0,0,{d}\nA,0.2,0,{d}\nA,0.2,0.4,{d}\nA,0,0.4,{d}\n"


@pytest.mark.parametrize("layer", ["depth -0.1", "piers depth -0.1", "depth_-0.1", "depth 0", "depth inf", "depth nan",
                                   "depth--0.1"])
def test_a_depth_that_is_no_length_is_refused(tmp_path, layer):
    (tmp_path / "w.csv").write_text(WALL.format(d=layer))
    with pytest.raises(ArchdemInputError, match=r"^w\.csv: layer '.*' states depth .*; a depth must be a positive length"):
        read_assembly(tmp_path / "w.csv")


@pytest.mark.parametrize("layer, mass", [("depth 0.1", 8.0), ("piers-depth-0.1", 8.0), ("depth 1e-1", 8.0)])
def test_a_depth_stated_by_a_layer_is_read(tmp_path, layer, mass):
    (tmp_path / "w.csv").write_text(WALL.format(d=layer))
    assert read_assembly(tmp_path / "w.csv", density=1000.0).total_mass == pytest.approx(mass)


@pytest.mark.parametrize("name, text", [
    ("huge.csv", "block,x,z\nA,0,0\nA,5e9,0\nA,5e9,1\nA,0,1\n"),
    ("huge.obj", "o A\nv 0 0 0\nv 5e9 0 0\nv 5e9 1 0\nv 0 1 0\nv 0 0 1\nv 5e9 0 1\nv 5e9 1 1\nv 0 1 1\nf 1 2 3 4\nf 5 6 7 8\n"),
    ("deep.csv", "block,x,z,layer\nA,0,0,depth 2e3\nA,1,0,depth 2e3\nA,1,1,depth 2e3\nA,0,1,depth 2e3\n"),
])
def test_a_drawing_larger_than_the_longest_length_is_refused_at_once(tmp_path, name, text):
    (tmp_path / name).write_text(text)
    t = time.perf_counter()
    with pytest.raises(ArchdemInputError, match=rf"^{name.replace('.', '[.]')}: .* more than {MAX_LENGTH_M:g} m"):
        read_assembly(tmp_path / name, depth=0.1)
    assert time.perf_counter() - t < 1.0


def test_a_huge_dxf_and_one_in_the_wrong_units_are_refused_at_once(tmp_path):
    doc = ezdxf.new(units=6)
    doc.modelspace().add_lwpolyline([(0, 0), (5e9, 0), (5e9, 1), (0, 1)], close=True)
    doc.saveas(str(tmp_path / "huge.dxf"))
    t = time.perf_counter()
    with pytest.raises(ArchdemInputError, match=r"^huge\.dxf: the drawing is 5e\+09 m across, more than 1000 m"):
        read_assembly(tmp_path / "huge.dxf", depth=0.1)
    assert time.perf_counter() - t < 1.0
    (tmp_path / "mm.csv").write_text("block,x,z\nA,0,0\nA,2000,0\nA,2000,400\nA,0,400\n")
    read_assembly(tmp_path / "mm.csv", units="mm", depth=0.1)  # 2 m in mm
    with pytest.raises(ArchdemInputError, match="2e\\+03 m across"):
        read_assembly(tmp_path / "mm.csv", units="m", depth=0.1)


def test_a_drawing_of_too_many_blocks_is_refused_before_it_is_assembled(tmp_path):
    rows = ["block,x,z"] + [f"B{k},{x},{z}" for k in range(MAX_BLOCKS + 1)
                            for x, z in ((k % 50, k // 50), (k % 50 + 1, k // 50), (k % 50 + 1, k // 50 + 1), (k % 50, k // 50 + 1))]
    (tmp_path / "many.csv").write_text("\n".join(rows) + "\n")
    t = time.perf_counter()
    with pytest.raises(ArchdemInputError, match=rf"^many\.csv: the drawing holds {MAX_BLOCKS + 1} blocks, more than {MAX_BLOCKS}"):
        read_assembly(tmp_path / "many.csv", units="mm", depth=0.1)
    assert time.perf_counter() - t < 1.0
