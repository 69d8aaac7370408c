"""Case functions of the studies: one DEM tilt test per case (the friction map and the campaign's
tilt step), its replay with the time history, and a closed-form stand-in for tests.

A case is a JSON-serialisable dict (its key identifies it in the study file); case functions are
passed to :func:`dem.studies.sweep.run_study` as functions (``DEM_CASE``, ``SYNTHETIC_CASE``).
"""
from __future__ import annotations

import math
import os
import time
import uuid
from dataclasses import fields
from pathlib import Path

import numpy as np

from dem.common.arch import arch_from_params, arch_params
from dem.core import detect
from dem.core.model import from_assembly
from dem.core.settings import Settings
from dem.experiments.tilt.run import TiltProtocol, TiltResult, hold_level, tilt, time_scale_of
from specimens.blocks import check_contact, discretise
from specimens.drawn import DrawnAssembly, from_dict
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from specimens.piers import Piers

MAP_TILT_TOL = 0.02  # relative lambda bracket of each map tilt (default protocol of the map)
# A map tilt reads the mode of the collapsing level of a 2 % bracket started at the LP; a bracket as
# narrow as the tilt test's moved that level nearer the threshold and mu* with it
MAP_GUESS_BRACKET = (0.95, 1.01)  # wider than the tilt test's: docs/decisions/004-map-guess-bracket.md
MAP_PROTOCOL = {"kind": "hold", "tol": MAP_TILT_TOL, "start": "lp", "guess_bracket": list(MAP_GUESS_BRACKET)}
# the hold's timing, rest rule and first bracket (and the order of its ends), written out in every
# case (see make_case)
CASE_PROTOCOL_FIELDS = ("ramp_time", "hold_time", "rest_after", "rest_window", "rest_growth", "guess_bracket",
                        "probe_ends")


def _jsonable(v):
    return list(v) if isinstance(v, tuple) else v


def make_case(label: str, arch: PointedArch | DrawnAssembly, config: str, mu_joint: float, mu_base: float,
              protocol: dict | None = None, settings: dict | None = None, n_voussoirs: int = 8,
              time_scale: float | str = "auto", contact: float = 1.0, piers=None) -> dict:
    """One tilt case (a JSON-serialisable dict; its key identifies it in the study file).

    ``protocol`` / ``settings``: overrides of :class:`dem.experiments.tilt.run.TiltProtocol` /
    :class:`dem.core.settings.Settings` fields at the catalogue scale; the time scale is applied
    by the case function. ``contact``: the effective contact of the joints (written only when
    below 1, so full-contact cases keep their keys); ``piers``: the arch stands on these
    :class:`~specimens.piers.Piers` (written only when given). ``arch`` may be a drawing's blocks
    (:class:`~specimens.drawn.DrawnAssembly`): the case then holds them whole (``drawn``), runs the
    protocol at its own scale and has no configuration, voussoirs or piers of its own.
    """
    if config not in ("glued", "free") and not (isinstance(arch, DrawnAssembly) and config == arch.config):
        raise ArchdemInputError(f"configuration must be 'glued' or 'free', got {config!r}")
    for nm, v in (("mu_joint", mu_joint), ("mu_base", mu_base)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ArchdemInputError(f"{nm} must be a finite number > 0, got {v!r}")
    default = TiltProtocol()
    drawn = isinstance(arch, DrawnAssembly)
    if drawn and piers is not None:
        raise ArchdemInputError("a drawing holds its piers as blocks: draw them instead of --pier-*")
    return {
        "label": label, **({"drawn": arch.to_dict()} if drawn else {"arch": arch_params(arch)}), "config": config,
        "n_voussoirs": int(n_voussoirs),
        "mu_joint": round(float(mu_joint), 9), "mu_base": float(mu_base),
        # CASE_PROTOCOL_FIELDS are written out so that a study made with other defaults is not
        # resumed into (its cases get other keys and are recomputed beside the old ones)
        "protocol": {**{k: _jsonable(getattr(default, k)) for k in CASE_PROTOCOL_FIELDS},
                     **(protocol if protocol is not None else MAP_PROTOCOL)},
        "settings": dict(settings or {}),
        "time_scale": time_scale_of(arch, time_scale),
        **({} if check_contact(contact) == 1.0 else {"contact": float(contact)}),
        **({} if piers is None else {"piers": piers.describe()}),
    }


def scaled_protocol(d: dict, s: float):
    names = {f.name for f in fields(TiltProtocol)}
    unknown = set(d) - names
    if unknown:
        raise ArchdemInputError(f"unknown tilt protocol fields: {sorted(unknown)}")
    return TiltProtocol(**{**d, "time_scale": s}).slowed(s)  # the scale recorded: tilt() does not apply it again


def scaled_settings(case: dict):
    s = float(case.get("time_scale", 1.0))
    base = Settings()
    kw = dict(case.get("settings") or {})
    kw.setdefault("dt", base.dt * s)
    kw.setdefault("record_every", base.record_every * s)
    return Settings(mu_joint=case["mu_joint"], mu_base=case["mu_base"], **kw)


def _case_setup(case: dict):
    """Assembly, model, settings and protocol of a DEM tilt case."""
    if "drawn" in case:
        asm = from_dict(case["drawn"]).with_contact(float(case.get("contact", 1.0)))
    else:
        asm = discretise(arch_from_params(case["arch"]), n_voussoirs=int(case.get("n_voussoirs", 8)),
                         config=case["config"], contact=float(case.get("contact", 1.0)),
                         bands={k: tuple(v) for k, v in case["bands"].items()} if case.get("bands") else None,
                         piers=Piers(**case["piers"]) if case.get("piers") else None)
    settings = scaled_settings(case)
    proto = scaled_protocol(case["protocol"], float(case.get("time_scale", 1.0)))
    return asm, from_assembly(asm, name=case["label"]), settings, proto


# ----------------------------------------------------------------------------- case functions
def tilt_case(case: dict) -> dict:
    """Case function (DEM): one tilt test of ``case`` (see :func:`make_case`).

    Returns ``lambda``, ``theta_deg``, ``mode``, ``bracket`` (2,), ``n_sims``, ``wall_s`` [s],
    ``friction_work_J``, ``levels`` (n, 2: lambda, collapsed) and the joint states at collapse
    (``joint_names``, ``joint_states``, ``joint_faces``, ``joint_opening`` [m], ``joint_slip`` [m]).
    """
    asm, model, settings, proto = _case_setup(case)
    res = tilt(model, settings, proto, label=case["label"], assembly=asm)
    joints = [j.to_dict() if hasattr(j, "to_dict") else dict(j) for j in res.joints]
    fw = res.collapse.history.friction_work if getattr(res, "collapse", None) is not None else float("nan")
    return {
        "lambda": float(res.lam), "theta_deg": math.degrees(math.atan(res.lam)), "mode": str(res.mode),
        "bracket": [float(x) for x in res.bracket], "n_sims": int(res.n_sims), "wall_s": float(res.wall_s),
        "friction_work_J": float(fw) if math.isfinite(fw) else None,
        "levels": np.array([[float(a), float(b)] for a, b in res.levels]).reshape(-1, 2),
        "joint_names": [j["joint"] for j in joints] or None,
        "joint_states": [j["state"] for j in joints] or None,
        "joint_faces": [j["face"] or "-" for j in joints] or None,
        "joint_opening": np.array([float(j["opening"]) for j in joints]),
        "joint_slip": np.array([float(j["slip"]) for j in joints]),
    }


def replay_tilt(case: dict, results: dict):
    """The :class:`dem.experiments.tilt.run.TiltResult` of a finished hold-protocol DEM ``case`` whose
    stored ``results`` are given, with the time history of its collapse: the collapsing level
    (upper end of the bracket) is simulated again. The engines are deterministic for identical
    command sequences, so this is the simulation the case ran (one simulation, not a tilt test)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.core.provenance import run_provenance

    _, model, settings, proto = _case_setup(case)
    if proto.kind != "hold":
        raise ArchdemInputError(f"only hold-protocol tilt cases can be replayed, not {proto.kind!r}")
    lo, hi = (float(x) for x in results["bracket"])
    sim = hold_level(model, settings, proto, hi)
    levels = [(float(a), bool(b)) for a, b in np.asarray(results["levels"]).reshape(-1, 2)]
    return TiltResult(case["label"], model, settings, proto, float(results["lambda"]), (lo, hi),
                      int(results["n_sims"]), float(results["wall_s"]), sim.mode, sim.joints, levels, sim, None,
                      detect.criterion(settings, model), run_provenance(settings.engine, settings.engine_options))


def synthetic_case(case: dict) -> dict:
    """Case function (closed form, no DEM): rocking at ``lam_rock`` above ``mu_star``, sliding
    with ``lambda = lam_rock * mu / mu_star`` below, from ``case["synthetic"]`` =
    ``{"mu_star", "lam_rock"}``. Hooks for tests: ``count_dir`` (one file per evaluation),
    ``fail_mu`` (raise at that friction), ``crash_marker`` (if that file exists and the friction
    is ``crash_mu`` (default any): delete it and kill the worker process)."""
    syn = case["synthetic"]
    mu = float(case["mu_joint"])
    if syn.get("count_dir"):
        Path(syn["count_dir"], f"{mu}-{os.getpid()}-{uuid.uuid4().hex}").touch()
    marker = syn.get("crash_marker")
    if marker and os.path.exists(marker) and abs(mu - float(syn.get("crash_mu", mu))) < 1e-12:
        try:
            os.remove(marker)
        except FileNotFoundError:
            pass
        else:
            os._exit(3)
    if syn.get("fail_mu") is not None and abs(mu - float(syn["fail_mu"])) < 1e-12:
        raise ValueError(f"synthetic case fails on purpose at mu = {mu}")
    if syn.get("sleep"):
        time.sleep(float(syn["sleep"]))
    ms, lr = float(syn["mu_star"]), float(syn["lam_rock"])
    rocks = mu >= ms
    return {"lambda": lr if rocks else lr * mu / ms, "mode": "rocking" if rocks else "sliding", "n_sims": 1,
            "wall_s": 0.0, "joint_names": None, "joint_states": None, "joint_faces": None}


#: The case function of the DEM tilt studies, and its closed-form stand-in for tests.
DEM_CASE = tilt_case
SYNTHETIC_CASE = synthetic_case
