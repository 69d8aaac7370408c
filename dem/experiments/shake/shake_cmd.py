"""``archdem shake``: one shake-table run (a one-cycle sine pulse or a recorded accelerogram); the
options ``threshold`` shares with it."""
from __future__ import annotations

import argparse
import math
import sys

from analytic.motions.inputs import MIN_PEAK_ACCELERATION
from analytic.motions.records import MAX_RECORD_BYTES, MAX_RECORD_S, MAX_RECORD_SAMPLES, ground_motion
from dem.common.options import (
    add_arch_arguments,
    add_contact_law_arguments,
    add_dynamics_dt_argument,
    add_engine_argument,
    add_friction_arguments,
    arch_from_args,
    can_make_dir,
    contact_law_settings,
    default_of,
    discretisation_kwargs,
    figure_file,
    print_json,
    require_standing,
    writable_dir,
)
from dem.core.model import from_assembly
from dem.core.progress import terminal
from dem.core.settings import dynamics_settings
from dem.experiments.shake.run import ANNOUNCE_SIMULATED_S, MAX_RUN_S, MAX_SIMULATED_S, ShakeProtocol, shake
from specimens.blocks import discretise
from specimens.constants import G
from foundation.errors import ArchdemInputError
from foundation.io import unique_run_path


def _positive(name: str, v: float | None) -> None:
    if v is not None and not (math.isfinite(v) and v > 0):
        raise ArchdemInputError(f"{name} must be a positive number, got {v}")


def model_and_settings(args: argparse.Namespace):
    """``(label, arch, assembly, model, settings)`` of the options."""
    label, arch = arch_from_args(args)
    if args.id is None and args.Ri is None and args.Sh is None and args.geometry is None:
        raise ArchdemInputError("give a specimen id or the arch parameters")
    _positive("--mu-joint", args.mu_joint)
    _positive("--mu-base", args.mu_base)
    require_standing(label, arch, **discretisation_kwargs(args, arch))
    asm = discretise(arch, config=args.config, **discretisation_kwargs(args, arch))
    kw = {"mu_joint": args.mu_joint, "mu_base": args.mu_base, "planar": args.planar, "engine": args.engine,
          **contact_law_settings(args, args.id)}
    if args.dt is not None:
        _positive("--dt", args.dt)
        kw["dt"] = args.dt
    return label, arch, asm, from_assembly(asm, name=label), dynamics_settings(**kw)


#: Bounds of a sine pulse on the command line: beyond them a run answers nothing physical.
MIN_SINE_HZ, MAX_SINE_HZ = 0.01, 100.0  # a 100 s cycle; at dt 0.5 ms, 20 steps per cycle
MAX_AMPLITUDE_G = 100.0


def check_sine(args: argparse.Namespace) -> None:
    """``--sine`` and ``--amplitude`` within the bounds above."""
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


def _motion(args: argparse.Namespace):
    check_sine(args)
    return ground_motion(sine=args.sine, amplitude=args.amplitude, record=args.record, units=args.units,
                         baseline=args.baseline, scale=args.scale, pga=args.pga)


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
        res = shake(model, motion, settings, proto, label=label, progress=line)
    stem = f"shake-{label}-{args.config}-" + (f"sine{args.sine:g}Hz-{args.amplitude:g}g" if args.sine else "record")
    path = save_shake(res, unique_run_path(writable_dir(args.out), stem))
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.shake.figure import save_shake_figure

        save_shake_figure(res, args.plot)
    s = res.summary()
    if args.json:
        print_json(s)
        return 0
    act = ", ".join(f"{j['joint']}:{j['state']}" for j in s["joints"] if j["state"] != "closed")
    print(f"{label} ({args.config}, mu {settings.mu_joint:g}/{settings.mu_base:g}), PGA {s['pga_g']:.3f} g: "
          + (f"COLLAPSE at t = {res.t_collapse:.3f} s ({res.collapse_phase}; confirmed at "
             f"{s['t_collapse_confirmed']:.3f} s), {res.mode} [{act}]" if res.collapsed else
             f"survival after an excursion to {s['max_displacement_mm']:.1f} mm (criterion at t = "
             f"{res.t_exceed:.3f} s, {s['residual_displacement_mm']:.1f} mm at the end), {res.mode}"
             if res.recovered else f"survival, {res.mode}")
          + f"; crown peak {res.peak_crown_mm:.2f} mm, residual {res.residual_crown_mm:.2f} mm; "
            f"{res.sim.wall_s:.1f} s -> {path}")
    return 0


def add_shake_arguments(p: argparse.ArgumentParser) -> None:
    """The arch, its blocks, friction, engine, joints and the shake protocol's options."""
    add_arch_arguments(p)
    p.add_argument("--config", choices=("glued", "free"), default=default_of(discretise, "config"))
    add_friction_arguments(p)
    p.add_argument("--planar", action="store_true", help="constrain the blocks to the arch plane")
    add_dynamics_dt_argument(p)
    add_engine_argument(p, dynamics=True)
    add_contact_law_arguments(p)
    p.add_argument("--tail", type=float, default=default_of(ShakeProtocol, "tail"),
                   help=f"zero-acceleration tail after the motion [s], up to {MAX_SIMULATED_S:g} "
                        f"(default {default_of(ShakeProtocol, 'tail'):g})")
    p.add_argument("--load", choices=("inertial", "driven-base"), default=default_of(ShakeProtocol, "load"),
                   help="ground motion as a uniform inertial field on a fixed base (inertial) or as a moving base "
                        f"(driven-base); default {default_of(ShakeProtocol, 'load')}")
    p.add_argument("--json", action="store_true", help="print one JSON object")


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
    p.add_argument("--out", default="runs/shake", help="directory for the run file (default runs/shake)")
    p.add_argument("--plot", default=None, help="time-history figure (.png/.pdf/.svg)")
    p.set_defaults(func=_run_shake)
