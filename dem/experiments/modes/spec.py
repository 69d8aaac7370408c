"""The natural modes a command asks for: the structure (an arch, on piers or not, or a block), the joints'
stiffness and the modes reported as one frozen spec checked once (its fields are ``archdem modes``'
own options, :func:`dem.experiments.contract.add_spec_options`), and its result, printed and as JSON."""
from __future__ import annotations

import inspect
import math
from dataclasses import dataclass, field
from typing import Any

from analytic.compliant.modes import POISSON, SPRINGS, Modes, ks_over_kn, modes
from dem.core.contact import normal_stiffness
from dem.core.model import from_assembly
from dem.core.model import single_block as block_model
from dem.core.settings import Settings
from specimens.blocks import DEFAULT_DENSITY, discretise
from foundation.errors import ArchdemInputError

#: Most modes a command prints or stores.
MAX_COUNT = 10_000


def _opt(default: Any, help: str, **meta: Any) -> Any:
    """A field that is an option: its help, and argparse's ``choices`` or the ``shown`` default."""
    return field(default=default, metadata={"help": help, **meta})


def modes_structure(req: Any, config: str) -> tuple[str, Any]:
    """``(label, structure)`` of an :class:`~dem.common.request.ArchRequest`: its ``--block`` as one
    block (density [kg/m^3] and depth [m] the request's or the defaults), else its arch's blocks."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.frame import single_block

    block = req.rectangular_block()
    if block is not None:
        b, h = block
        density = DEFAULT_DENSITY if req.density is None else req.density
        return f"block-b{b:g}-h{h:g}", single_block(b, h, density, 0.1 if req.width is None else req.width)
    label, arch = req.structure()
    return label, discretise(arch, config=config, **req.discretise_kwargs(arch))


@dataclass
class ModesRun:
    """The modes of the structure ``label``: ``count`` of them reported, ``plot`` their figure's file."""

    label: str
    structure: Any
    modes: Modes
    count: int
    plot: str | None = None

    def save_figure(self, path: str) -> None:
        """Draw the mode shapes into ``path`` (recorded in the JSON)."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.modes.figure import save_mode_shapes

        save_mode_shapes(self.structure, self.modes, path, title=self.label)
        self.plot = path

    def to_json(self) -> dict:
        return {"id": self.label, **self.modes.describe(self.count)} | ({"plot": self.plot} if self.plot else {})

    def lines(self) -> list[str]:
        res = self.modes
        return [f"{self.label}: {len(res.frequencies_hz)} modes on joints kn {res.kn:.3g} Pa/m, ks {res.ks:.3g} Pa/m "
                f"(springs at the {'contact ends' if res.springs == 'ends' else 'whole contact'})"
                + (f" ({res.unstable} unstable under gravity)" if res.unstable else ""),
                "  " + "  ".join(f"{x:.4g}" for x in res.frequencies_hz[:self.count]) + " Hz"]


@dataclass(frozen=True)
class ModesSpec:
    """The joints' stiffness ``kn``, ``ks`` [Pa/m] given, or from the blocks' Young's modulus ``youngs``
    [Pa] and ``poisson``; where a joint's springs sit; how many modes are reported. ``given``: the
    options set by hand (``poisson`` given where it gives nothing is refused)."""

    poisson: float = _opt(POISSON, "the blocks' Poisson's ratio, for ks = (5/6) G / length with --youngs")
    springs: str = _opt(inspect.signature(modes).parameters["springs"].default,
                        "a joint's springs at its contact's two ends, as the DEM's corner contacts (default), or "
                        "spread over it", choices=tuple(SPRINGS), shown=None)
    count: int = _opt(80, "modes printed")
    kn: float | None = None
    ks: float | None = None
    youngs: float | None = None
    given: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        if not (isinstance(self.count, int) and 1 <= self.count <= MAX_COUNT):
            raise ArchdemInputError(f"--count must be a whole number from 1 to {MAX_COUNT}, got {self.count!r}")

    def stiffness(self, structure: Any) -> tuple[float, float | None]:
        """``(kn, ks)`` given, or from ``youngs`` and ``poisson`` over the blocks' length (dem.core.contact)."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from specimens.frame import Block

        if (self.kn is None) == (self.youngs is None):
            raise ArchdemInputError("give the joints' stiffness as --kn PA_PER_M or as --youngs E_PA")
        if "poisson" in self.given and not (self.kn is None and self.ks is None):
            raise ArchdemInputError("--poisson does nothing here: it gives k_s from --youngs, without --ks")
        if self.kn is not None:
            return self.kn, self.ks
        if not (math.isfinite(self.youngs) and self.youngs > 0):
            raise ArchdemInputError(f"--youngs must be a positive modulus [Pa], got {self.youngs}")
        if not (math.isfinite(self.poisson) and 0.0 <= self.poisson < 0.5):
            raise ArchdemInputError(f"--poisson must be in [0, 0.5), got {self.poisson}")
        model = (block_model(2 * structure.b, 2 * structure.h, structure.width) if isinstance(structure, Block)
                 else from_assembly(structure))
        kn = normal_stiffness(Settings(contact_law="compliant", youngs=self.youngs), model)
        return kn, (ks_over_kn(self.poisson) * kn if self.ks is None else self.ks)

    def run(self, label: str, structure: Any) -> ModesRun:
        """The natural modes of ``structure`` (named ``label``) on these joints."""
        kn, ks = self.stiffness(structure)
        return ModesRun(label, structure, modes(structure, kn, ks, springs=self.springs), self.count)
