"""Voussoir meshes: each convex piece of each body extruded into a watertight prism.

Meshes are in the arch frame (x horizontal, y up) with the width along z, centred on z = 0.
A non-convex body (crown, curved voussoirs, the glued crown) is a compound of convex
prisms, one per convex piece of :mod:`specimens.blocks` — never its convex hull.
"""
from __future__ import annotations

from pathlib import Path
from typing import Literal

import numpy as np
import trimesh

from specimens.blocks import Assembly, Body
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path
from specimens.sections import is_convex

MeshFormat = Literal["stl", "obj", "glb"]


def prism(polygon: np.ndarray, width: float, inflate: float = 0.0) -> trimesh.Trimesh:
    """Watertight, outward-oriented prism of a convex counter-clockwise polygon [m].

    ``inflate`` offsets every vertex outward from the polygon's centroid by that distance [m]
    (the simulator uses ~1e-6 m so that touching faces produce contacts from the first step).
    """
    poly = np.asarray(polygon, dtype=float)
    if not is_convex(poly):
        raise ValueError("prism() takes convex pieces only; split non-convex blocks into pieces")
    if inflate:
        c = poly.mean(axis=0)
        d = poly - c
        poly = poly + inflate * d / np.linalg.norm(d, axis=1, keepdims=True)
    n = len(poly)
    fan = np.array([[0, k, k + 1] for k in range(1, n - 1)])  # convex: a fan triangulates it
    half = width / 2 + inflate
    mesh = trimesh.creation.extrude_triangulation(poly, fan, height=2 * half)
    mesh.apply_translation([0.0, 0.0, -half])
    mesh.fix_normals()
    return mesh


def body_pieces(body: Body, width: float, inflate: float = 0.0) -> list[trimesh.Trimesh]:
    """The convex prisms of one body, in the arch frame."""
    return [prism(p, width, inflate) for p in body.pieces]


def assembly_meshes(assembly: Assembly, inflate: float = 0.0) -> list[list[trimesh.Trimesh]]:
    """Per body, the list of its convex prisms (each body as deep as it is: ring or piers)."""
    return [body_pieces(b, b.width, inflate) for b in assembly.bodies]


def export_meshes(assembly: Assembly, out_dir: str | Path, fmt: MeshFormat = "stl") -> list[Path]:
    """Write the meshes of ``assembly`` to ``out_dir`` and return the files written.

    ``stl``/``obj``: one file per convex piece, ``<body>_p<k>.<fmt>`` (each loads back as
    one convex, watertight solid). ``glb``: one scene file ``assembly.glb`` with one node
    per piece named ``<body>_p<k>``.
    """
    out = Path(out_dir)
    written: list[Path] = []
    meshes = assembly_meshes(assembly)
    if fmt == "glb":
        scene = trimesh.Scene()
        for body, pieces in zip(assembly.bodies, meshes):
            for k, m in enumerate(pieces):
                scene.add_geometry(m, node_name=f"{body.name}_p{k}", geom_name=f"{body.name}_p{k}")
        target = out / "assembly.glb"
        with atomic_path(target) as tmp:
            tmp.write_bytes(scene.export(file_type="glb"))
        return [target]
    if fmt not in ("stl", "obj"):
        raise ValueError(f"unknown mesh format {fmt!r}")
    targets = [out / f"{body.name}_p{k}.{fmt}" for body, pieces in zip(assembly.bodies, meshes) for k in range(len(pieces))]
    clash = [t for t in targets if t.exists()]
    if clash:  # refused before anything is written: never a folder of mixed old and new meshes
        raise ArchdemInputError(f"{out} holds meshes already ({clash[0].name}, ...); choose another folder")
    for body, pieces in zip(assembly.bodies, meshes):
        for k, m in enumerate(pieces):
            target = out / f"{body.name}_p{k}.{fmt}"
            data = m.export(file_type=fmt)
            with atomic_path(target) as tmp:
                if isinstance(data, str):
                    tmp.write_text(data)
                else:
                    tmp.write_bytes(data)
            written.append(target)
    return written
