"""``archdem domain``: the failure domain of a rocking linkage (analytic), or of the DEM arch over sine
frequencies (``--engine dem``) plotted over the four-bar and two-bar domains of the same specimen."""
from __future__ import annotations

import argparse
import math
from dataclasses import replace

from analytic.rocking.domain import failure_domain
from dem.common.joints import contact_fraction
from dem.common.options import (
    CONTACT_LAW_DESTS,
    add_arch_arguments,
    add_contact_law_arguments,
    add_dynamics_dt_argument,
    arch_from_args,
    check_density,
    contact_law_settings,
    default_of,
    discretisation_kwargs,
    figure_file,
    option_used,
    parse_grid,
    piers_from_args,
    print_json,
    workers_option,
)
from dem.core.engines import available_engines, check_engine
from dem.core.progress import terminal
from dem.core.settings import DYNAMICS_ENGINE
from dem.experiments.shake.domain import analytic_domains, dem_failure_domain
from dem.experiments.shake.step_shake import SHAKE_FREQS
from specimens.blocks import DEFAULT_DENSITY, discretise
from specimens.catalogue import SPECIMEN_WIDTH
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from foundation.errors import ArchdemInputError
from foundation.io import MAX_GRID_POINTS

# Default grids of ``archdem domain`` (the analytic failure_domain takes its grid from the caller)
SINE_FREQS = "1:20:0.5"  # Hz
PULSE_DURATIONS = "0.05:1:0.05"  # s


def restitution_option(text: str) -> float | None:
    """``--restitution``: ``auto`` (None: momentum balance) or an energy restitution in [0, 1]."""
    if text == "auto":
        return None
    try:
        v = float(text)
    except ValueError:
        raise ArchdemInputError(f"--restitution must be 'auto' or a number in [0, 1], got {text!r}") from None
    if not 0 <= v <= 1:
        raise ArchdemInputError(f"--restitution must be in [0, 1], got {v:g}")
    return v


def build_mechanism(args: argparse.Namespace):
    """``(label, mechanism)`` opened by a positive ground acceleration, from the options."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking import linkage

    density = check_density(args.density) if args.density is not None else DEFAULT_DENSITY
    if args.block is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.rocking.rocking_block import RockingBlock

        if args.id is not None or any(getattr(args, k) is not None for k in ("Ri", "Re", "e", "Sh", "Sd", "Rc")):
            raise ArchdemInputError("give either --block B H or an arch, not both")
        if args.model not in (None, "block"):
            raise ArchdemInputError("--block goes with --model block")
        if args.contact is not None:
            raise ArchdemInputError("--contact applies to the joints of an arch, not to --block")
        if piers_from_args(args) is not None:
            raise ArchdemInputError("--pier-* options set an arch on piers, not a --block")
        b, h = args.block
        width = args.width if args.width is not None else SPECIMEN_WIDTH
        return f"block b={b:g} h={h:g}", RockingBlock(b, h, -1, density, width)
    label, arch = arch_from_args(args)
    model = args.model or "four-bar"
    if model == "block":
        raise ArchdemInputError("--model block needs --block B H")

    piers = piers_from_args(args)
    if piers is not None or args.layout == "discrete":
        return label, _discrete_four_bar(args, arch, model, density)
    contact = contact_fraction(args.contact, arch)
    if model == "two-bar":
        if contact != 1.0:
            raise ArchdemInputError("--contact is not modelled by the two-bar linkage; use the four-bar")
        return label, linkage.arch_two_bar(arch, density, direction=1)
    lay = args.layout
    if lay == "minimised":
        return label, linkage.minimised_four_bar(arch, density, direction=1, contact=contact)
    if lay == "oppenheim":
        layout = linkage.oppenheim_hinges(arch)
    else:
        layout = linkage.parse_hinge_angles(arch, lay)
    layout = tuple(replace(h, contact=contact) for h in layout)
    fb = linkage.arch_four_bar(arch, layout, density, direction=1, name=f"four-bar ({lay.split(',')[0] if ',' not in lay else 'user'})")
    if not fb.admissible:
        raise ArchdemInputError(f"the {lay} hinge layout is not an admissible mechanism for this arch")
    return label, fb


def _discrete_four_bar(args: argparse.Namespace, arch, model: str, density: float):
    """The four-bar of the discrete minimum mechanism (the only linkage of an arch on piers)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.linkage import mechanism_four_bar

    if model != "four-bar":
        raise ArchdemInputError("an arch on piers rocks as the four-bar of its discrete mechanism; use --model four-bar")
    if args.layout not in ("minimised", "discrete"):
        raise ArchdemInputError("on piers the four-bar's hinges are those of the discrete mechanism; use --layout discrete")
    kw = discretisation_kwargs(args, arch)
    kw["density"] = density
    return mechanism_four_bar(discretise(arch, **kw), direction=1)


def add_linkage_arguments(p: argparse.ArgumentParser) -> None:
    """The options ``domain`` and ``rock`` share: the arch or block, the linkage, its input."""
    add_arch_arguments(p)
    p.add_argument("--block", nargs=2, type=float, metavar=("B", "H"), default=None,
                   help="rectangular block of half-width B and half-height H [m]")
    p.add_argument("--model", choices=("four-bar", "two-bar", "block"), default=None, help="linkage (default four-bar)")
    p.add_argument("--layout", default="minimised",
                   help="four-bar hinge layout: minimised (continuous ring) | discrete (minimum mechanism of the "
                        "voussoirs, piers included; the only one on piers) | oppenheim | 'b1,b2,b3,b4' "
                        "(polar angles about O, rad)")
    p.add_argument("--input", choices=("sine", "sine0", "A", "B"), default="sine",
                   help="phased one-cycle sine (starts at the onset), plain one-cycle sine, pulse A or B")
    p.add_argument("--restitution", default="auto", help="'auto' (momentum balance) or an energy restitution in [0, 1]")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.add_argument("--plot", default=None, metavar="FILE.png", help="write a figure (never overwrites)")


def _run_domain(args: argparse.Namespace) -> int:
    if args.engine != "analytic":
        return int(dem_domain(args) or 0)
    option_used(args, "dt", False, "it is the DEM's time step (--engine dem or a named engine)")
    if args.scheduler:
        raise ArchdemInputError("--scheduler runs the DEM's domain (--engine dem); the analytic one runs here")
    if any(getattr(args, k) is not None for k in CONTACT_LAW_DESTS):
        raise ArchdemInputError("--contact-law, --kn, --youngs, --damping-* and --joints are the DEM's joints (--engine dem)")
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.impact import post_impact

    for dest in ("config", "mu_joint", "mu_base"):
        option_used(args, dest, False, "it is the DEM's (--engine dem)")
    rest = restitution_option(args.restitution)
    pulses = args.input in ("A", "B")
    if pulses and args.freq is not None:
        raise ArchdemInputError("pulses A/B take --durations, not --freq")
    if not pulses and args.durations is not None:
        raise ArchdemInputError("sine inputs take --freq, not --durations")
    if not (math.isfinite(args.tol) and 1e-4 <= args.tol <= 0.5):
        raise ArchdemInputError(f"--tol must be a relative tolerance in [0.0001, 0.5], got {args.tol}")
    if not (math.isfinite(args.amax) and 1 < args.amax <= 1e3):
        raise ArchdemInputError(f"--amax must be a ratio to the static onset in (1, 1000], got {args.amax:g}")
    if not 2 <= args.scan <= MAX_GRID_POINTS:
        raise ArchdemInputError(f"--scan must be 2 to {MAX_GRID_POINTS} amplitudes, got {args.scan}")
    xs = (parse_grid(PULSE_DURATIONS if args.durations is None else args.durations, "--durations") if pulses
          else parse_grid(SINE_FREQS if args.freq is None else args.freq))
    if not 0.01 <= min(xs) <= max(xs) <= 100:
        raise ArchdemInputError(f"{'--durations [s]' if pulses else '--freq [Hz]'} values must be in [0.01, 100]")
    if args.plot:
        figure_file(args.plot)
    label, mech = build_mechanism(args)
    dom = failure_domain(mech, args.input, xs, a_max_ratio=args.amax, n_scan=args.scan, tol=args.tol,
                         restitution=rest, workers=args.workers)
    e = post_impact(mech, rest).e_applied
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.rocking.figures import plot_domain

        plot_domain(dom, args.plot, title=f"{label}: {mech.label}, input {args.input}")
    if args.json:
        hinges = {"hinges": mech.summary()["hinges"]} if "hinges" in mech.summary() else {}
        print_json({"restitution": e, "omega0": dom.omega0, "phi_cr": dom.phi_cr, "lambda": dom.lam, **hinges,
                    "points": dom.points(), "bands": dom.bands()})
        return 0
    unit = "Hz" if dom.axis == "frequency" else "s"
    print(f"{label}  {mech.label}  lambda {dom.lam:.4f}  omega0 {dom.omega0:.4g} rad/s  phi_cr {dom.phi_cr:.4g} rad  "
          f"e {e:.4f}")
    for c in dom.columns:
        th = ", ".join(f"{a / 9.81:.4f} g ({m})" for a, m in c.thresholds) or "none below a_max"
        print(f"  {c.x:8.4g} {unit}: collapse from {th}")
    if args.plot:
        print(f"figure: {args.plot}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("domain", help="failure domain of a rocking linkage (collapse amplitude vs frequency/duration)",
                       description="Failure domain: amplitude scan and bisection at every frequency (sines) or "
                                   "duration (pulses), all collapse/survival bands.")
    add_linkage_arguments(p)
    p.add_argument("--freq", default=None, help=f"frequencies [Hz]: '0.5,1,2' or 'start:stop:step', at most {MAX_GRID_POINTS} (default "
                   f"{SINE_FREQS}; --engine dem {','.join(f'{f:g}' for f in SHAKE_FREQS)})")
    p.add_argument("--durations", default=None, help=f"pulse durations t_i [s] (default {PULSE_DURATIONS})")
    p.add_argument("--amax", type=float, default=default_of(failure_domain, "a_max_ratio"),
                   help=f"top of the amplitude scan / (lambda g) (default {default_of(failure_domain, 'a_max_ratio'):g}; "
                        f"--engine dem {default_of(dem_failure_domain, 'a_max_ratio'):g})")
    p.add_argument("--scan", type=int, default=default_of(failure_domain, "n_scan"),
                   help=f"amplitudes in the scan (default {default_of(failure_domain, 'n_scan')})")
    p.add_argument("--tol", type=float, default=default_of(failure_domain, "tol"),
                   help=f"relative bisection tolerance (default {default_of(failure_domain, 'tol'):g})")
    p.add_argument("--workers", type=workers_option, default=None, help="processes (default: all cores)")
    p.add_argument("--scheduler", default=None, help="Dask scheduler address tcp://HOST:PORT (with --engine dem)")
    p.add_argument("--engine", choices=("analytic", "dem", *available_engines()), default="analytic",
                   help=f"analytic linkage, or the DEM: 'dem' runs the shakes' default engine ({DYNAMICS_ENGINE}), "
                        "or name one")
    add_dynamics_dt_argument(p, "DEM: ")
    p.add_argument("--config", choices=("glued", "free"), default=default_of(dem_failure_domain, "config"),
                   help="DEM: discrete configuration")
    p.add_argument("--mu-joint", dest="mu_joint", type=float, default=None,
                   help=f"DEM: block-block friction (default {REFERENCE_MU_JOINT:g})")
    p.add_argument("--mu-base", dest="mu_base", type=float, default=None,
                   help=f"DEM: block-base friction (default {REFERENCE_MU_BASE:g})")
    add_contact_law_arguments(p)
    p.set_defaults(func=_run_domain)


def dem_domain(args: argparse.Namespace) -> int:
    """``archdem domain ID --engine dem --freq 2,4,6,8,10 [--plot FILE] [--json]``."""
    if getattr(args, "block", None) is not None:
        raise ArchdemInputError("--engine dem takes an arch (id or parameters), not --block")
    if getattr(args, "input", "sine") not in ("sine", "sine0"):
        raise ArchdemInputError("--engine dem runs one-cycle sines only (--input sine0)")
    if getattr(args, "durations", None) is not None:
        raise ArchdemInputError("--engine dem takes --freq, not --durations")
    for dest in ("model", "layout", "restitution", "scan", "tol"):
        option_used(args, dest, False, "it belongs to the analytic linkage (--engine analytic)")

    freqs = parse_grid(args.freq) if args.freq is not None else list(SHAKE_FREQS)
    if args.plot:
        figure_file(args.plot)
    if getattr(args, "engine", "dem") == "dem":
        args.engine = DYNAMICS_ENGINE
    check_engine(args.engine)
    label, arch = arch_from_args(args)
    law = contact_law_settings(args, getattr(args, "id", None))
    dem_a_max = default_of(dem_failure_domain, "a_max_ratio")
    a_max = getattr(args, "amax", dem_a_max)
    # the analytic default (failure_domain's a_max_ratio) is too costly here: the DEM's own default instead
    a_max = dem_a_max if a_max is None or a_max == default_of(failure_domain, "a_max_ratio") else float(a_max)
    with terminal(f"domain {label}", unit="frequencies", enabled=not args.json) as line:
        res = dem_failure_domain(label, arch, freqs, getattr(args, "config", None) or default_of(dem_failure_domain, "config"),
                                 getattr(args, "mu_joint", None), getattr(args, "mu_base", None), a_max_ratio=a_max,
                                 workers=getattr(args, "workers", None), disc_kw=discretisation_kwargs(args, arch),
                                 scheduler=getattr(args, "scheduler", None), joints=law or None, engine=args.engine,
                                 dt=getattr(args, "dt", None), progress=line)
    if args.plot:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from dem.experiments.shake.figure import plot_domain_over_analytic

        density = getattr(args, "density", None) or DEFAULT_DENSITY
        contact = discretisation_kwargs(args, arch).get("contact", 1.0)
        plot_domain_over_analytic(res, analytic_domains(arch, freqs, density, contact=contact,
                                                        piers=piers_from_args(args)), args.plot,
                                  title=f"{label}: DEM vs rocking linkages, one-cycle sine")
        res["plot"] = str(args.plot)
    if args.json:
        print_json({k: v for k, v in res.items() if k != "thresholds"} | {"thresholds": [
            {k: t[k] for k in ("freq", "amplitude_g", "bracket_g", "mode", "collapse_phase", "n_sims")}
            for t in res["thresholds"]]})
        return 0
    print(f"{label}  DEM ({res['physics_engine']}, dt {res['dt']:g} s, {res['config']}, mu {res['mu_joint']:g}/"
          f"{res['mu_base']:g})  static lambda {res['lambda']:.4f}")
    for t in res["thresholds"]:
        a = "none up to %.3f g" % res["a_range_g"][1] if t["amplitude_g"] is None else f"{t['amplitude_g']:.4f} g"
        above = ", ".join(f"{b['from_g']:.3f}-{b['to_g']:.3f} g" for b in t["survival_bands_above"])
        print(f"  {t['freq']:6.3g} Hz: collapse from {a}" + (f"; survives again {above}" if above else ""))
    if args.plot:
        print(f"figure: {args.plot}")
    return 0
