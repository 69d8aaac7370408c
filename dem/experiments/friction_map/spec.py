"""The options of ``archdem map`` as one frozen spec: each field is an option (its help and default the
library's, :func:`dem.experiments.contract.add_spec_options`), checked once in the spec itself, which
selects the specimens and builds the :class:`~dem.experiments.friction_map.run.MapSpec` the map runs."""
from __future__ import annotations

import inspect
import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

from dem.common.joints import contact_fraction
from dem.core.settings import Settings
from dem.experiments.friction_map.run import MapSpec, catalogue_map, parse_mu_grid
from dem.experiments.tilt import MAP_TILT_TOL
from specimens.catalogue import FULL_SCALE_SPANS, Specimen, full_scale_set, select_specimens
from specimens.constants import REFERENCE_MU_BASE
from foundation.errors import ArchdemInputError

_DEFAULTS = {k: p.default for k, p in inspect.signature(catalogue_map).parameters.items()}


def _opt(default: Any, help: str, **meta: Any) -> Any:
    """A field that is an option: its help, and the ``shown`` default of its help text."""
    return field(default=default, metadata={"help": help, **meta})


@dataclass(frozen=True)
class MapOptions:
    """What ``archdem map`` maps: the ``specimens`` (``all`` or ids, of the catalogue or with
    ``full_scale`` of the full-scale set; none with ``geometry``: a drawing is the one structure), the
    friction grid ``mu`` (text), the bisection rounds ``refine``, each tilt's relative tolerance ``tol``,
    the base friction ``mu_base``. ``given``: the options set by hand (one that does nothing is refused)."""

    specimens: str = _opt("all", "all or comma-separated ids")
    mu: str = _opt(_DEFAULTS["mus"], "joint friction grid START:STOP:STEP or a,b,c",
                   shown=f"{_DEFAULTS['mus']}, {len(parse_mu_grid(_DEFAULTS['mus']))} values")
    refine: int = _opt(_DEFAULTS["refine"], "bisection steps on mu* after the grid")
    tol: float = _opt(MAP_TILT_TOL, "relative lambda tolerance of each tilt")
    full_scale: bool = _opt(False, "use the full-scale parametric set (spans "
                            f"{'/'.join(f'{s:g}' for s in FULL_SCALE_SPANS)} m, {_DEFAULTS['n_voussoirs']} voussoirs "
                            "per side)", shown=None)
    mu_base: float = REFERENCE_MU_BASE
    geometry: bool = False
    given: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        if self.geometry:
            for name in ("specimens", "full_scale"):
                if name in self.given:
                    raise ArchdemInputError(f"--{name.replace('_', '-')} does nothing here: --geometry gives the one "
                                            "structure of the map")
        else:
            self.catalogue  # noqa: B018 (selected, and refused, before the grid)
        self.mus  # noqa: B018 (parsed, and refused, before the frictions' range)
        Settings(mu_base=self.mu_base)  # the simulator's range of frictions
        if "refine" in self.given and not (len(self.mus) > 1 or self.refine == 0):
            raise ArchdemInputError("--refine does nothing here: it bisects mu* between the values of a --mu grid; "
                                    "one value has none")
        if not (0 <= self.refine <= 20):
            raise ArchdemInputError(f"--refine must be in 0..20, got {self.refine}")
        if not (math.isfinite(self.tol) and 1e-3 <= self.tol <= 0.5):
            raise ArchdemInputError(f"--tol must be a relative tolerance in [0.001, 0.5], got {self.tol}")

    @cached_property
    def mus(self) -> list[float]:
        return parse_mu_grid(self.mu)

    @cached_property
    def catalogue(self) -> list:
        """The specimens selected (catalogue or full-scale ones)."""
        if not self.full_scale:
            return select_specimens(self.specimens)
        pool = {s.id: s for s in full_scale_set()}
        if self.specimens.strip() == "all":
            return list(pool.values())
        out = []
        for sid in (s.strip() for s in self.specimens.split(",") if s.strip()):
            if sid not in pool:
                raise ArchdemInputError(f"unknown full-scale specimen {sid!r}; ids look like L10-Sh0.6-Sd0.15 "
                                        f"(spans 5/10/20, Sh 0/0.2/0.6/1, Sd 0.1/0.15/0.2/0.25)")
            out.append(pool[sid])
        if not out:
            raise ArchdemInputError("no specimens selected")
        return out

    def structures(self, req: Any) -> list:
        """The structures mapped: the drawing of ``req`` (a :class:`~dem.common.request.ArchRequest`) or the
        specimens selected, each checked to carry the request's piers."""
        specs = [Specimen(*req.structure())] if self.geometry else self.catalogue
        for s in specs if req.piers is not None else ():
            req.piers.check(s.arch)
        return specs

    def map_spec(self, specimens: list, config: str, engine: str, law: dict, contact: float | str,
                 piers: Any = None) -> MapSpec:
        """The map of ``specimens`` (``config``) on ``engine`` (stored only when not the default) with the
        joints' ``law`` (:class:`Settings` fields), ``contact`` (a fraction or ``"calibrated"``) and ``piers``."""
        settings = ({"engine": engine} if engine != Settings().engine else {}) | law
        return MapSpec(specimens, config, self.mus, self.mu_base, refine=self.refine,
                       protocol={"kind": "hold", "tol": self.tol}, settings=settings or None,
                       contact={s.id: contact_fraction(contact, s.arch) for s in specimens}, piers=piers)
