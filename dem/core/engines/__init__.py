"""Engine registry: ``get_engine(name, options)`` returns a new, unbuilt backend instance with its options
(:mod:`dem.core.engines.options`, light: no engine library is imported before a backend is asked for)."""
from __future__ import annotations

import importlib

from dem.core.engines.base import Engine
from dem.core.engines.options import EngineOptions, LMGC90Options, MuJoCoOptions, PyBulletOptions, engine_options
from dem.core.extras import require
from foundation.errors import ArchdemInputError

_ENGINES = {"pybullet": ("dem.core.engines.pybullet_engine", "PyBulletEngine"), "mujoco": ("dem.core.engines.mujoco_engine", "MuJoCoEngine"),
            "lmgc90": ("dem.core.engines.lmgc90_engine", "LMGC90Engine")}
#: The module each optional engine needs (dem.core.extras names the extra that installs it).
_MODULES = {"mujoco": ("mujoco", "the MuJoCo engine"), "lmgc90": ("compas_lmgc90", "the LMGC90 engine")}


def available_engines() -> list[str]:
    return sorted(_ENGINES)


def engine_installed(name: str) -> bool:
    """True if engine ``name``'s optional package is importable (always for PyBullet)."""
    import importlib.util

    return name not in _MODULES or importlib.util.find_spec(_MODULES[name][0]) is not None


def engine_package(name: str) -> str:
    """The distribution whose version is engine ``name``'s (``compas_lmgc90`` for LMGC90)."""
    return _MODULES.get(name, (name,))[0]


def check_engine(name: str) -> None:
    """Refuse in one line an unknown engine, or one whose optional package is not installed."""
    if name not in _ENGINES:
        raise ArchdemInputError(f"unknown engine {name!r}; available: {', '.join(available_engines())}")
    if name in _MODULES:
        require(*_MODULES[name])


def get_engine(name: str, options: EngineOptions | None = None) -> Engine:
    """A new backend instance of engine ``name`` (see :func:`available_engines`) with ``options`` (its
    options class of :mod:`dem.core.engines.options`; None: the engine's defaults). Another engine's
    options are refused in one line."""
    if name not in _ENGINES:
        raise ArchdemInputError(f"unknown engine {name!r}; available: {', '.join(available_engines())}")
    opts = engine_options(name, options)
    if name in _MODULES:
        require(*_MODULES[name])
    mod, cls = _ENGINES[name]
    return getattr(importlib.import_module(mod), cls)(opts)


__all__ = ["Engine", "EngineOptions", "PyBulletOptions", "MuJoCoOptions", "LMGC90Options", "get_engine",
           "available_engines", "engine_installed"]
