"""HDF5 groups shared by the result files: the model (bodies, joints, base) and one simulation."""
from __future__ import annotations

import json

import h5py
import numpy as np

from dem.core.detect import JointState
from dem.core.model import BaseSpec, BodySpec, JointSpec, Model
from dem.core.simulate import History, SimResult
from foundation.io import to_json


def write_model(g: h5py.Group, m: Model) -> None:
    g.attrs.update(name=m.name, size=m.size, crown=m.crown, source=to_json(m.source))
    bg = g.create_group("bodies")
    for k, b in enumerate(m.bodies):
        h = bg.create_group(f"{k:04d}")
        h.attrs.update(name=b.name, width=b.width, mass=b.mass, n_pieces=len(b.pieces))
        h["centroid"], h["inertia"], h["outline"] = b.centroid, b.inertia, b.outline
        for i, p in enumerate(b.pieces):
            h[f"piece{i}"] = p
    jg = g.create_group("joints")
    jg.attrs["names"] = to_json([j.name for j in m.joints])
    jg["ab"] = np.array([[j.a, j.b] for j in m.joints], dtype=int).reshape(-1, 2)
    jg["p_i"] = np.array([j.p_i for j in m.joints]).reshape(-1, 2)
    jg["p_e"] = np.array([j.p_e for j in m.joints]).reshape(-1, 2)
    jg["normal"] = np.array([j.normal for j in m.joints]).reshape(-1, 2)
    base = g.create_group("base")
    base.attrs.update(width=m.base.width, n_pieces=len(m.base.pieces))
    for i, p in enumerate(m.base.pieces):
        base[f"piece{i}"] = p


def read_model(g: h5py.Group) -> Model:
    bodies = []
    for key in sorted(g["bodies"]):
        h = g["bodies"][key]
        pieces = tuple(h[f"piece{i}"][()] for i in range(int(h.attrs["n_pieces"])))
        bodies.append(BodySpec(str(h.attrs["name"]), pieces, float(h.attrs["width"]), float(h.attrs["mass"]),
                               h["centroid"][()], h["inertia"][()], h["outline"][()]))
    jg = g["joints"]
    names = json.loads(jg.attrs["names"])
    joints = tuple(JointSpec(n, int(ab[0]), int(ab[1]), pi, pe, nr)
                   for n, ab, pi, pe, nr in zip(names, jg["ab"][()], jg["p_i"][()], jg["p_e"][()], jg["normal"][()]))
    bg = g["base"]
    base = BaseSpec(tuple(bg[f"piece{i}"][()] for i in range(int(bg.attrs["n_pieces"]))), float(bg.attrs["width"]))
    return Model(str(g.attrs["name"]), tuple(bodies), joints, base, float(g.attrs["size"]), int(g.attrs["crown"]),
                 json.loads(g.attrs["source"]))


def write_sim(g: h5py.Group, s: SimResult) -> None:
    g.attrs.update(load=to_json(s.load), duration=s.duration, collapsed=s.collapsed, t_collapse=s.t_collapse,
                   mode=s.mode, joints=to_json([j.to_dict() for j in s.joints]), out_of_plane=to_json(s.out_of_plane),
                   wall_s=s.wall_s, steps=s.steps, t_rest=s.t_rest, t_exceed=s.t_exceed, t_confirm=s.t_confirm,
                   friction_work=s.history.friction_work)
    h = s.history
    for k in ("t", "pos", "quat", "gravity", "dmax", "ke", "fpower"):
        g.create_dataset(k, data=getattr(h, k), compression="gzip" if getattr(h, k).size > 1000 else None)


def read_sim(g: h5py.Group) -> SimResult:
    h = History(*(g[k][()] for k in ("t", "pos", "quat", "gravity", "dmax", "ke", "fpower")))
    joints = [JointState(**d) for d in json.loads(g.attrs["joints"])]
    return SimResult(json.loads(g.attrs["load"]), float(g.attrs["duration"]), h, bool(g.attrs["collapsed"]),
                     float(g.attrs["t_collapse"]), joints, str(g.attrs["mode"]), json.loads(g.attrs["out_of_plane"]),
                     float(g.attrs["wall_s"]), int(g.attrs["steps"]), float(g.attrs.get("t_rest", float("nan"))),
                     # files before the confirmed collapse (docs/decisions/012): the criterion's firing was the collapse
                     float(g.attrs.get("t_exceed", g.attrs["t_collapse"])),
                     float(g.attrs.get("t_confirm", g.attrs["t_collapse"])))
