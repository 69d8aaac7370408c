"""``archdem shake``: one shake-table run (a one-cycle sine pulse or a recorded accelerogram); the
arch and the simulator's options ``threshold`` shares with it.

The library call is :func:`dem.experiments.shake.run.run` with the run spec of a
:class:`~dem.experiments.shake.spec.ShakeOptions`."""
from __future__ import annotations

import argparse
import sys

from dem.common.options import add_options, answer, arch_request, can_make_dir, figure_file, settings_kwargs
from dem.common.options import writable_dir
from dem.core.model import from_assembly
from dem.core.progress import terminal
from dem.core.settings import dynamics_settings
from dem.experiments.contract import add_spec_options, spec_from_args
from dem.experiments.shake.run import run
from dem.experiments.shake.spec import ShakeOptions
from foundation.io import unique_run_path
from specimens.blocks import discretise


def model_and_settings(args: argparse.Namespace):
    """``(label, arch, assembly, model, settings)`` of the options."""
    req = arch_request(args)
    label, arch = req.structure()
    settings = dynamics_settings(**settings_kwargs(args))
    req.require_standing(label, arch)
    asm = discretise(arch, config=args.config, **req.discretise_kwargs(arch))
    return label, arch, asm, from_assembly(asm, name=label), settings


def _run_shake(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.shake.file import save_shake

    opts = spec_from_args(ShakeOptions, args, units=args.units)
    label, _, _, model, settings = model_and_settings(args)
    if args.plot:
        figure_file(args.plot)
    can_make_dir(args.out)
    if say := opts.announcement(settings):
        print(f"archdem: {say}", file=sys.stderr)
    with terminal(f"shake {label}", unit="s simulated", enabled=not args.json) as line:
        res = run(opts.run_spec(model, settings, label), progress=line)
    save_shake(res, unique_run_path(writable_dir(args.out), opts.stem(label, args.config)))
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.shake.figure import save_shake_figure

        save_shake_figure(res, args.plot)
    answer(args.json, res.summary(), [res.text()])
    return 0


def register(sub) -> None:
    p = sub.add_parser("shake", help="virtual shake table: one sine pulse or recorded accelerogram",
                       description="One shake-table run (uniform inertial field on a fixed base, or --load driven-base).")
    add_options(p, "shake", out="runs/shake")
    add_spec_options(p, ShakeOptions)
    p.set_defaults(func=_run_shake)
