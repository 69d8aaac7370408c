"""A failure domain as ``archdem domain`` asks for it, checked once (:class:`DomainSpec`): the analytic
linkage's (amplitude scan and bisection at each sine frequency or pulse duration) or the DEM arch's over
sine frequencies (``engine`` other than ``analytic``); :func:`run` answers :class:`~dem.experiments.shake.domain.AnalyticDomain`
or :class:`~dem.experiments.shake.domain.DemDomain`, which print themselves."""
from __future__ import annotations

import inspect
import math
from dataclasses import dataclass
from typing import Any

from analytic.rocking.domain import failure_domain
from dem.common.limits import MAX_SINE_HZ, MIN_SINE_HZ
from dem.core.engines import check_engine
from dem.core.progress import terminal
from dem.core.settings import DYNAMICS_ENGINE
from dem.experiments.shake.domain import AnalyticDomain, DemDomain, analytic_domains, dem_failure_domain
from dem.experiments.shake.linkage import LinkageOptions, option, unused
from dem.experiments.shake.step_shake import SHAKE_FREQS
from foundation.errors import ArchdemInputError
from foundation.io import MAX_GRID_POINTS, parse_grid
from specimens.blocks import DEFAULT_DENSITY

# Default grids of ``archdem domain`` (the analytic failure_domain takes its grid from the caller)
SINE_FREQS = "1:20:0.5"  # Hz
PULSE_DURATIONS = "0.05:1:0.05"  # s


def _default(fn: Any, name: str) -> Any:
    return inspect.signature(fn).parameters[name].default


#: The top of the amplitude scan / (lambda g): the analytic linkage's, and the DEM's (the analytic one is too costly there).
A_MAX, DEM_A_MAX = _default(failure_domain, "a_max_ratio"), _default(dem_failure_domain, "a_max_ratio")


@dataclass(frozen=True)
class DomainSpec(LinkageOptions):
    """The failure domain of the linkage (``engine`` ``analytic``) or of the DEM arch (``dem`` or a named
    engine, with ``config``, the frictions, the contact law ``joints``, the step ``dt`` [s], each threshold
    settled or a range if ``check``): sine frequencies ``freq`` [Hz] or pulse durations ``durations`` [s] (grid
    texts), the scan's top ``amax`` (/ lambda g), its ``scan`` amplitudes and the bisection's ``tol``; drawn into
    ``plot`` if given. Checked in one line per refusal, naming the option typed."""

    freq: str | None = option(None, f"frequencies [Hz]: '0.5,1,2' or 'start:stop:step', at most {MAX_GRID_POINTS}",
                              shown=f"{SINE_FREQS}; --engine dem {','.join(f'{f:g}' for f in SHAKE_FREQS)}")
    durations: str | None = option(None, "pulse durations t_i [s]", shown=PULSE_DURATIONS)
    amax: float = option(A_MAX, "top of the amplitude scan / (lambda g)", shown=f"{A_MAX:g}; --engine dem {DEM_A_MAX:g}")
    scan: int = option(_default(failure_domain, "n_scan"), "amplitudes in the scan")
    tol: float = option(_default(failure_domain, "tol"), "relative bisection tolerance")
    engine: str = "analytic"
    config: str = _default(dem_failure_domain, "config")
    mu_joint: float | None = None
    mu_base: float | None = None
    joints: dict | None = None
    dt: float | None = None
    check: bool = True
    workers: int | None = None
    scheduler: str | None = None
    plot: str | None = None

    def __post_init__(self) -> None:
        super().__post_init__()
        if self.engine != "analytic":
            self._check_dem()
            return
        self.energy_restitution  # noqa: B018 (its refusal first, as the command line reads it)
        if self.pulses and self.freq is not None:
            raise ArchdemInputError("pulses A/B take --durations, not --freq")
        if not self.pulses and self.durations is not None:
            raise ArchdemInputError("sine inputs take --freq, not --durations")
        if not (math.isfinite(self.tol) and 1e-4 <= self.tol <= 0.5):
            raise ArchdemInputError(f"--tol must be a relative tolerance in [0.0001, 0.5], got {self.tol}")
        if not (math.isfinite(self.amax) and 1 < self.amax <= 1e3):
            raise ArchdemInputError(f"--amax must be a ratio to the static onset in (1, 1000], got {self.amax:g}")
        if not 2 <= self.scan <= MAX_GRID_POINTS:
            raise ArchdemInputError(f"--scan must be 2 to {MAX_GRID_POINTS} amplitudes, got {self.scan}")
        xs = self.xs
        if not 0.01 <= min(xs) <= max(xs) <= 100:
            raise ArchdemInputError(f"{'--durations [s]' if self.pulses else '--freq [Hz]'} values must be in [0.01, 100]")

    def _check_dem(self) -> None:
        if self.request.block is not None:
            raise ArchdemInputError("--engine dem takes an arch (id or parameters), not --block")
        if self.input not in ("sine", "sine0"):
            raise ArchdemInputError("--engine dem runs one-cycle sines only (--input sine0)")
        if self.durations is not None:
            raise ArchdemInputError("--engine dem takes --freq, not --durations")
        for name in ("model", "layout", "restitution", "scan", "tol"):
            unused(self, name, False, "it belongs to the analytic linkage (--engine analytic)")
        xs = self.xs  # the grid's refusal before the engine's
        if not MIN_SINE_HZ <= min(xs) <= max(xs) <= MAX_SINE_HZ:
            raise ArchdemInputError(f"--freq [Hz] values must be in [{MIN_SINE_HZ:g}, {MAX_SINE_HZ:g}]")
        check_engine(self.physics_engine)

    @property
    def xs(self) -> list[float]:
        """The grid: pulse durations [s] or sine frequencies [Hz] (the DEM's default: the shake step's)."""
        if self.engine != "analytic":
            return parse_grid(self.freq, "--freq") if self.freq is not None else list(SHAKE_FREQS)
        if self.pulses:
            return parse_grid(PULSE_DURATIONS if self.durations is None else self.durations, "--durations")
        return parse_grid(SINE_FREQS if self.freq is None else self.freq, "--freq")

    @property
    def physics_engine(self) -> str:
        """The DEM's engine: ``dem`` is the shakes' (:data:`~dem.core.settings.DYNAMICS_ENGINE`)."""
        return DYNAMICS_ENGINE if self.engine == "dem" else self.engine

    @property
    def dem_a_max(self) -> float:
        """The DEM scan's top / (lambda g): the analytic default means the DEM's own."""
        return DEM_A_MAX if self.amax is None or self.amax == A_MAX else float(self.amax)


def run(spec: DomainSpec, progress: bool = False) -> AnalyticDomain | DemDomain:
    """The failure domain ``spec`` asks for; ``progress``: the DEM's progress line on a terminal."""
    return _dem(spec, progress) if spec.engine != "analytic" else _analytic(spec)


def _analytic(spec: DomainSpec) -> AnalyticDomain:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.impact import post_impact

    label, mech = spec.mechanism()
    rest = spec.energy_restitution
    dom = failure_domain(mech, spec.input, spec.xs, a_max_ratio=spec.amax, n_scan=spec.scan, tol=spec.tol,
                         restitution=rest, workers=spec.workers)
    if spec.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.rocking.figures import plot_domain

        plot_domain(dom, spec.plot, title=f"{label}: {mech.label}, input {spec.input}")
    return AnalyticDomain(label, mech, dom, post_impact(mech, rest).e_applied, spec.plot)


def _dem(spec: DomainSpec, progress: bool) -> DemDomain:
    req = spec.request
    label, arch = req.structure()
    freqs = spec.xs
    with terminal(f"domain {label}", unit="frequencies", enabled=progress) as line:
        res = dem_failure_domain(label, arch, freqs, spec.config, spec.mu_joint, spec.mu_base, a_max_ratio=spec.dem_a_max,
                                 workers=spec.workers, disc_kw=req.discretise_kwargs(arch), scheduler=spec.scheduler,
                                 joints=spec.joints or None, engine=spec.physics_engine, dt=spec.dt, progress=line,
                                 check=spec.check)
    if spec.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.shake.figure import plot_domain_over_analytic

        contact = req.discretise_kwargs(arch).get("contact", 1.0)
        plot_domain_over_analytic(res, analytic_domains(arch, freqs, req.density or DEFAULT_DENSITY, contact=contact,
                                                        piers=req.piers), spec.plot,
                                  title=f"{label}: DEM vs rocking linkages, one-cycle sine")
        res["plot"] = str(spec.plot)
    return DemDomain(label, res)


__all__ = ["DomainSpec", "run", "SINE_FREQS", "PULSE_DURATIONS"]
