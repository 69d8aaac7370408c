"""The rest state of an arch: its blocks, built in place, left under plain gravity on their base for a
while (docs/architecture.md#the-experiment-contract). How far the blocks move and turn before they settle,
the kinetic energy left at the end, and whether they are at rest by the tilt test's rest rule."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from dem.core.loads import Rest
from dem.core.model import as_model
from dem.core.settings import Settings
from dem.core.simulate import simulate
from dem.experiments.contract import COLUMNS_ARE_FIELDS, Result, Schema
from dem.experiments.tilt import TiltProtocol
from foundation.errors import ArchdemInputError

#: The longest settle [s]: the rest state of a catalogue arch is reached well within 1 s.
MAX_DURATION = 60.0


@dataclass(frozen=True)
class SettleSpec:
    """What to settle: ``target`` a specimen id, Specimen, PointedArch, Assembly or Model
    (:func:`dem.core.model.as_model`, an arch cut in ``config``), the simulator's ``settings`` (the tilt
    test's engine by default), ``duration`` [s] under gravity; ``label`` names it (default the model's name)."""

    target: Any
    config: str = "glued"
    settings: Settings = field(default_factory=Settings)
    duration: float = 1.0
    label: str | None = None

    def __post_init__(self) -> None:
        window = TiltProtocol().rest_window
        if not (isinstance(self.duration, (int, float)) and math.isfinite(self.duration)
                and window < self.duration <= MAX_DURATION):
            raise ArchdemInputError(f"settle duration must be longer than the rest rule's window ({window:g} s) "
                                    f"and at most {MAX_DURATION:g} s, got {self.duration!r}")


@dataclass(frozen=True)
class SettleResult(Result):
    """The rest state of one arch: one table row, its columns the fields (``COLUMNS_ARE_FIELDS``)."""

    SCHEMA: ClassVar[Schema] = COLUMNS_ARE_FIELDS

    id: str
    config: str
    engine: str
    duration_s: float = field(metadata={"unit": "s"})
    max_displacement_mm: float = field(metadata={"unit": "mm"})  # the largest displacement of a block's centre over the run
    max_rotation_mrad: float = field(metadata={"unit": "mrad"})  # the largest rotation of a block over the run
    final_kinetic_energy_J: float = field(metadata={"unit": "J"})
    at_rest: bool  # by the tilt test's rest rule over the run's last window
    collapsed: bool


def run(spec: SettleSpec) -> SettleResult:
    """Leave ``spec``'s blocks under gravity for ``spec.duration`` [s]. At rest: the tilt test's rest rule
    (the largest displacement grew by less than ``rest_growth x size`` over the last ``rest_window``)
    holds at the end of the run, applied by :func:`dem.core.simulate.simulate` itself."""
    model = as_model(spec.target, config=spec.config, name=spec.label)
    proto = TiltProtocol()  # its rule at the catalogue's scale, as the tilt holds a catalogue arch's level
    st = spec.settings
    # the rule checked only at the run's end: the whole duration is simulated
    sim = simulate(model, st, Rest(g=st.g), spec.duration, rest=(spec.duration, proto.rest_window,
                                                                  proto.rest_growth * model.size))
    h = sim.history
    moved = np.linalg.norm(h.pos - h.pos[:1], axis=2)  # (nt, n) [m]
    turned = 2.0 * np.arctan2(np.linalg.norm(h.quat[..., :3], axis=2), np.abs(h.quat[..., 3]))  # (nt, n) [rad]
    return SettleResult(
        id=model.name, config=model.source.get("config", spec.config), engine=st.engine, duration_s=float(spec.duration),
        max_displacement_mm=float(moved.max()) * 1e3, max_rotation_mrad=float(turned.max()) * 1e3,
        final_kinetic_energy_J=float(h.ke[-1]), at_rest=not math.isnan(sim.t_rest), collapsed=bool(sim.collapsed))
