"""Result files: one HDF5 file per tilt run (h5py), written atomically, never overwritten.

Layout: root attributes ``format``, ``label``, scalar outcome (``lambda``, ``theta_deg``,
``mode``, ``n_sims``, ``wall_s``, ``bracket``) and JSON attributes ``settings``, ``protocol``,
``criterion``, ``versions``, ``joints``, ``levels``, ``summary``, ``lp_check`` (the answer beside the LP
of the same blocks, with its warning); group ``model`` (bodies with
their convex pieces, mass, centroid, inertia, outline; joints; base; source parameters);
groups ``collapse`` and ``stable`` (the two simulations behind the bracket: load, outcome and
the time histories ``t``, ``pos``, ``quat``, ``gravity``, ``dmax``, ``ke``, ``fpower``).
"""
from __future__ import annotations

import json
from pathlib import Path

import h5py
import numpy as np

from dem.common.hdf5 import read_model, read_sim, write_model, write_sim
from dem.core.detect import JointState
from dem.core.settings import Settings
from dem.experiments.tilt.check import HINGE_STATES, LpCheck
from dem.experiments.tilt.run import TiltProtocol, TiltResult
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path, to_json

FORMAT = "archdem-tilt-1"
FORMER_GUESS_BRACKET = (0.95, 1.01)  # the first bracket of files written before TiltProtocol.guess_bracket


def save_result(result: TiltResult, path: str | Path) -> Path:
    """Write ``result`` to ``path`` (.h5) atomically; an existing file is never overwritten."""
    path = Path(path)
    result.result_file = str(path)
    with atomic_path(path) as tmp:
        with h5py.File(tmp, "w") as f:
            f.attrs.update({
                "format": FORMAT, "label": result.label, "lambda": result.lam, "theta_deg": result.theta_deg,
                "mode": result.mode, "n_sims": result.n_sims, "wall_s": result.wall_s,
                "bracket": np.array(result.bracket), "settings": to_json(result.settings.to_dict()),
                "protocol": to_json(result.protocol.__dict__), "criterion": to_json(result.criterion),
                "versions": to_json(result.versions), "joints": to_json([j.to_dict() for j in result.joints]),
                "levels": to_json(result.levels), "summary": to_json(result.summary()),
                "lp_check": to_json(result.lp_check.to_dict() if result.lp_check is not None else None),
            })
            write_model(f.create_group("model"), result.model)
            for name in ("collapse", "stable"):
                s = getattr(result, name)
                if s is not None:
                    write_sim(f.create_group(name), s)
    return path


def load_result(path: str | Path) -> TiltResult:
    """Read a tilt result written by :func:`save_result`."""
    with h5py.File(path, "r") as f:
        if f.attrs.get("format") != FORMAT:
            raise ArchdemInputError(f"{path} is not an archdem tilt result")
        model = read_model(f["model"])
        sims = {n: (read_sim(f[n]) if n in f else None) for n in ("collapse", "stable")}
        res = TiltResult(
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
        chk = json.loads(f.attrs["lp_check"]) if "lp_check" in f.attrs else None  # none in files before the check
    if chk:
        res.lp_check = LpCheck(res.label, res.lam, float(chk["lp_lambda"]), tuple(tuple(h) for h in chk["lp_hinges"]),
                               bool(chk["lp_slides"]), chk["lp_friction"].startswith("none"), res.settings.contact_law,
                               tuple((j.joint, j.face) for j in res.joints if j.state in HINGE_STATES),
                               float(chk["tolerance_pct"]) / 100)
    return res
