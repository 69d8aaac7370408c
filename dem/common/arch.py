"""A pointed arch as the plain parameters a study case or a result file stores, and back."""
from __future__ import annotations

from specimens.geometry import PointedArch


def arch_params(arch: PointedArch) -> dict:
    """The exact constructor parameters of ``arch`` (JSON-serialisable) [m]."""
    return {"e": float(arch.e), "t": float(arch.t), "Rp": float(arch.Rp), "width": float(arch.width)}


def arch_from_params(p: dict) -> PointedArch:
    """The arch of :func:`arch_params`' dict ``p`` [m]."""
    return PointedArch(e=p["e"], t=p["t"], Rp=p["Rp"], width=p["width"])
