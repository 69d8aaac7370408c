"""The backend interface. Protocols and detection use only this.

Poses are reported in the model's arch frame as the position of each body's centroid and the
rotation matrix taking the body from its initial (as-built) orientation to the current one:
a material point at ``x0`` initially is at ``pos + R @ (x0 - c0)``. Engines that use other
body frames (e.g. principal axes) convert internally.

Poses, velocities and contacts are in the world (laboratory) frame. With a driven base
(``build(..., driven_base=True)``) the base is a body whose horizontal motion the caller
prescribes every step (:meth:`Engine.drive_base`); :meth:`Engine.base_motion` gives where it
actually is, so that callers can express results in the table frame.
"""
from __future__ import annotations

import abc
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Contacts:
    """Contact points at one instant (arrays of length n; ``a``/``b`` body indices, -1 = base).

    ``point`` (n, 3) on body b; ``normal`` (n, 3) from b to a; ``fn`` (n,) normal force [N];
    ``ft`` (n, 3) friction force on a [N].
    """

    a: np.ndarray
    b: np.ndarray
    point: np.ndarray
    normal: np.ndarray
    fn: np.ndarray
    ft: np.ndarray


class Engine(abc.ABC):
    """A rigid-body engine holding one model."""

    name: str = "abstract"

    @abc.abstractmethod
    def build(self, model, settings, driven_base: bool = False) -> None:
        """Create the bodies of ``model`` (at their initial poses, at rest) with ``settings``;
        ``driven_base``: the base moves horizontally as prescribed by :meth:`drive_base`
        (otherwise it is fixed)."""

    def drive_base(self, x: float, v: float) -> None:
        """Prescribe the base's horizontal (+x) displacement ``x`` [m] at the end of the next
        step and its nominal velocity ``v`` [m/s] during it (only after ``build(...,
        driven_base=True)``). Engines that move a dynamic base by the velocity landing it on
        ``x`` (both here: it also corrects any drift) need only ``x``."""
        raise NotImplementedError(f"the {self.name} engine cannot drive the base")

    def base_motion(self) -> tuple[float, float]:
        """Actual horizontal displacement [m] and velocity [m/s] of the base (0, 0 if fixed)."""
        return 0.0, 0.0

    @abc.abstractmethod
    def set_gravity(self, vec: np.ndarray) -> None:
        """Gravity (3,) [m/s^2] in the arch frame, from the next step on."""

    @abc.abstractmethod
    def step(self, n: int = 1) -> None:
        """Advance ``n`` time steps of ``settings.dt``."""

    @abc.abstractmethod
    def poses(self) -> tuple[np.ndarray, np.ndarray]:
        """``(pos (n, 3), R (n, 3, 3))`` as described in the module docstring."""

    @abc.abstractmethod
    def velocities(self) -> tuple[np.ndarray, np.ndarray]:
        """``(v (n, 3), w (n, 3))``: centroid velocities [m/s] and angular velocities [rad/s]."""

    def contacts(self) -> Contacts | None:
        """Contact forces at the current instant, or None if the engine does not give them."""
        return None

    def versions(self) -> dict:
        """Engine name and version, for result files."""
        return {"engine": self.name}

    @abc.abstractmethod
    def close(self) -> None:
        """Free the engine's resources; the instance cannot be used afterwards."""

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()
