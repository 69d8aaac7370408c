"""Result files: one HDF5 file per tilt run (h5py), written atomically, never overwritten.

Layout: root attributes ``format``, ``label``, scalar outcome (``lambda``, ``theta_deg``,
``mode``, ``n_sims``, ``wall_s``, ``bracket``) and JSON attributes ``settings``, ``protocol``,
``criterion``, ``versions``, ``joints``, ``levels``, ``summary``; group ``model`` (bodies with
their convex pieces, mass, centroid, inertia, outline; joints; base; source parameters);
groups ``collapse`` and ``stable`` (the two simulations behind the bracket: load, outcome and
the time histories ``t``, ``pos``, ``quat``, ``gravity``, ``dmax``, ``ke``, ``fpower``).
"""
from __future__ import annotations

import json
from pathlib import Path

import h5py
import numpy as np

from dem.atomic import atomic_path
from dem.detect import JointState
from dem.model import BaseSpec, BodySpec, JointSpec, Model
from dem.protocols import FORMER_GUESS_BRACKET, History, SimResult, TiltProtocol, TiltResult
from dem.settings import Settings

FORMAT = "archdem-tilt-1"


def _js(o) -> str:
    def default(x):
        if isinstance(x, np.ndarray):
            return x.tolist()
        if isinstance(x, (np.floating, np.integer, np.bool_)):
            return x.item()
        raise TypeError(type(x).__name__)

    return json.dumps(o, default=default)


def _write_model(g: h5py.Group, m: Model) -> None:
    g.attrs.update(name=m.name, size=m.size, crown=m.crown, source=_js(m.source))
    bg = g.create_group("bodies")
    for k, b in enumerate(m.bodies):
        h = bg.create_group(f"{k:04d}")
        h.attrs.update(name=b.name, width=b.width, mass=b.mass, n_pieces=len(b.pieces))
        h["centroid"], h["inertia"], h["outline"] = b.centroid, b.inertia, b.outline
        for i, p in enumerate(b.pieces):
            h[f"piece{i}"] = p
    jg = g.create_group("joints")
    jg.attrs["names"] = _js([j.name for j in m.joints])
    jg["ab"] = np.array([[j.a, j.b] for j in m.joints], dtype=int).reshape(-1, 2)
    jg["p_i"] = np.array([j.p_i for j in m.joints]).reshape(-1, 2)
    jg["p_e"] = np.array([j.p_e for j in m.joints]).reshape(-1, 2)
    jg["normal"] = np.array([j.normal for j in m.joints]).reshape(-1, 2)
    base = g.create_group("base")
    base.attrs.update(width=m.base.width, n_pieces=len(m.base.pieces))
    for i, p in enumerate(m.base.pieces):
        base[f"piece{i}"] = p


def _read_model(g: h5py.Group) -> Model:
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


def _write_sim(g: h5py.Group, s: SimResult) -> None:
    g.attrs.update(load=_js(s.load), duration=s.duration, collapsed=s.collapsed, t_collapse=s.t_collapse,
                   mode=s.mode, joints=_js([j.to_dict() for j in s.joints]), out_of_plane=_js(s.out_of_plane),
                   wall_s=s.wall_s, steps=s.steps, t_rest=s.t_rest,
                   friction_work=s.history.friction_work)
    h = s.history
    for k in ("t", "pos", "quat", "gravity", "dmax", "ke", "fpower"):
        g.create_dataset(k, data=getattr(h, k), compression="gzip" if getattr(h, k).size > 1000 else None)


def _read_sim(g: h5py.Group) -> SimResult:
    h = History(*(g[k][()] for k in ("t", "pos", "quat", "gravity", "dmax", "ke", "fpower")))
    joints = [JointState(**d) for d in json.loads(g.attrs["joints"])]
    return SimResult(json.loads(g.attrs["load"]), float(g.attrs["duration"]), h, bool(g.attrs["collapsed"]),
                     float(g.attrs["t_collapse"]), joints, str(g.attrs["mode"]), json.loads(g.attrs["out_of_plane"]),
                     float(g.attrs["wall_s"]), int(g.attrs["steps"]), float(g.attrs.get("t_rest", float("nan"))))


def save_result(result: TiltResult, path: str | Path) -> Path:
    """Write ``result`` to ``path`` (.h5) atomically; an existing file is never overwritten."""
    path = Path(path)
    result.result_file = str(path)
    with atomic_path(path) as tmp:
        with h5py.File(tmp, "w") as f:
            f.attrs.update({
                "format": FORMAT, "label": result.label, "lambda": result.lam, "theta_deg": result.theta_deg,
                "mode": result.mode, "n_sims": result.n_sims, "wall_s": result.wall_s,
                "bracket": np.array(result.bracket), "settings": _js(result.settings.to_dict()),
                "protocol": _js(result.protocol.__dict__), "criterion": _js(result.criterion),
                "versions": _js(result.versions), "joints": _js([j.to_dict() for j in result.joints]),
                "levels": _js(result.levels), "summary": _js(result.summary()),
            })
            _write_model(f.create_group("model"), result.model)
            for name in ("collapse", "stable"):
                s = getattr(result, name)
                if s is not None:
                    _write_sim(f.create_group(name), s)
    return path


def load_result(path: str | Path) -> TiltResult:
    """Read a tilt result written by :func:`save_result`."""
    with h5py.File(path, "r") as f:
        if f.attrs.get("format") != FORMAT:
            from specimens.errors import ArchdemInputError

            raise ArchdemInputError(f"{path} is not an archdem tilt result")
        model = _read_model(f["model"])
        sims = {n: (_read_sim(f[n]) if n in f else None) for n in ("collapse", "stable")}
        return TiltResult(
            str(f.attrs["label"]), model, Settings.from_dict(json.loads(f.attrs["settings"])),
            # a result written before the rest rule held every level its full hold_time, and one
            # written before guess_bracket started from FORMER_GUESS_BRACKET x the guess, before
            # probe_ends simulated both ends first
            TiltProtocol(**{"rest_after": None, "guess_bracket": FORMER_GUESS_BRACKET, "probe_ends": "first",
                            **json.loads(f.attrs["protocol"])}),
            float(f.attrs["lambda"]),
            tuple(float(x) for x in f.attrs["bracket"]), int(f.attrs["n_sims"]), float(f.attrs["wall_s"]),
            str(f.attrs["mode"]), [JointState(**d) for d in json.loads(f.attrs["joints"])],
            [tuple(x) for x in json.loads(f.attrs["levels"])], sims["collapse"], sims["stable"],
            json.loads(f.attrs["criterion"]), json.loads(f.attrs["versions"]), str(path))
