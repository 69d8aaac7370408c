"""Shake-run result files (HDF5, format ``archdem-shake-1``): write atomically, read back."""
from __future__ import annotations

import json
from dataclasses import asdict
from pathlib import Path

import h5py

from dem.common.hdf5 import read_model, read_sim, write_model, write_sim
from dem.core.settings import Settings
from dem.experiments.shake.run import FORMAT, ShakeResult, motion_trace
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path, to_json


def save_shake(result: ShakeResult, path) -> "Path":
    """Write ``result`` to ``path`` (.h5) atomically, never overwriting: root attributes (format,
    summary, settings, protocol, criterion, versions), ``model``, ``input`` (``t``, ``a_g`` [m/s^2]
    sampled at the simulator step, ``motion`` JSON) and ``sim`` (histories, as tilt results)."""
    path = Path(path)
    result.result_file = str(path)
    with atomic_path(path) as tmp:
        with h5py.File(tmp, "w") as f:
            f.attrs.update({
                "format": FORMAT, "label": result.label, "collapsed": result.collapsed,
                "t_collapse": result.t_collapse if result.t_collapse is not None else float("nan"),
                "mode": result.mode, "summary": to_json(result.summary()), "settings": to_json(result.settings.to_dict()),
                "protocol": to_json(asdict(result.protocol)), "criterion": to_json(result.criterion),
                "versions": to_json(result.versions),
            })
            write_model(f.create_group("model"), result.model)
            g = f.create_group("input")
            t, a = motion_trace(result.motion, result.sim.duration, result.settings.dt)
            g.attrs["motion"] = to_json(result.motion.describe())
            g.create_dataset("t", data=t, compression="gzip")
            g.create_dataset("a_g", data=a, compression="gzip")
            s = f.create_group("sim")
            write_sim(s, result.sim)
            s["crown_u"] = result.crown_u
    return path


def load_shake(path) -> dict:
    """Read a shake run file: dict with ``model``, ``settings``, ``sim`` (SimResult), ``summary``,
    ``input_t``, ``input_a`` [m/s^2], ``crown_u`` [m], ``protocol``, ``criterion``."""
    with h5py.File(path, "r") as f:
        if f.attrs.get("format") != FORMAT:
            raise ArchdemInputError(f"{path} is not an archdem shake result")
        protocol = json.loads(f.attrs["protocol"])
        protocol.setdefault("confirm_fraction", None)  # before docs/decisions/012: the firing was the collapse
        return {
            "label": str(f.attrs["label"]), "model": read_model(f["model"]),
            "settings": Settings.from_dict(json.loads(f.attrs["settings"])),
            "protocol": protocol, "criterion": json.loads(f.attrs["criterion"]),
            "summary": json.loads(f.attrs["summary"]), "motion": json.loads(f["input"].attrs["motion"]),
            "input_t": f["input/t"][()], "input_a": f["input/a_g"][()],
            "sim": read_sim(f["sim"]), "crown_u": f["sim/crown_u"][()],
        }
