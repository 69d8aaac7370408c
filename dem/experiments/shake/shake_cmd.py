"""``archdem shake``: one shake-table run (a one-cycle sine pulse or a recorded accelerogram); the
options ``threshold`` shares with it."""
from __future__ import annotations

import argparse
import math
import sys

from analytic.motions.inputs import MIN_PEAK_ACCELERATION
from analytic.motions.records import MAX_RECORD_BYTES, MAX_RECORD_S, MAX_RECORD_SAMPLES, ground_motion
from dem.common.limits import MAX_AMPLITUDE_G, MAX_SINE_HZ, MIN_SINE_HZ
from dem.common.options import (
    add_options,
    arch_from_args,
    can_make_dir,
    default_of,
    discretisation_kwargs,
    figure_file,
    print_json,
    require_standing,
    settings_kwargs,
    writable_dir,
)
from dem.core.model import from_assembly
from dem.core.progress import terminal
from dem.core.settings import dynamics_settings
from dem.experiments.shake.run import ANNOUNCE_SIMULATED_S, MAX_RUN_S, MAX_SIMULATED_S, ShakeProtocol, ShakeSpec, run
from specimens.blocks import discretise
from specimens.constants import G
from foundation.errors import ArchdemInputError
from foundation.io import unique_run_path


def model_and_settings(args: argparse.Namespace):
    """``(label, arch, assembly, model, settings)`` of the options."""
    label, arch = arch_from_args(args)
    if args.id is None and args.Ri is None and args.Sh is None and args.geometry is None:
        raise ArchdemInputError("give a specimen id or the arch parameters")
    settings = dynamics_settings(**settings_kwargs(args))
    require_standing(label, arch, **discretisation_kwargs(args, arch))
    asm = discretise(arch, config=args.config, **discretisation_kwargs(args, arch))
    return label, arch, asm, from_assembly(asm, name=label), settings


def check_sine(args: argparse.Namespace) -> None:
    """``--sine`` and ``--amplitude`` within the bounds of :mod:`dem.common.limits`."""
    if args.sine is not None and not (math.isfinite(args.sine) and MIN_SINE_HZ <= args.sine <= MAX_SINE_HZ):
        raise ArchdemInputError(f"--sine must be a frequency in [{MIN_SINE_HZ:g}, {MAX_SINE_HZ:g}] Hz, got {args.sine:g}")
    for name in ("amplitude", "a_min", "a_max"):
        a = getattr(args, name, None)
        opt = "--" + name.replace("_", "-")
        if a is not None and not (math.isfinite(a) and 0 < a <= MAX_AMPLITUDE_G):
            raise ArchdemInputError(f"{opt} must be in (0, {MAX_AMPLITUDE_G:g}] g, got {a:g}")
        if a is not None and a * G < MIN_PEAK_ACCELERATION:
            raise ArchdemInputError(f"{opt} {a:g} g is below {MIN_PEAK_ACCELERATION / G:g} g, an accelerometer's "
                                    "resolution: it moves nothing")


def sine_fn(args: argparse.Namespace):
    """The one-cycle sine ``(a [m/s^2], f [Hz]) -> motion`` of the options: the ideal sine, or with
    ``--table-speed`` the motion of a table whose servo cannot exceed that speed
    (:func:`analytic.motions.table.servo_sine`)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from functools import partial

    from analytic.motions.table import servo_sine
    from dem.experiments.shake.thresholds import sine_motion

    v = getattr(args, "table_speed", None)
    if v is None:
        return sine_motion
    if not (math.isfinite(v) and 0 < v <= 100):
        raise ArchdemInputError(f"--table-speed must be a speed in (0, 100] m/s, got {v:g}")
    if getattr(args, "record", None) is not None:
        raise ArchdemInputError("--table-speed applies to a one-cycle sine (--sine), not to a record")
    return partial(servo_sine, v_max=float(v))


def _motion(args: argparse.Namespace):
    check_sine(args)
    m = ground_motion(sine=args.sine, amplitude=args.amplitude, record=args.record, units=args.units,
                      baseline=args.baseline, scale=args.scale, pga=args.pga)
    return m if args.table_speed is None else sine_fn(args)(m.a, m.f)


def _run_shake(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.shake.file import save_shake

    motion = _motion(args)
    label, _, _, model, settings = model_and_settings(args)
    proto = ShakeProtocol(tail=args.tail, duration=args.duration, stop_on_collapse=not args.full, load=args.load,
                          **({"rest_after": None} if args.full else {}))
    if args.plot:
        figure_file(args.plot)
    can_make_dir(args.out)
    total = proto.total_duration(motion)
    if total > ANNOUNCE_SIMULATED_S:
        print(f"archdem: simulating up to {total:g} s of motion and tail ({math.ceil(total / settings.dt)} steps of "
              f"{settings.dt:g} s)" + ("" if args.full else "; stops at collapse, or once at rest after the motion"), file=sys.stderr)
    with terminal(f"shake {label}", unit="s simulated", enabled=not args.json) as line:
        res = run(ShakeSpec(model, motion, settings, proto, label), progress=line)
    stem = f"shake-{label}-{args.config}-" + (f"sine{args.sine:g}Hz-{args.amplitude:g}g" if args.sine else "record")
    save_shake(res, unique_run_path(writable_dir(args.out), stem))
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.shake.figure import save_shake_figure

        save_shake_figure(res, args.plot)
    if args.json:
        print_json(res.summary())
    else:
        print(res.text())
    return 0


def add_shake_arguments(p: argparse.ArgumentParser, command: str = "shake") -> None:
    """The arch, its blocks, friction, engine, joints and the shake protocol's options."""
    add_options(p, command, out="runs/shake")
    p.add_argument("--tail", type=float, default=default_of(ShakeProtocol, "tail"),
                   help=f"zero-acceleration tail after the motion [s], up to {MAX_SIMULATED_S:g} "
                        f"(default {default_of(ShakeProtocol, 'tail'):g})")
    p.add_argument("--load", choices=("inertial", "driven-base"), default=default_of(ShakeProtocol, "load"),
                   help="ground motion as a uniform inertial field on a fixed base (inertial) or as a moving base "
                        f"(driven-base); default {default_of(ShakeProtocol, 'load')}")
    p.add_argument("--table-speed", dest="table_speed", type=float, default=None, metavar="M_PER_S",
                   help="the table's speed limit [m/s] (the laboratory's servo: 1): a sine faster than it runs as "
                        "the motion of a table that cannot follow it (default: the ideal sine)")


def register(sub) -> None:
    p = sub.add_parser("shake", help="virtual shake table: one sine pulse or recorded accelerogram",
                       description="One shake-table run (uniform inertial field on a fixed base, or --load driven-base).")
    add_shake_arguments(p)
    p.add_argument("--sine", type=float, default=None, metavar="FREQ",
                   help=f"one-cycle sine pulse of FREQ [Hz], up to {MAX_SINE_HZ:g}")
    p.add_argument("--amplitude", type=float, default=None, metavar="A_G",
                   help=f"sine amplitude [g], from {MIN_PEAK_ACCELERATION / G:g} up to {MAX_AMPLITUDE_G:g}")
    p.add_argument("--record", default=None, metavar="FILE",
                   help=f"accelerogram (.AT2, .smc, ESM ASCII, CSV), up to {MAX_RECORD_BYTES // 2**20} MB, "
                        f"{MAX_RECORD_SAMPLES} samples and {MAX_RECORD_S:g} s")
    p.add_argument("--scale", type=float, default=None, help="record scale factor")
    p.add_argument("--pga", type=float, default=None, metavar="A_G", help="scale the record to this PGA [g]")
    p.add_argument("--baseline", action="store_true", help="baseline-correct the record (linear velocity fit)")
    p.add_argument("--duration", type=float, default=None,
                   help=f"simulated time [s], up to {MAX_SIMULATED_S:g} (default: motion + tail, up to {MAX_RUN_S:g})")
    p.add_argument("--full", action="store_true",
                   help="simulate the whole duration (default: stop at collapse, or once at rest after the motion)")
    p.set_defaults(func=_run_shake)
