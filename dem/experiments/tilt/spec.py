"""What ``archdem tilt`` asks for besides the structure and the settings, as one frozen spec checked once:
a tilt's protocol, or an ensemble of imperfect realisations (their number, seed and edge-loss scatter)."""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from dem.common.joints import ensemble_imperfection
from dem.experiments.tilt.run import TiltProtocol
from foundation.errors import ArchdemInputError
from foundation.io import unique_run_path, writable_dir

if TYPE_CHECKING:  # for type checkers (importing ensemble.py loads what `archdem --help` must not)
    from dem.experiments.tilt.ensemble import EnsembleResult


@dataclass(frozen=True)
class TiltOptions:
    """The protocol's ``kind`` (``hold``, ``staircase``, ``ramp``), a hold's ``start`` and ``full_hold``
    (every level held its whole time); or ``ensemble`` realisations of imperfect joints from ``seed``,
    their edge losses' standard deviation ``scatter`` [mm] (None: the calibrated one). ``given``: the
    options set by hand (one that does nothing for the protocol is refused)."""

    protocol: str = TiltProtocol.kind
    start: str = TiltProtocol.start
    full_hold: bool = False
    ensemble: int | None = None
    seed: int | None = None
    scatter: float | None = None
    given: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        if self.ensemble is not None:
            if self.protocol != "hold" or self.start != "auto" or self.full_hold:
                raise ArchdemInputError("an ensemble runs the default hold protocol: drop "
                                        "--protocol/--start/--full-hold")
            if self.seed is None:
                raise ArchdemInputError("--ensemble needs --seed S (every realisation is reproducible from it)")
            return
        if self.seed is not None or self.scatter is not None:
            raise ArchdemInputError("--seed and --scatter go with --ensemble N")
        for name in ("start", "full_hold"):
            if self.protocol != "hold" and name in self.given:
                raise ArchdemInputError(f"--{name.replace('_', '-')} does nothing here: it belongs to --protocol hold")

    def tilt_protocol(self) -> TiltProtocol:
        """The protocol of one tilt."""
        return TiltProtocol(kind=self.protocol, start=self.start, **({"rest_after": None} if self.full_hold else {}))

    def imperfection(self, contact: float | str | None, arch: Any) -> Any:
        """The ensemble's imperfect fit of ``arch``'s joints at ``contact`` (``"calibrated"``: the
        calibrated edge loss) with this scatter (:func:`dem.common.joints.ensemble_imperfection`)."""
        if self.scatter is not None and not (math.isfinite(self.scatter) and 0 <= self.scatter <= 1e3 * arch.t / 2):
            raise ArchdemInputError("--scatter must be between 0 and half the ring thickness [mm], got "
                                    f"{self.scatter:g}")
        return ensemble_imperfection(contact, arch, None if self.scatter is None else self.scatter / 1e3)

    def run_ensemble(self, label: str, arch: Any, contact: float | str | None, out: str | os.PathLike, config: str,
                     n_voussoirs: int | None = None, **kw: Any) -> "EnsembleResult":
        """The ensemble of ``arch`` at ``contact`` (:meth:`imperfection`), stored in a new file in the folder
        ``out``; ``kw``: friction, engine, workers, progress of :func:`dem.experiments.tilt.ensemble.tilt_ensemble`."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.tilt.ensemble import tilt_ensemble

        imp = self.imperfection(contact, arch)
        path = unique_run_path(writable_dir(out), f"ensemble-{label}-{config}-seed{self.seed}")
        return tilt_ensemble(label, arch, imp, self.ensemble, self.seed, path, config=config,
                             **({"n_voussoirs": n_voussoirs} if n_voussoirs is not None else {}), **kw)
