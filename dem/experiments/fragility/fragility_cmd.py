"""``archdem fragility``: collapse probability and lognormal fragility curves from ensembles of
perturbed realisations, under sine pulses or a suite of records (docs/physics/fragility.md)."""
from __future__ import annotations

import argparse
import functools
import math
import os

from dem.common.limits import MAX_AMPLITUDE_G, MAX_SINE_HZ, MIN_SINE_HZ
from dem.common.options import (
    add_options,
    arch_from_args,
    block_from_args,
    discretisation_kwargs,
    figure_file,
    option_used,
    parse_grid,
    print_json,
    require_standing,
    settings_kwargs,
    study_definition,
    study_path,
    study_stopped,
)
from dem.core.model import from_assembly, single_block
from dem.core.progress import terminal
from dem.core.settings import Settings, dynamics_settings
from dem.experiments.fragility.run import (
    DEFAULT_EDGE_LOSS_SD,
    DEFAULT_FRICTION_COV,
    DEFAULT_SIZE_SD,
    FragilitySpec,
    Perturbation,
    arch_structure,
    block_structure,
    drawing_structure,
    make_cases,
    prepared_record,
    record_spec,
    sine_spec,
)
from dem.experiments.fragility.run import run as run_fragility
from dem.experiments.shake import ShakeProtocol, threshold
from specimens.blocks import DEFAULT_DENSITY, discretise
from specimens.constants import G
from foundation.errors import ArchdemInputError


def _structure(args: argparse.Namespace):
    """``(label, structure entry, nominal model)``: an arch as ``archdem shake`` cuts it, or a block."""
    block = block_from_args(args)
    if block is not None:
        b, h = block
        width = args.width if args.width is not None else 0.1
        density = args.density if args.density is not None else DEFAULT_DENSITY
        model = single_block(2 * b, 2 * h, width, density)  # checks the sizes
        return f"block-b{b:g}-h{h:g}", block_structure(2 * b, 2 * h, width, density), model
    label, arch = arch_from_args(args)
    kw = discretisation_kwargs(args, arch)
    require_standing(label, arch, **kw)
    asm = discretise(arch, config=args.config, **kw)
    if asm.arch is None:  # a drawing (--geometry): its joints' edge loss is the perturbation's, not --contact
        if asm.contact != 1.0:
            raise ArchdemInputError("a drawing's fragility takes its joints' contact from --edge-loss, not --contact")
        return label, drawing_structure(asm), from_assembly(asm, name=label)
    return label, arch_structure(arch, args.config, kw.get("n_voussoirs"), asm.contact, kw.get("piers"),
                                 kw.get("density")), from_assembly(asm, name=label)


def _settings(args: argparse.Namespace) -> dict:
    s = settings_kwargs(args)
    if args.solver_iterations is not None:
        s["engine_options"] = {"solver_iterations": args.solver_iterations}
    s["dt"] = dynamics_settings(**s).dt  # checks them; the step written into the study
    return s


def _grid(text: str, what: str, lo: float, hi: float, unit: str) -> list[float]:
    vals = [float(f"{v:.12g}") for v in parse_grid(text, what)]  # 0.345, not 0.34500000000000003
    if not all(math.isfinite(v) and lo < v <= hi for v in vals):
        raise ArchdemInputError(f"{what} values must be in ({lo:g}, {hi:g}] {unit}, got {text!r}")
    if len(set(vals)) != len(vals):
        raise ArchdemInputError(f"{what} repeats a value: {text!r}")
    return sorted(vals)


def _groups(args: argparse.Namespace) -> tuple[list, dict]:
    """The study's groups ``(name, unit, [(intensity, motion spec), ...])`` and what they are."""
    if (args.sine is None) == (args.records is None):
        raise ArchdemInputError("give --sine F[,F...] with --amplitudes, or --records FILE... with --im and --stripes")
    if args.sine is not None:
        if args.amplitudes is None or args.im is not None or args.stripes is not None:
            raise ArchdemInputError("--sine goes with --amplitudes (in g); --im and --stripes belong to --records")
        freqs = _grid(args.sine, "--sine", MIN_SINE_HZ - 1e-12, MAX_SINE_HZ, "Hz")
        amps = _grid(args.amplitudes, "--amplitudes", 0.0, MAX_AMPLITUDE_G, "g")
        return [(f"{f:g} Hz", "g", [(a, sine_spec(f, a)) for a in amps]) for f in freqs], {"input": "sine", "freqs": freqs}
    if args.stripes is None or args.im is None or args.amplitudes is not None:
        raise ArchdemInputError("--records goes with --im pga|pgv|sa:T and --stripes; --amplitudes belongs to --sine")
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.motions.matching import intensity_measure, parse_im

    im = parse_im(args.im)
    unit, factor = ("m/s", 1.0) if im[0] == "pgv" else ("g", G)
    xs = _grid(args.stripes, "--stripes", 0.0, 20.0 if unit == "m/s" else 10.0, unit)
    items = []
    for path in args.records:
        motion, window = prepared_record(path)
        v = intensity_measure(motion, im)
        if not v > 0:
            raise ArchdemInputError(f"{os.path.basename(path)}: its {args.im} is zero")
        items += [(x, record_spec(path, x * factor / v, window)) for x in xs]
    # one suite: a stripe holds every record (x realisations) at that intensity
    return [(f"records {args.im}", unit, items)], {"input": "records", "im": args.im,
                                                    "records": [os.path.basename(p) for p in args.records]}


def _deterministic(args, model, settings: dict, groups: list, info: dict) -> dict:
    """Per frequency, the least collapsing amplitude of the nominal structure (``archdem threshold``):
    checked now; per group the function that runs it (the study runs it once its file exists)."""
    option_used(args, "no_deterministic", info["input"] == "sine", "the deterministic thresholds are the sines'")
    if info["input"] != "sine" or args.no_deterministic:
        return {}

    def run(f: float, amps: list[float]) -> float:
        with terminal(f"deterministic threshold {f:g} Hz", unit="runs", enabled=not args.json) as line:
            return threshold(model, f, Settings(**settings), ShakeProtocol(), a_min_g=0.5 * amps[0],
                             a_max_g=2.0 * amps[-1], workers=args.workers, scheduler=args.scheduler,
                             progress=line).amplitude_g

    return {name: functools.partial(run, f, [a for a, _ in items])
            for (name, _, items), f in zip(groups, info["freqs"])}


def _perturbation(args: argparse.Namespace, structure: dict):
    """The realisations' perturbations: joint edge loss for an arch, dimensions for a block, friction."""
    block = structure["kind"] == "block"
    if block and (args.edge_loss is not None or args.edge_loss_sd is not None):
        raise ArchdemInputError("--edge-loss and --edge-loss-sd perturb an arch's joints; a block takes --size-sd")
    if not block and args.size_sd is not None:
        raise ArchdemInputError("--size-sd perturbs a block; an arch's joints take --edge-loss-sd")
    for name in ("edge_loss", "edge_loss_sd", "size_sd"):
        v = getattr(args, name)
        if v is not None and not (math.isfinite(v) and 0 <= v <= 100):
            raise ArchdemInputError(f"--{name.replace('_', '-')} must be a length from 0 to 100 mm, got {v:g}")
    return Perturbation((args.edge_loss or 0.0) * 1e-3,
                        0.0 if block else (DEFAULT_EDGE_LOSS_SD if args.edge_loss_sd is None else args.edge_loss_sd * 1e-3),
                        (DEFAULT_SIZE_SD if args.size_sd is None else args.size_sd * 1e-3) if block else 0.0,
                        args.friction_cov)


def _run(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import StudyInterrupted, check_scheduler
    if args.realizations is None:
        raise ArchdemInputError("give --realizations N (perturbed realisations per stripe)")
    label, structure, model = _structure(args)
    settings = _settings(args)
    pert = _perturbation(args, structure)
    groups, info = _groups(args)
    make_cases(label, structure, settings, pert, groups, args.realizations, args.seed)  # checks n and the seed
    path, resume = study_path(args, "runs/fragility", f"fragility-{label}-s{args.seed}")
    if args.plot:
        figure_file(args.plot)
    if args.scheduler:
        check_scheduler(args.scheduler)  # before the deterministic runs and the study file
    deterministic = _deterministic(args, model, settings, groups, info)
    spec = FragilitySpec(label, structure, settings, pert, groups, args.realizations, args.seed, path,
                         workers=args.workers, scheduler=args.scheduler, resume=resume, progress=not args.json,
                         deterministic=deterministic, definition=study_definition(args))
    try:
        res = run_fragility(spec)
    except (StudyInterrupted, KeyboardInterrupt) as exc:
        return study_stopped(path, exc)
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.fragility.file import write_tables

    csv_path = write_tables(res, path)
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.fragility.figure import save_fragility_figure

        save_fragility_figure(res, args.plot)
    out = {**res.summary(), **info, "perturbation": pert.describe(), "settings": settings, "csv": str(csv_path)}
    if args.json:
        print_json(out)
        return 0
    print("\n".join(res.lines(args.realizations)))
    return 0


def register(sub) -> None:
    p = sub.add_parser("fragility", help="collapse probability and lognormal fragility from ensembles of perturbed "
                                         "realisations (sine pulses or a suite of records)",
                       description=__doc__.splitlines()[0])
    add_options(p, "fragility")
    p.add_argument("--sine", default=None, metavar="F[,F...]", help="one-cycle sine pulses of these frequencies [Hz]")
    p.add_argument("--amplitudes", default=None, metavar="GRID", help="sine amplitudes [g]: START:STOP:STEP or a,b,c")
    p.add_argument("--records", nargs="+", default=None, metavar="FILE", help="a suite of records (.AT2, .smc, ESM, CSV)")
    p.add_argument("--im", default=None, metavar="pga|pgv|sa:T", help="intensity measure of the records' stripes")
    p.add_argument("--stripes", default=None, metavar="GRID", help="intensities of the stripes (g; m/s for pgv)")
    p.add_argument("--realizations", "--realisations", dest="realizations", type=int, default=None,
                   help="perturbed realisations per stripe (needed; a resume takes the study's)")
    p.add_argument("--seed", type=int, default=0, help="seed of the realisations (default 0)")
    p.add_argument("--edge-loss", type=float, default=None, help="mean edge loss of every joint [mm] (arch; default 0)")
    p.add_argument("--edge-loss-sd", type=float, default=None,
                   help=f"scatter of the joints' edge loss [mm] (arch; default {DEFAULT_EDGE_LOSS_SD * 1e3:g})")
    p.add_argument("--size-sd", type=float, default=None,
                   help=f"scatter of a block's base and height [mm] (block; default {DEFAULT_SIZE_SD * 1e3:g})")
    p.add_argument("--friction-cov", type=float, default=DEFAULT_FRICTION_COV,
                   help=f"coefficient of variation of the friction coefficients (default {DEFAULT_FRICTION_COV:g})")
    p.add_argument("--no-deterministic", action="store_true",
                   help="skip the nominal structure's threshold beside each sine curve")
    p.set_defaults(func=_run)
