"""``archdem shake`` (one shake-table run), ``archdem threshold`` (least collapsing sine
amplitude and survival bands) and ``archdem animate`` (animation of a run file)."""
from __future__ import annotations

import argparse
import math
import sys

from dem.cli.common import (
    add_arch_arguments,
    add_contact_law_arguments,
    add_engine_argument,
    add_friction_arguments,
    arch_from_args,
    can_make_dir,
    contact_law_settings,
    default_of,
    discretisation_kwargs,
    figure_file,
    print_json,
    workers_option,
    writable_dir,
)
from specimens.errors import ArchdemInputError


def _positive(name: str, v: float | None) -> None:
    if v is not None and not (math.isfinite(v) and v > 0):
        raise ArchdemInputError(f"{name} must be a positive number, got {v}")


def _model_and_settings(args: argparse.Namespace):
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from specimens.blocks import discretise

    label, arch = arch_from_args(args)
    if args.id is None and args.Ri is None and args.Sh is None and args.geometry is None:
        raise ArchdemInputError("give a specimen id or the arch parameters")
    _positive("--mu-joint", args.mu_joint)
    _positive("--mu-base", args.mu_base)
    asm = discretise(arch, config=args.config, **discretisation_kwargs(args, arch))
    kw = {"mu_joint": args.mu_joint, "mu_base": args.mu_base, "planar": args.planar, "engine": args.engine,
          **contact_law_settings(args, args.id)}
    if args.dt is not None:
        _positive("--dt", args.dt)
        kw["dt"] = args.dt
    return label, arch, asm, from_assembly(asm, name=label), Settings(**kw)


#: Bounds of a sine pulse on the command line: beyond them a run answers nothing physical.
MIN_SINE_HZ, MAX_SINE_HZ = 0.01, 100.0  # a 100 s cycle; at dt 0.5 ms, 20 steps per cycle
MAX_AMPLITUDE_G = 100.0


def _sine(args: argparse.Namespace) -> None:
    if args.sine is not None and not (math.isfinite(args.sine) and MIN_SINE_HZ <= args.sine <= MAX_SINE_HZ):
        raise ArchdemInputError(f"--sine must be a frequency in [{MIN_SINE_HZ:g}, {MAX_SINE_HZ:g}] Hz, got {args.sine:g}")
    a = getattr(args, "amplitude", None)
    if a is not None and not (math.isfinite(a) and 0 < a <= MAX_AMPLITUDE_G):
        raise ArchdemInputError(f"--amplitude must be in (0, {MAX_AMPLITUDE_G:g}] g, got {a:g}")


def _motion(args: argparse.Namespace):
    from analytic.records import ground_motion

    _sine(args)
    return ground_motion(sine=args.sine, amplitude=args.amplitude, record=args.record, units=args.units,
                         baseline=args.baseline, scale=args.scale, pga=args.pga)


def _run_shake(args: argparse.Namespace) -> int:
    from dem.experiments.shake import ANNOUNCE_SIMULATED_S, ShakeProtocol, shake
    from dem.formats.shake import save_shake
    from specimens.io import unique_run_path

    motion = _motion(args)
    label, _, _, model, settings = _model_and_settings(args)
    proto = ShakeProtocol(tail=args.tail, duration=args.duration, stop_on_collapse=not args.full, load=args.load,
                          **({"rest_after": None} if args.full else {}))
    if args.plot:
        figure_file(args.plot)
    can_make_dir(args.out)
    total = proto.total_duration(motion)
    if total > ANNOUNCE_SIMULATED_S:
        print(f"archdem: simulating up to {total:g} s of motion and tail ({math.ceil(total / settings.dt)} steps of "
              f"{settings.dt:g} s)" + ("" if args.full else "; stops at collapse, or once at rest after the motion"), file=sys.stderr)
    res = shake(model, motion, settings, proto, label=label)
    stem = f"shake-{label}-{args.config}-" + (f"sine{args.sine:g}Hz-{args.amplitude:g}g" if args.sine else "record")
    path = save_shake(res, unique_run_path(writable_dir(args.out), stem))
    if args.plot:
        from dem.plotting.shake import save_shake_figure

        save_shake_figure(res, args.plot)
    s = res.summary()
    if args.json:
        print_json(s)
        return 0
    act = ", ".join(f"{j['joint']}:{j['state']}" for j in s["joints"] if j["state"] != "closed")
    print(f"{label} ({args.config}, mu {settings.mu_joint:g}/{settings.mu_base:g}), PGA {s['pga_g']:.3f} g: "
          + (f"COLLAPSE at t = {res.t_collapse:.3f} s ({res.collapse_phase}), {res.mode} [{act}]"
             if res.collapsed else f"survival, {res.mode}")
          + f"; crown peak {res.peak_crown_mm:.2f} mm, residual {res.residual_crown_mm:.2f} mm; "
            f"{res.sim.wall_s:.1f} s -> {path}")
    return 0


def _run_threshold(args: argparse.Namespace) -> int:
    from dem.experiments.shake import ShakeProtocol
    from dem.experiments.thresholds import static_onset, threshold

    _sine(args)
    label, arch, _, model, settings = _model_and_settings(args)
    lam = static_onset(model, settings)
    for name, v in (("--a-min", args.a_min), ("--a-max", args.a_max)):
        if v is not None and not (math.isfinite(v) and 0 < v <= MAX_AMPLITUDE_G):
            raise ArchdemInputError(f"{name} must be in (0, {MAX_AMPLITUDE_G:g}] g, got {v:g}")
    if not (math.isfinite(args.scan_ratio) and 1 < args.scan_ratio <= 10):
        raise ArchdemInputError(f"--scan-ratio must be in (1, 10], got {args.scan_ratio:g}")
    if not (math.isfinite(args.tol) and 1e-3 <= args.tol <= 0.5):
        raise ArchdemInputError(f"--tol must be a relative tolerance in [0.001, 0.5], got {args.tol}")
    res = threshold(model, args.sine, settings, ShakeProtocol(tail=args.tail, load=args.load), a_min_g=args.a_min,
                    a_max_g=args.a_max, scan_ratio=args.scan_ratio, tol=args.tol, workers=args.workers,
                    scheduler=args.scheduler)
    a_max = res.a_range_g[1]
    s = {"id": label, "lambda": lam, "config": args.config, "contact": model.source.get("contact", 1.0),
         "mu_joint": settings.mu_joint, "mu_base": settings.mu_base, **res.summary()}
    if args.json:
        print_json(s)
        return 0
    if res.amplitude_g is None:
        print(f"{label} {args.sine:g} Hz: no collapse up to {a_max:.3f} g ({res.n_sims} runs, {res.wall_s:.1f} s)")
        return 0
    above = ", ".join(f"{b['from_g']:.3f}-{b['to_g']:.3f} g" for b in res.survival_bands_above)
    print(f"{label} {args.sine:g} Hz: least collapsing amplitude {res.amplitude_g:.4f} g "
          f"(bracket {res.bracket_g[0]:.4f}-{res.bracket_g[1]:.4f}, {res.mode}, {res.phase}); static lambda {lam:.4f}"
          + (f"; survives again {above}" if above else "") + f"; {res.n_sims} runs, {res.wall_s:.1f} s")
    return 0


def _run_animate(args: argparse.Namespace) -> int:
    from dem.plotting.animate import animate

    out = animate(args.run, args.out, fps=args.fps, max_frames=args.frames)
    print(out)
    return 0


def _common(p: argparse.ArgumentParser) -> None:
    from dem.core.settings import Settings
    from dem.experiments.shake import MAX_SIMULATED_S, ShakeProtocol
    from specimens.blocks import discretise

    add_arch_arguments(p)
    p.add_argument("--config", choices=("glued", "free"), default=default_of(discretise, "config"))
    add_friction_arguments(p)
    p.add_argument("--planar", action="store_true", help="constrain the blocks to the arch plane")
    p.add_argument("--dt", type=float, default=None, help=f"time step [s] (default {default_of(Settings, 'dt'):g})")
    add_engine_argument(p)
    add_contact_law_arguments(p)
    p.add_argument("--tail", type=float, default=default_of(ShakeProtocol, "tail"),
                   help=f"zero-acceleration tail after the motion [s], up to {MAX_SIMULATED_S:g} "
                        f"(default {default_of(ShakeProtocol, 'tail'):g})")
    p.add_argument("--load", choices=("inertial", "driven-base"), default=default_of(ShakeProtocol, "load"),
                   help="ground motion as a uniform inertial field on a fixed base (inertial) or as a moving base "
                        f"(driven-base); default {default_of(ShakeProtocol, 'load')}")
    p.add_argument("--json", action="store_true", help="print one JSON object")


def register(sub) -> None:
    from dem.experiments.thresholds import SCAN_TOP, threshold
    from dem.plotting.animate import animate

    p = sub.add_parser("shake", help="virtual shake table: one sine pulse or recorded accelerogram",
                       description="One shake-table run (uniform inertial field on a fixed base, or --load driven-base).")
    _common(p)
    p.add_argument("--sine", type=float, default=None, metavar="FREQ",
                   help=f"one-cycle sine pulse of FREQ [Hz], up to {MAX_SINE_HZ:g}")
    p.add_argument("--amplitude", type=float, default=None, metavar="A_G", help=f"sine amplitude [g], up to {MAX_AMPLITUDE_G:g}")
    p.add_argument("--record", default=None, metavar="FILE", help="accelerogram (.AT2, .smc, ESM ASCII, CSV)")
    p.add_argument("--scale", type=float, default=None, help="record scale factor")
    p.add_argument("--pga", type=float, default=None, metavar="A_G", help="scale the record to this PGA [g]")
    p.add_argument("--baseline", action="store_true", help="baseline-correct the record (linear velocity fit)")
    p.add_argument("--duration", type=float, default=None, help="simulated time [s] (default: motion + tail)")
    p.add_argument("--full", action="store_true",
                   help="simulate the whole duration (default: stop at collapse, or once at rest after the motion)")
    p.add_argument("--out", default="runs/shake", help="directory for the run file (default runs/shake)")
    p.add_argument("--plot", default=None, help="time-history figure (.png/.pdf/.svg)")
    p.set_defaults(func=_run_shake)

    q = sub.add_parser("threshold", help="least collapsing one-cycle sine amplitude (scan + bisection)",
                       description="Least collapsing amplitude of a one-cycle sine: amplitude scan, bisection of "
                                   "the lowest collapsing bracket, and every survival band above it.")
    _common(q)
    q.add_argument("--sine", type=float, required=True, metavar="FREQ", help=f"sine frequency [Hz], up to {MAX_SINE_HZ:g}")
    q.add_argument("--a-min", dest="a_min", type=float, default=None, help="scan start [g] (default: static lambda)")
    q.add_argument("--a-max", dest="a_max", type=float, default=None, help=f"scan end [g] (default {SCAN_TOP:g} x start)")
    q.add_argument("--scan-ratio", dest="scan_ratio", type=float, default=default_of(threshold, "scan_ratio"),
                   help=f"scan step ratio (default {default_of(threshold, 'scan_ratio'):g})")
    q.add_argument("--tol", type=float, default=default_of(threshold, "tol"),
                   help=f"relative bisection tolerance (default {default_of(threshold, 'tol'):g})")
    q.add_argument("--workers", type=workers_option, default=None, help="processes for the scan (default: all cores)")
    q.add_argument("--scheduler", default=None, help="Dask scheduler address tcp://HOST:PORT (instead of local workers)")
    q.set_defaults(func=_run_threshold)

    r = sub.add_parser("animate", help="animation of a tilt or shake run file (gif, or mp4 with ffmpeg)")
    r.add_argument("run", help="run file (.h5) written by `archdem tilt` or `archdem shake`")
    r.add_argument("--out", required=True, help="FILE.gif or FILE.mp4 (never overwritten)")
    r.add_argument("--fps", type=int, default=default_of(animate, "fps"),
                   help=f"frames per second (default {default_of(animate, 'fps')})")
    r.add_argument("--frames", type=int, default=default_of(animate, "max_frames"),
                   help=f"most frames (default {default_of(animate, 'max_frames')})")
    r.set_defaults(func=_run_animate)
