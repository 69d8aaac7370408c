"""What a fragility study is built from, checked (:class:`~dem.experiments.fragility.run.FragilitySpec`'s
parts): the nominal structure with its case entry, the engine's settings, each realisation's perturbation
from lengths in millimetres, the groups of stripes (sine pulses or a suite of records scaled to an
intensity measure) and the nominal structure's deterministic thresholds beside the sines'."""
from __future__ import annotations

import functools
import math
import os
from typing import Any, Callable

from dem.common.limits import MAX_AMPLITUDE_G, MAX_SINE_HZ, MIN_SINE_HZ
from dem.common.request import ArchRequest
from dem.core.model import from_assembly, single_block
from dem.core.progress import terminal
from dem.core.settings import Settings, dynamics_settings
from dem.experiments.fragility.run import (
    DEFAULT_EDGE_LOSS_SD,
    DEFAULT_SIZE_SD,
    Perturbation,
    arch_structure,
    block_structure,
    drawing_structure,
    prepared_record,
    record_spec,
    sine_spec,
)
from dem.experiments.shake import ShakeProtocol, threshold
from foundation.errors import ArchdemInputError
from foundation.io import parse_grid
from specimens.blocks import DEFAULT_DENSITY, discretise
from specimens.constants import G

#: The width [m] of a rectangular block given without one.
BLOCK_WIDTH = 0.1


def block_nominal(b: float, h: float, width: float | None = None, density: float | None = None) -> tuple[dict, Any]:
    """``(structure entry, nominal model)`` of a block ``b`` x ``h`` [m], ``width`` [m] deep (default
    :data:`BLOCK_WIDTH`), of ``density`` [kg/m^3] (default the blocks')."""
    width = BLOCK_WIDTH if width is None else width
    density = DEFAULT_DENSITY if density is None else density
    model = single_block(b, h, width, density)  # checks the sizes
    return block_structure(b, h, width, density), model


def arch_nominal(label: str, arch, config: str, disc_kw: dict) -> tuple[dict, Any]:
    """``(structure entry, nominal model)`` of an arch cut as ``archdem shake`` cuts it (``disc_kw``:
    :func:`specimens.blocks.discretise` keywords), or of a drawing (its blocks as drawn)."""
    asm = discretise(arch, config=config, **disc_kw)
    if asm.arch is None:  # a drawing (--geometry): its joints' edge loss is the perturbation's, not --contact
        if asm.contact != 1.0:
            raise ArchdemInputError("a drawing's fragility takes its joints' contact from --edge-loss, not --contact")
        return drawing_structure(asm), from_assembly(asm, name=label)
    return arch_structure(arch, config, disc_kw.get("n_voussoirs"), asm.contact, disc_kw.get("piers"),
                          disc_kw.get("density")), from_assembly(asm, name=label)


def nominal(req: ArchRequest, config: str, width: float | None = None,
            density: float | None = None) -> tuple[str, dict, Any]:
    """``(label, structure entry, nominal model)`` of ``req``: a block of ``width`` [m] and ``density``
    [kg/m^3] (:func:`block_nominal`), or an arch that stands, cut in ``config`` (:func:`arch_nominal`)."""
    block = req.rectangular_block()
    if block is not None:
        b, h = block
        return (f"block-b{b:g}-h{h:g}", *block_nominal(2 * b, 2 * h, width, density))
    label, arch = req.structure()
    kw = req.discretise_kwargs(arch)
    req.require_standing(label, arch)
    return (label, *arch_nominal(label, arch, config, kw))


def study_settings(settings: dict, solver_iterations: int | None = None) -> dict:
    """The engine's settings as the study file holds them (checked), with the step ``dt`` [s] they give."""
    s = dict(settings)
    if solver_iterations is not None:
        s["engine_options"] = {"solver_iterations": solver_iterations}
    s["dt"] = dynamics_settings(**s).dt  # checks them; the step written into the study
    return s


def perturbation_mm(kind: str, edge_loss: float | None, edge_loss_sd: float | None, size_sd: float | None,
                    friction_cov: float) -> Perturbation:
    """The realisations' :class:`Perturbation` of a structure of ``kind`` from lengths in mm (None: the
    default): joint edge loss (mean, scatter) for an arch or a drawing, dimension scatter for a block."""
    block = kind == "block"
    if block and (edge_loss is not None or edge_loss_sd is not None):
        raise ArchdemInputError("--edge-loss and --edge-loss-sd perturb an arch's joints; a block takes --size-sd")
    if not block and size_sd is not None:
        raise ArchdemInputError("--size-sd perturbs a block; an arch's joints take --edge-loss-sd")
    for name, v in (("edge_loss", edge_loss), ("edge_loss_sd", edge_loss_sd), ("size_sd", size_sd)):
        if v is not None and not (math.isfinite(v) and 0 <= v <= 100):
            raise ArchdemInputError(f"--{name.replace('_', '-')} must be a length from 0 to 100 mm, got {v:g}")
    return Perturbation((edge_loss or 0.0) * 1e-3,
                        0.0 if block else (DEFAULT_EDGE_LOSS_SD if edge_loss_sd is None else edge_loss_sd * 1e-3),
                        (DEFAULT_SIZE_SD if size_sd is None else size_sd * 1e-3) if block else 0.0,
                        friction_cov)


def stripe_grid(text: str, what: str, lo: float, hi: float, unit: str) -> list[float]:
    """The sorted values of the grid ``text`` (option ``what``), each in (``lo``, ``hi``] ``unit``, none twice."""
    vals = [float(f"{v:.12g}") for v in parse_grid(text, what)]  # 0.345, not 0.34500000000000003
    if not all(math.isfinite(v) and lo < v <= hi for v in vals):
        raise ArchdemInputError(f"{what} values must be in ({lo:g}, {hi:g}] {unit}, got {text!r}")
    if len(set(vals)) != len(vals):
        raise ArchdemInputError(f"{what} repeats a value: {text!r}")
    return sorted(vals)


def motion_groups(sine: str | None = None, amplitudes: str | None = None, records: list[str] | None = None,
                  im: str | None = None, stripes: str | None = None) -> tuple[list, dict]:
    """The study's groups ``(name, unit, [(intensity, motion spec), ...])`` and what they are: one per
    frequency of ``sine`` [Hz] at ``amplitudes`` [g], or one suite of ``records`` scaled to the
    intensities ``stripes`` of the measure ``im`` (``pga``, ``pgv``, ``sa:T``; g, m/s for pgv)."""
    if (sine is None) == (records is None):
        raise ArchdemInputError("give --sine F[,F...] with --amplitudes, or --records FILE... with --im and --stripes")
    if sine is not None:
        if amplitudes is None or im is not None or stripes is not None:
            raise ArchdemInputError("--sine goes with --amplitudes (in g); --im and --stripes belong to --records")
        freqs = stripe_grid(sine, "--sine", MIN_SINE_HZ - 1e-12, MAX_SINE_HZ, "Hz")
        amps = stripe_grid(amplitudes, "--amplitudes", 0.0, MAX_AMPLITUDE_G, "g")
        return [(f"{f:g} Hz", "g", [(a, sine_spec(f, a)) for a in amps]) for f in freqs], {"input": "sine", "freqs": freqs}
    if stripes is None or im is None or amplitudes is not None:
        raise ArchdemInputError("--records goes with --im pga|pgv|sa:T and --stripes; --amplitudes belongs to --sine")
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.motions.matching import intensity_measure, parse_im

    measure = parse_im(im)
    unit, factor = ("m/s", 1.0) if measure[0] == "pgv" else ("g", G)
    xs = stripe_grid(stripes, "--stripes", 0.0, 20.0 if unit == "m/s" else 10.0, unit)
    items = []
    for path in records:
        motion, window = prepared_record(path)
        v = intensity_measure(motion, measure)
        if not v > 0:
            raise ArchdemInputError(f"{os.path.basename(path)}: its {im} is zero")
        items += [(x, record_spec(path, x * factor / v, window)) for x in xs]
    # one suite: a stripe holds every record (x realisations) at that intensity
    return [(f"records {im}", unit, items)], {"input": "records", "im": im,
                                              "records": [os.path.basename(p) for p in records]}


def deterministic_thresholds(model, settings: dict, groups: list, freqs: list[float], workers: int | None = None,
                             scheduler: str | None = None, progress: bool = True) -> dict[str, Callable[[], float]]:
    """Per sine group (frequency ``freqs`` [Hz]), the function that finds the nominal ``model``'s least
    collapsing amplitude [g] (``archdem threshold``), searched from half the group's lowest amplitude to
    twice its highest; the study calls it once its file exists."""
    def run(f: float, amps: list[float]) -> float:
        with terminal(f"deterministic threshold {f:g} Hz", unit="runs", enabled=progress) as line:
            return threshold(model, f, Settings(**settings), ShakeProtocol(), a_min_g=0.5 * amps[0],
                             a_max_g=2.0 * amps[-1], workers=workers, scheduler=scheduler, progress=line).amplitude_g

    return {name: functools.partial(run, f, [a for a, _ in items]) for (name, _, items), f in zip(groups, freqs)}


__all__ = ["BLOCK_WIDTH", "block_nominal", "arch_nominal", "nominal", "study_settings", "perturbation_mm", "stripe_grid",
           "motion_groups", "deterministic_thresholds"]
