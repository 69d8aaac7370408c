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


def cpu_math() -> str:
    """The CPU features that decide which math kernels run: glibc picks FMA variants of sin/cos
    (called inside the engines) when the CPU has FMA and AVX2, so results can differ in the last
    bit, and near a threshold by more, between CPUs with and without them (dem.engines.inputs)."""
    try:
        from numpy._core._multiarray_umath import __cpu_features__ as f
    except ImportError:  # numpy < 2
        from numpy.core._multiarray_umath import __cpu_features__ as f
    libc = " ".join(platform.libc_ver()).strip() or "unknown libc"
    return f"{platform.machine()} {libc}; " + " ".join(k for k in ("FMA3", "AVX2", "AVX512F") if f.get(k))


def provenance(extra: tuple[str, ...] = ()) -> dict[str, str]:
    """Versions of archdem and the libraries whose numbers a result depends on."""
    out = {"python": sys.version.split()[0], "platform": platform.platform(), "cpu_math": cpu_math()}
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
