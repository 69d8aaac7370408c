"""Versions and platform facts stored with every result (reproducibility)."""
from __future__ import annotations

import platform
import sys
from importlib.metadata import PackageNotFoundError, version


def package_version(name: str) -> str:
    try:
        return version(name)
    except PackageNotFoundError:
        return "not installed"


def provenance(extra: tuple[str, ...] = ()) -> dict[str, str]:
    """Versions of archdem and the libraries whose numbers a result depends on."""
    out = {"python": sys.version.split()[0], "platform": platform.platform()}
    for name in ("archdem", "numpy", "scipy", "trimesh", "h5py", "pybullet", "mujoco") + tuple(extra):
        out[name] = package_version(name)
    return out


def run_provenance(engine: str) -> dict:
    """:func:`provenance` plus the engine's own description (name, version, engine options)."""
    from dem.engines import get_engine

    eng = get_engine(engine)
    try:
        return {**provenance(), **eng.versions()}
    finally:
        eng.close()
