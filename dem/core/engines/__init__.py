"""Engine registry: ``get_engine(name)`` returns a new, unbuilt backend instance."""
from __future__ import annotations

import importlib

from dem.core.engines.base import Engine
from dem.core.extras import require
from specimens.errors import ArchdemInputError

_ENGINES = {"pybullet": ("dem.core.engines.pybullet_engine", "PyBulletEngine"), "mujoco": ("dem.core.engines.mujoco_engine", "MuJoCoEngine")}


def available_engines() -> list[str]:
    return sorted(_ENGINES)


def get_engine(name: str) -> Engine:
    """A new backend instance of engine ``name`` (see :func:`available_engines`)."""
    if name not in _ENGINES:
        raise ArchdemInputError(f"unknown engine {name!r}; available: {', '.join(available_engines())}")
    if name == "mujoco":
        require("mujoco", "the MuJoCo engine")
    mod, cls = _ENGINES[name]
    return getattr(importlib.import_module(mod), cls)()


__all__ = ["Engine", "get_engine", "available_engines"]
