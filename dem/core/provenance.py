"""Versions and platform facts stored with every result (reproducibility)."""
from __future__ import annotations

import platform
import sys
from importlib.metadata import PackageNotFoundError, version

from dem.core.engines import engine_package, get_engine
from dem.core.engines.options import EngineOptions


def package_version(name: str) -> str:
    try:
        return version(name)
    except PackageNotFoundError:
        return "not installed"


def numpy_cpu() -> tuple[dict[str, bool], list[str]]:
    """numpy's view of the CPU: its feature flags, and the SIMD targets it dispatches here."""
    try:
        from numpy._core import _multiarray_umath as mu
    except ImportError:  # numpy < 2
        from numpy.core import _multiarray_umath as mu
    f = mu.__cpu_features__
    return f, [t for t in mu.__cpu_dispatch__ if f.get(t)]


def cpu_math() -> str:
    """The CPU features that decide which math kernels run: glibc picks FMA variants of sin/cos
    (called inside the engines) when the CPU has FMA and AVX2, so results can differ in the last
    bit, and near a threshold by more, between CPUs with and without them (dem.core.engines.inputs)."""
    f, _ = numpy_cpu()
    libc = " ".join(platform.libc_ver()).strip() or "unknown libc"
    return f"{platform.machine()} {libc}; " + " ".join(k for k in ("FMA3", "AVX2", "AVX512F") if f.get(k))


def engine_version(name: str) -> str:
    """The installed version of engine ``name``'s package ("not installed" if it is not)."""
    return package_version(engine_package(name))


def provenance(extra: tuple[str, ...] = ()) -> dict[str, str]:
    """Versions of archdem and the libraries whose numbers a result depends on."""
    out = {"python": sys.version.split()[0], "platform": platform.platform(), "cpu_math": cpu_math()}
    for name in ("archdem", "numpy", "scipy", "trimesh", "h5py", "pybullet", "mujoco", "compas_lmgc90") + tuple(extra):
        out[name] = package_version(name)
    return out


def run_provenance(engine: str, options: EngineOptions | None = None) -> dict:
    """:func:`provenance` plus the engine's own description: name, version and the ``options`` it ran with
    (``Settings.engine_options``; None: the engine's defaults)."""
    eng = get_engine(engine, options)
    try:
        return {**provenance(), **eng.versions()}
    finally:
        eng.close()
