"""Assemblies to and from drawing files: DXF, CSV of block polygons, OBJ/STL meshes
(docs/physics/geometry.md#16-assemblies-from-drawings).

:func:`read_assembly` reads any of them into a :class:`~specimens.drawn.DrawnAssembly`;
:func:`write_assembly` writes any assembly (a catalogue arch, an arch on piers, a drawn one) so
that reading the file back gives the same bodies, joints, masses and answers, bit for bit.

The conventions, one for every format (a DXF layer, the CSV's ``layer`` column, an OBJ object's
name): a name containing ``ground`` or ``support`` marks a support (fixed); ``pieces``: convex
pieces of the block whose outline holds them (DXF) or named ``<block>/<k>`` (CSV, OBJ);
``joints``: a label at a joint's mid-point names it; ``depth <D>`` states the blocks' depth in
the drawing's units. A comment line ``# archdem: key=value ...`` (CSV, OBJ) or the DXF's custom
properties ``archdem:key`` carry the length scale, collapse length and density [kg/m^3] archdem's
writers used (a drawing that states no density is :data:`specimens.constants.DRAWN_DENSITY`).
"""
from __future__ import annotations

import contextlib
import csv
import hashlib
import logging
import math
import re
import warnings
from pathlib import Path

import numpy as np

from specimens.blocks import Assembly
from specimens.constants import DRAWN_DENSITY, MAX_LENGTH_M
from specimens.drawn import MAX_BLOCKS, DrawnAssembly, DrawnBlock, _merge, _point_in, _self_intersects, assemble
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path
from specimens.sections import polygon_properties, signed_area

#: Length units a drawing may be in, and their size in metres.
UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048}
#: DXF $INSUNITS codes of those units (0: unitless).
DXF_UNITS = {1: "in", 2: "ft", 4: "mm", 5: "cm", 6: "m"}
FORMATS = {".dxf": "dxf", ".csv": "csv", ".obj": "obj", ".stl": "stl"}
# a hyphen right after "depth" separates (piers-depth-600); a minus after a space or another hyphen is a sign
_DEPTH = re.compile(r"depth(?:-|[ _]*)([-+]?(?:[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?|inf(?:inity)?|nan))", re.IGNORECASE)
#: DXF entities a drawing's reader takes; any other on a layer of blocks, supports or pieces is refused.
DXF_TAKEN = ("LWPOLYLINE", "POLYLINE", "TEXT", "MTEXT")
_META_KEYS = ("length_scale", "size", "density")
#: The example structure shipped with archdem: a pointed arch on piers as built (specimens/data/README.md).
EXAMPLE_DRAWING = Path(__file__).resolve().parent / "data" / "survey-arch-on-piers.dxf"


def role(layer: str) -> str:
    """What a layer (or object) name marks: ``ground``, ``pieces``, ``joints`` or ``blocks``."""
    low = layer.lower()
    if "ground" in low or "support" in low:
        return "ground"
    if "pieces" in low:
        return "pieces"
    if "joints" in low:
        return "joints"
    return "blocks"


def layer_depth(layer: str) -> float | None:
    """The depth a layer name states (``... depth 300``), in the drawing's units, or None."""
    m = _DEPTH.search(layer)
    return float(m.group(1)) if m else None


def _layer_depth(layer: str, path: Path) -> float | None:
    """:func:`layer_depth`, refused in one line unless a positive finite number."""
    d = layer_depth(layer)
    if d is not None and not (math.isfinite(d) and d > 0):
        raise ArchdemInputError(f"{path.name}: layer {layer!r} states depth {d:g}; a depth must be a positive length")
    return d


def _check_size(path: Path, n_blocks: int, pts: np.ndarray, scale: float, depths=()) -> None:
    """The drawing's bounds, checked before any work: at most MAX_BLOCKS blocks; finite coordinates;
    an extent and depths of at most MAX_LENGTH_M (the longest length an option takes)."""
    if n_blocks > MAX_BLOCKS:
        raise ArchdemInputError(f"{path.name}: the drawing holds {n_blocks} blocks, more than {MAX_BLOCKS}")
    pts = np.asarray(pts, float)
    if pts.size and not np.all(np.isfinite(pts)):
        raise ArchdemInputError(f"{path.name}: the drawing holds coordinates that are not finite numbers")
    ext = float(np.ptp(pts.reshape(len(pts), -1), axis=0).max()) * scale if pts.size else 0.0
    if not ext <= MAX_LENGTH_M:
        raise ArchdemInputError(f"{path.name}: the drawing is {ext:.3g} m across, more than {MAX_LENGTH_M:g} m "
                                "(are its units right?)")
    big = [d for d in depths if d is not None and not d * scale <= MAX_LENGTH_M]
    if big:
        raise ArchdemInputError(f"{path.name}: a layer states a depth of {big[0] * scale:.3g} m, more than "
                                f"{MAX_LENGTH_M:g} m (are its units right?)")


@contextlib.contextmanager
def _quiet(logger_name: str):
    """A library's log records and warnings kept off the terminal while it reads a file (a bad file is
    refused in one line)."""
    log = logging.getLogger(logger_name)
    null = logging.NullHandler()
    propagate = log.propagate
    log.addHandler(null)
    log.propagate = False
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            yield
    finally:
        log.propagate = propagate
        log.removeHandler(null)


def _units(stated: str | None, option: str | None, path: Path) -> float:
    if option is not None and option not in UNITS:
        raise ArchdemInputError(f"units must be one of {', '.join(UNITS)}, got {option!r}")
    if stated is not None and option is not None and stated != option:
        raise ArchdemInputError(f"{path.name} states its units as {stated}, and units {option} were given")
    return UNITS[stated or option or "m"]


# ---------------------------------------------------------------------------------------------
# reading
# ---------------------------------------------------------------------------------------------
def read_assembly(path: str | Path, units: str | None = None, depth: float | None = None,
                  density: float | None = None, tol: float | None = None, up: str | None = None) -> DrawnAssembly:
    """The assembly drawn in ``path`` (``.dxf``, ``.csv``, ``.obj``, ``.stl``).

    ``units``: the drawing's length unit (m, cm, mm, in, ft) when the file does not state it (a
    DXF's ``$INSUNITS``; default m); ``depth`` [m]: the blocks' out-of-plane depth where the
    drawing does not give it (a mesh gives its own); ``density`` [kg/m^3] of every block (default: the
    one the file states, else :data:`~specimens.constants.DRAWN_DENSITY`; the source records which, as
    ``density_from``: given, file or default); ``tol`` [m]: contact
    tolerance (default: :data:`specimens.drawn.RELATIVE_TOLERANCE` of the drawing's extent);
    ``up``: the vertical axis of a mesh (``y`` or ``z``; default: z if the blocks' depth runs
    along y, else y)."""
    p = Path(path)
    fmt = FORMATS.get(p.suffix.lower())
    if fmt is None:
        raise ArchdemInputError(f"{p.name}: unknown drawing format {p.suffix!r}; give a .dxf, .csv, .obj or .stl file")
    if not p.is_file():
        raise ArchdemInputError(f"{p}: no such file")
    if depth is not None and not (isinstance(depth, (int, float)) and math.isfinite(depth) and depth > 0):
        raise ArchdemInputError(f"depth must be a positive length in m, got {depth!r}")
    reader = {"dxf": _read_dxf, "csv": _read_csv, "obj": _read_mesh, "stl": _read_mesh}[fmt]
    try:
        return _read(p, fmt, reader, units, depth, density, tol, up)
    except ArchdemInputError as exc:  # every refusal of a drawing names the file
        msg = str(exc)
        if msg.startswith((p.name, str(p))):
            raise
        raise ArchdemInputError(f"{p.name}: {msg}") from None


def _read(p: Path, fmt: str, reader, units, depth, density, tol, up) -> DrawnAssembly:
    data = reader(p, units, up)
    scale = data["scale"]
    meta = data.get("meta", {})
    stated = meta.pop("density", None)
    origin = "given" if density is not None else "file" if stated is not None else "default"
    density = density if density is not None else stated if stated is not None else DRAWN_DENSITY
    source = {"file": p.name, "format": fmt, "sha256": hashlib.sha256(p.read_bytes()).hexdigest(),
              "units": data["units"], "depth_m": depth, "density": float(density), "density_from": origin}
    if depth is not None:  # how many blocks the option gave their depth (the others' layers state it)
        source["blocks_at_depth_m"] = sum(b.depth is None for b in data["blocks"])
    blocks = [DrawnBlock(b.name, b.outline * scale, tuple(q * scale for q in b.pieces) if b.pieces else None,
                         b.depth * scale if b.depth is not None else None) for b in data["blocks"]]
    return assemble(blocks, [s * scale for s in data["supports"]], density=density, depth=depth, tol=tol,
                    joint_labels=[(n, q * scale) for n, q in data["joints"]], source=source,
                    length_scale=meta.get("length_scale"), size=meta.get("size"))


def _label_blocks(polys: list[tuple[np.ndarray, float | None]], labels: list[tuple[str, np.ndarray]],
                  pieces: list[np.ndarray]) -> list[DrawnBlock]:
    """Blocks named by the labels inside them (else ``B<k>``, k their place in the file) with the pieces inside them."""
    names = [f"B{k + 1}" for k in range(len(polys))]
    for text, pt in labels:
        hit = [k for k, (o, _) in enumerate(polys) if _point_in(o, pt)]
        if len(hit) == 1:
            names[hit[0]] = text
    own: list[list[np.ndarray]] = [[] for _ in polys]
    for q in pieces:
        c = polygon_properties(q).centroid
        hit = [k for k, (o, _) in enumerate(polys) if _point_in(o, c)]
        if len(hit) != 1:
            raise ArchdemInputError(f"a piece (centroid {c[0]:.6g}, {c[1]:.6g}) lies in no block outline")
        own[hit[0]].append(q)
    return [DrawnBlock(n, o, tuple(ps) or None, d) for n, (o, d), ps in zip(names, polys, own)]


def _read_dxf(path: Path, units: str | None, up: str | None) -> dict:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    import ezdxf
    from ezdxf.lldxf.const import DXFError

    if up is not None:
        raise ArchdemInputError("a DXF drawing's vertical axis is found from its plane: drop up")
    try:  # a truncated or damaged file: ezdxf raises these (StopIteration from its tag reader)
        with _quiet("ezdxf"):
            doc = ezdxf.readfile(str(path))
            return _dxf_drawing(doc, path, units)
    except ArchdemInputError:
        raise
    except (OSError, DXFError, UnicodeError, ValueError, StopIteration, TypeError, AttributeError, KeyError,
            IndexError, OverflowError) as exc:
        why = (str(exc).strip().splitlines() or [""])[0][:120] or type(exc).__name__
        raise ArchdemInputError(f"{path.name}: not a readable DXF file, truncated or damaged ({why})") from None


def _dxf_drawing(doc, path: Path, units: str | None) -> dict:
    code = int(doc.header.get("$INSUNITS", 0) or 0)
    if code and code not in DXF_UNITS:
        raise ArchdemInputError(f"{path.name}: drawing units $INSUNITS = {code} are not a length archdem reads "
                                f"({', '.join(UNITS)})")
    stated = DXF_UNITS.get(code)
    scale = _units(stated, units, path)
    polys3, labels3, joints3 = [], [], []
    n_blocks = 0
    for e in doc.modelspace():
        kind = e.dxftype()
        layer = str(e.dxf.get("layer", "0"))
        if kind not in DXF_TAKEN and role(layer) != "joints":
            raise ArchdemInputError(f"{path.name}: {kind} {e.dxf.get('handle', '?')} on layer {layer!r}: archdem reads "
                                    "blocks as closed polylines with straight sides (draw a curve as chords)")
        if kind in ("LWPOLYLINE", "POLYLINE"):
            pts, closed = _dxf_points(e, path)
            if not closed:
                if len(pts) > 2 and np.array_equal(pts[0], pts[-1]):
                    pts = pts[:-1]
                else:
                    raise ArchdemInputError(f"{path.name}: open polyline on layer {layer!r} (handle {e.dxf.handle}); "
                                            "every block is a closed outline")
            polys3.append((layer, pts))
            n_blocks += role(layer) == "blocks"
            if n_blocks > MAX_BLOCKS:  # refused before the rest is read
                _check_size(path, n_blocks, pts, scale)
        elif kind in ("TEXT", "MTEXT"):
            text = (e.plain_text() if kind == "MTEXT" else e.dxf.text).strip()
            ins = np.array(e.dxf.insert, float)
            (joints3 if role(layer) == "joints" else labels3).append((text, ins))
    if not polys3:
        raise ArchdemInputError(f"{path.name}: no closed polylines (one per block) in the drawing")
    allp = np.vstack([p for _, p in polys3])
    _check_size(path, n_blocks, allp, scale, [_layer_depth(layer, path) for layer, _ in polys3 if role(layer) == "blocks"])
    ax = _plane(allp, path)
    to2 = lambda q: np.asarray(q, float)[..., ax]  # noqa: E731
    blocks, supports, pieces = [], [], []
    for layer, pts in polys3:
        r = role(layer)
        q = to2(pts)
        if r == "ground":
            supports.append(q)
        elif r == "pieces":
            pieces.append(q)
        elif r == "joints":
            continue
        else:
            blocks.append((q, _layer_depth(layer, path)))
    meta = {}
    for k in _META_KEYS:
        v = doc.header.custom_vars.get(f"archdem:{k}")
        if v is not None:
            meta[k] = _meta_float(k, v, path)
    return {"blocks": _label_blocks(blocks, [(t, to2(p)) for t, p in labels3], pieces), "supports": supports,
            "joints": [(t, to2(p)) for t, p in joints3], "scale": scale, "units": stated or units or "m", "meta": meta}


def _meta_float(key: str, v: str, path: Path) -> float:
    try:
        x = float(v)
    except ValueError:
        x = math.nan
    if not (math.isfinite(x) and x > 0):
        raise ArchdemInputError(f"{path.name}: archdem:{key} must be a positive number, got {v!r}")
    return x


def _dxf_points(e, path: Path) -> tuple[np.ndarray, bool]:
    """WCS points (n, 3) of a polyline and whether it is closed; arcs (bulges) refused."""
    if e.dxftype() == "LWPOLYLINE":
        raw = list(e.get_points("xyb"))
        if any(abs(b) > 0 for _, _, b in raw):
            raise ArchdemInputError(f"{path.name}: polyline {e.dxf.handle} has arc segments; draw block faces as "
                                    "straight segments")
        ext = tuple(e.dxf.get("extrusion", (0.0, 0.0, 1.0)))
        if tuple(float(v) for v in ext) == (0.0, 0.0, 1.0):
            z = float(e.dxf.get("elevation", 0.0))
            pts = np.array([[x, y, z] for x, y, _ in raw], float)
        else:
            pts = np.array([tuple(v) for v in e.vertices_in_wcs()], float)
        return pts, bool(e.closed)
    if e.is_poly_face_mesh or e.is_polygon_mesh:
        raise ArchdemInputError(f"{path.name}: mesh {e.dxf.handle} in the drawing; draw blocks as closed polylines")
    if any(abs(float(v.dxf.get("bulge", 0.0))) > 0 for v in e.vertices):
        raise ArchdemInputError(f"{path.name}: polyline {e.dxf.handle} has arc segments; draw block faces as "
                                "straight segments")
    pts = np.array([tuple(v) for v in (e.points_in_wcs() if hasattr(e, "points_in_wcs") else e.points())], float)
    return pts, bool(e.is_closed)


def _plane(pts: np.ndarray, path: Path) -> list[int]:
    """The two coordinates of the drawing's plane, horizontal first (XY: y up; XZ or YZ: z up)."""
    span = np.ptp(pts, axis=0)
    ext = float(span.max())
    flat = [k for k in range(3) if span[k] <= 1e-9 * ext]
    if 2 in flat:
        return [0, 1]
    if 1 in flat:
        return [0, 2]
    if 0 in flat:
        return [1, 2]
    raise ArchdemInputError(f"{path.name}: the outlines do not lie in one plane parallel to XY, XZ or YZ")


def _read_csv(path: Path, units: str | None, up: str | None) -> dict:
    if up is not None:
        raise ArchdemInputError("a CSV drawing is in x (horizontal) and z (up): drop up")
    scale = _units(None, units, path)
    try:
        text = path.read_text()
    except (OSError, UnicodeError) as exc:
        raise ArchdemInputError(f"{path.name}: not a readable text file ({type(exc).__name__})") from None
    meta: dict[str, float] = {}
    lines = []
    for line in text.splitlines():
        if line.lstrip().startswith("#"):
            m = re.match(r"\s*#\s*archdem:\s*(.*)", line)
            for kv in (m.group(1).split() if m else []):
                k, _, v = kv.partition("=")
                if k in _META_KEYS:
                    meta[k] = _meta_float(k, v, path)
            continue
        if line.strip():
            lines.append(line)
    rows = list(csv.reader(lines))
    if not rows:
        raise ArchdemInputError(f"{path.name}: empty; expected a header block,x,z[,layer] and one row per vertex")
    head = [h.strip().lower() for h in rows[0]]
    if not {"block", "x", "z"} <= set(head):
        raise ArchdemInputError(f"{path.name}: the header must name the columns block, x, z (and optionally layer), "
                                f"got {','.join(rows[0])!r}")
    ib, ix, iz = head.index("block"), head.index("x"), head.index("z")
    il = head.index("layer") if "layer" in head else None
    runs: list[tuple[str, str, list]] = []
    seen: set[tuple[str, str]] = set()  # the runs' keys: a scan of the runs per row was quadratic in the blocks
    for n, r in enumerate(rows[1:], start=2):
        if len(r) < len(head):
            raise ArchdemInputError(f"{path.name}: row {n} has {len(r)} columns, the header {len(head)}")
        try:
            x, z = float(r[ix]), float(r[iz])
        except ValueError:
            raise ArchdemInputError(f"{path.name}: row {n}: x and z must be numbers, got {r[ix]!r}, {r[iz]!r}") from None
        key = (r[ib].strip(), r[il].strip() if il is not None else "")
        if not key[0]:
            raise ArchdemInputError(f"{path.name}: row {n} has no block id")
        if runs and runs[-1][:2] == key:
            runs[-1][2].append((x, z))
        else:
            if key in seen:
                raise ArchdemInputError(f"{path.name}: block {key[0]!r} appears in two places (row {n}); "
                                        "list each block's vertices together")
            runs.append((key[0], key[1], [(x, z)]))
            seen.add(key)
    _check_size(path, sum(role(lay) == "blocks" for _, lay, _ in runs), np.array([p for *_, ps in runs for p in ps]),
                scale, [_layer_depth(lay, path) for _, lay, _ in runs if role(lay) == "blocks"])
    blocks, supports, joints, pieces = [], [], [], {}
    for name, layer, pts in runs:
        q = np.array(pts, float)
        r = role(layer)
        if r == "ground":
            supports.append(q)
        elif r == "joints":
            joints.append((name, q.mean(axis=0) if len(q) > 1 else q[0]))
        elif r == "pieces":
            owner = name.rsplit("/", 1)[0]
            pieces.setdefault(owner, []).append(q)
        else:
            blocks.append((name, q, _layer_depth(layer, path)))
    names = {n for n, _, _ in blocks}
    for owner in pieces:
        if owner not in names:
            raise ArchdemInputError(f"{path.name}: pieces of block {owner!r}, which the file does not hold")
    out = [DrawnBlock(n, q, tuple(pieces.get(n, ())) or None, d) for n, q, d in blocks]
    return {"blocks": out, "supports": supports, "joints": joints, "scale": scale, "units": units or "m", "meta": meta}


def _read_mesh(path: Path, units: str | None, up: str | None) -> dict:
    """Meshes: one convex prism per block (OBJ objects named as blocks; STL solids ``B<k>``)."""
    scale = _units(None, units, path)
    if up not in (None, "y", "z"):
        raise ArchdemInputError(f"up must be y or z, got {up!r}")
    meta: dict[str, float] = {}
    if path.suffix.lower() == ".obj":
        objects, meta = _obj_objects(path)
    else:
        objects = _stl_objects(path)
    if not objects:
        raise ArchdemInputError(f"{path.name}: no meshes in the file")
    allv = np.vstack([v for _, v in objects])
    _check_size(path, len({n.split("/")[0] for n, _ in objects if role(n) == "blocks"}), allv, scale)
    # the out-of-plane axis: each block's vertices take two values along it (its two faces)
    deep = [k for k in range(3) if all(len(np.unique(v[:, k])) == 2 for n, v in objects if role(n) != "joints")]
    if not deep:
        raise ArchdemInputError(f"{path.name}: the meshes are not prisms extruded along one axis (x, y or z)")
    dax = 2 if 2 in deep else deep[0]
    vax = {"y": 1, "z": 2}[up] if up else (2 if dax == 1 else 1)
    if vax == dax:
        raise ArchdemInputError(f"{path.name}: the blocks' depth runs along the vertical axis {up}")
    hax = next(k for k in range(3) if k not in (dax, vax))
    del allv
    blocks, supports, pieces = [], [], {}
    labels = [(name.split("/", 1)[1], v) for name, v in objects if role(name) == "joints" and "/" in name]
    objects = [(name, v) for name, v in objects if role(name) != "joints"]
    for name, v in objects:
        front = v[v[:, dax] == v[:, dax].min()][:, [hax, vax]]
        ring = _ring(front)
        d = float(np.ptp(v[:, dax]))
        r = role(name)
        if r == "ground":
            supports.append(ring)
        elif "/" in name:
            pieces.setdefault(name.rsplit("/", 1)[0], []).append(ring)
        else:
            blocks.append((name, ring, d))
    names = {n for n, _, _ in blocks}
    for owner, ps in pieces.items():
        if owner not in names:  # a block given only as its convex pieces: their union is its outline
            blocks.append((owner, _union(ps, owner, path), float(np.ptp(next(v for n, v in objects
                                                                          if n.startswith(owner + "/"))[:, dax]))))
    out = [DrawnBlock(n, q, tuple(pieces.get(n, ())) or None, d) for n, q, d in blocks]
    joints = [(name, v[:, [hax, vax]].mean(axis=0)) for name, v in labels]
    return {"blocks": out, "supports": supports, "joints": joints, "scale": scale, "units": units or "m", "meta": meta}


def _ring(front: np.ndarray) -> np.ndarray:
    """A face's polygon: its vertices in the file's order when they already go round it, else their hull."""
    _, first = np.unique(front, axis=0, return_index=True)
    pts = front[np.sort(first)]
    if len(pts) >= 3 and abs(signed_area(pts)) > 0 and not _self_intersects(pts, 0.0):
        return pts
    # deferred: `archdem --help` imports this module, not scipy.spatial (docs/architecture.md#imports)
    from scipy.spatial import ConvexHull, QhullError

    try:
        return pts[ConvexHull(pts).vertices]
    except (QhullError, ValueError):
        return pts


def _union(pieces: list[np.ndarray], name: str, path: Path) -> np.ndarray:
    """The outline of a block given only as convex pieces sharing whole edges."""
    pts: list[np.ndarray] = []
    rings = []
    for q in pieces:
        ring = []
        for p in (q if _signed(q) > 0 else q[::-1]):
            k = next((i for i, r in enumerate(pts) if np.allclose(r, p, rtol=0, atol=1e-12)), None)
            if k is None:
                pts.append(p)
                k = len(pts) - 1
            ring.append(k)
        rings.append(ring)
    u = rings[0]
    rest = rings[1:]
    while rest:
        for i, r in enumerate(rest):
            m = _merge(u, r)
            if m is not None:
                u = m
                rest.pop(i)
                break
        else:
            raise ArchdemInputError(f"{path.name}: the pieces of block {name} do not share whole faces; "
                                    "give the block's outline too")
    return np.array([pts[k] for k in u])


def _signed(q: np.ndarray) -> float:
    return signed_area(q)


def _obj_objects(path: Path) -> tuple[list[tuple[str, np.ndarray]], dict]:
    """(name, vertices in file order) per ``o``/``g`` object of an OBJ file, and its archdem comment."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    import trimesh

    try:
        text = path.read_text()
    except (OSError, UnicodeError) as exc:
        raise ArchdemInputError(f"{path.name}: not a readable OBJ file ({type(exc).__name__})") from None
    meta: dict[str, float] = {}
    verts: list[list[float]] = []
    objs: list[tuple[str, list[int]]] = []
    name = None
    for n, line in enumerate(text.splitlines(), start=1):
        w = line.split()
        if not w:
            continue
        if w[0] == "#" and len(w) > 1 and w[1] == "archdem:":
            for kv in w[2:]:
                k, _, v = kv.partition("=")
                if k in _META_KEYS:
                    meta[k] = _meta_float(k, v, path)
        elif w[0] in ("o", "g") and len(w) > 1:
            name = " ".join(w[1:])
        elif w[0] == "v":
            try:
                verts.append([float(x) for x in w[1:4]])
            except ValueError:
                raise ArchdemInputError(f"{path.name}: line {n}: a vertex needs three numbers") from None
            if len(verts[-1]) != 3:
                raise ArchdemInputError(f"{path.name}: line {n}: a vertex needs three numbers")
        elif w[0] in ("f", "l"):
            try:
                idx = [int(x.split("/")[0]) for x in w[1:]]
            except ValueError:
                raise ArchdemInputError(f"{path.name}: line {n}: a face needs vertex numbers") from None
            idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
            if any(not 0 <= i < len(verts) for i in idx):
                raise ArchdemInputError(f"{path.name}: line {n}: a face refers to a vertex not defined before it")
            key = name or f"B{len(objs) + 1}"
            if not objs or objs[-1][0] != key:
                if any(o[0] == key for o in objs):
                    raise ArchdemInputError(f"{path.name}: object {key!r} appears in two places")
                objs.append((key, []))
            objs[-1][1].extend(i for i in idx if i not in objs[-1][1])
    V = np.array(verts, float).reshape(-1, 3)
    out = []
    for key, idx in objs:
        v = V[sorted(idx)]
        with _quiet("trimesh"):
            if not trimesh.Trimesh(v, process=False).vertices.size:  # pragma: no cover - trimesh sanity
                continue
        out.append((key, v))
    return out, meta


def _stl_objects(path: Path) -> list[tuple[str, np.ndarray]]:
    """One block per connected solid of an STL file, ``B<k>`` left to right."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    import trimesh

    try:
        with _quiet("trimesh"):
            mesh = trimesh.load(str(path), file_type="stl", force="mesh")
    except Exception as exc:  # trimesh raises many types on garbage; all mean the same to the user
        raise ArchdemInputError(f"{path.name}: not a readable STL file ({type(exc).__name__})") from None
    if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
        raise ArchdemInputError(f"{path.name}: no triangles in the STL file")
    # deferred: `archdem --help` imports this module, not scipy.sparse (docs/architecture.md#imports)
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    f = np.asarray(mesh.faces)
    e = np.vstack([f[:, [0, 1]], f[:, [1, 2]]])
    n = len(mesh.vertices)
    _, lab = connected_components(coo_matrix((np.ones(len(e)), (e[:, 0], e[:, 1])), shape=(n, n)), directed=False)
    used = np.unique(f)
    parts = [np.asarray(mesh.vertices, float)[[i for i in used if lab[i] == c]] for c in np.unique(lab[used])]
    parts.sort(key=lambda v: tuple(np.round(v.mean(0), 12)))
    return [(f"B{k + 1}", v) for k, v in enumerate(parts)]


# ---------------------------------------------------------------------------------------------
# writing
# ---------------------------------------------------------------------------------------------
def _support_pads(asm) -> list[np.ndarray]:
    """A pad under each base joint: the joint's face pushed away from its block by the collapse length."""
    out = []
    for j in asm.joints:
        if not j.is_base:
            continue
        n = np.asarray(j.normal, float) * (1.0 if j.a < 0 else -1.0)  # from the support into the block
        h = float(getattr(asm, "size", 0.0) or j.length)
        q = np.array([j.p_i, j.p_e, j.p_e - h * n, j.p_i - h * n])
        out.append(q)
    return out


def _meta(asm) -> dict[str, float]:
    # the density too: a catalogue arch read back keeps its masses (drawings default to another density)
    return {"length_scale": float(asm.length_scale), "size": float(asm.size), "density": float(asm.density)}


def _check_writable(asm) -> None:
    if not isinstance(asm, Assembly):
        raise ArchdemInputError(f"write_assembly takes an Assembly, got {type(asm).__name__}")
    if asm.contact != 1.0 or asm.imperfect:
        raise ArchdemInputError("write the full blocks (contact 1): the effective contact is an option of the analysis")
    if any(b.com is not None for b in asm.bodies):
        raise ArchdemInputError("a drawing holds blocks only: the loads carried by piers cannot be written")


def write_assembly(asm: Assembly, path: str | Path, overwrite: bool = False) -> Path:
    """Write ``asm`` (metres) to ``path``: ``.dxf``, ``.csv`` or ``.obj`` (one rigid body per block;
    a non-convex body with its convex pieces); written atomically, never over an existing file
    unless ``overwrite``."""
    p = Path(path)
    fmt = FORMATS.get(p.suffix.lower())
    if fmt not in ("dxf", "csv", "obj"):
        raise ArchdemInputError(f"{p.name}: write a .dxf, .csv or .obj file")
    _check_writable(asm)
    with atomic_path(p, overwrite=overwrite) as tmp:
        {"dxf": _write_dxf, "csv": _write_csv, "obj": _write_obj}[fmt](asm, tmp)
    return p


def _own_pieces(body) -> list[np.ndarray]:
    """The pieces a drawing must carry: none when the body is its one convex outline."""
    if len(body.pieces) == 1 and np.array_equal(body.pieces[0], body.outline):
        return []
    return list(body.pieces)


def _write_dxf(asm, path: Path) -> None:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    import ezdxf

    doc = ezdxf.new(units=6)
    msp = doc.modelspace()
    for k, v in _meta(asm).items():
        doc.header.custom_vars.append(f"archdem:{k}", repr(v))
    for body in asm.bodies:
        layer = f"blocks depth {body.width!r}"
        msp.add_lwpolyline(np.asarray(body.outline).tolist(), format="xy", close=True, dxfattribs={"layer": layer})
        for q in _own_pieces(body):
            msp.add_lwpolyline(np.asarray(q).tolist(), format="xy", close=True, dxfattribs={"layer": "pieces"})
        at = np.asarray(body.pieces[0]).mean(axis=0)  # inside the outline: a convex piece's vertex mean
        msp.add_text(body.name, dxfattribs={"layer": "labels", "insert": (float(at[0]), float(at[1])),
                                            "height": 0.1 * asm.size})
    for j in asm.joints:
        mid = 0.5 * (np.asarray(j.p_i) + np.asarray(j.p_e))
        msp.add_text(j.name, dxfattribs={"layer": "joints", "insert": (float(mid[0]), float(mid[1])),
                                         "height": 0.1 * asm.size})
    for k, q in enumerate(_support_pads(asm)):
        msp.add_lwpolyline(q.tolist(), format="xy", close=True, dxfattribs={"layer": "ground"})
    doc.saveas(str(path))


def _write_csv(asm, path: Path) -> None:
    with open(path, "w", newline="") as fh:
        fh.write("# archdem: " + " ".join(f"{k}={v!r}" for k, v in _meta(asm).items()) + "\n")
        w = csv.writer(fh)
        w.writerow(["block", "x", "z", "layer"])
        for body in asm.bodies:
            for x, z in body.outline:
                w.writerow([body.name, repr(float(x)), repr(float(z)), f"depth {body.width!r}"])
            for k, q in enumerate(_own_pieces(body)):
                for x, z in q:
                    w.writerow([f"{body.name}/{k}", repr(float(x)), repr(float(z)), "pieces"])
        for k, q in enumerate(_support_pads(asm)):
            for x, z in q:
                w.writerow([f"ground {k + 1}", repr(float(x)), repr(float(z)), "ground"])
        for j in asm.joints:
            for x, z in (j.p_i, j.p_e):
                w.writerow([j.name, repr(float(x)), repr(float(z)), "joints"])


def _write_obj(asm, path: Path) -> None:
    lines = ["# archdem: " + " ".join(f"{k}={v!r}" for k, v in _meta(asm).items())]
    nv = 0

    def prism(name: str, poly: np.ndarray, width: float) -> None:
        nonlocal nv
        n = len(poly)
        lines.append(f"o {name}")
        for z in (-width / 2, width / 2):
            lines.extend(f"v {float(x)!r} {float(y)!r} {z!r}" for x, y in poly)
        f = [nv + 1 + k for k in range(n)]
        b = [nv + 1 + n + k for k in range(n)]
        lines.append("f " + " ".join(str(i) for i in reversed(f)))
        lines.append("f " + " ".join(str(i) for i in b))
        lines.extend(f"f {f[k]} {f[(k + 1) % n]} {b[(k + 1) % n]} {b[k]}" for k in range(n))
        nv += 2 * n

    for body in asm.bodies:
        prism(body.name, np.asarray(body.outline), float(body.width))
        for k, q in enumerate(_own_pieces(body)):
            prism(f"{body.name}/{k}", np.asarray(q), float(body.width))
    for k, q in enumerate(_support_pads(asm)):
        prism(f"ground {k + 1}", q if _signed(q) > 0 else q[::-1], float(max(b.width for b in asm.bodies)))
    for j in asm.joints:  # a joint's label: a line along it, on the blocks' front face
        z = -float(asm.bodies[max(j.a, j.b)].width) / 2
        lines += [f"o joints/{j.name}", *(f"v {float(x)!r} {float(y)!r} {z!r}" for x, y in (j.p_i, j.p_e)),
                  f"l {nv + 1} {nv + 2}"]
        nv += 2
    path.write_text("\n".join(lines) + "\n")
