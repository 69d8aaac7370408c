"""``archdem domain``: the failure domain of a rocking linkage (analytic), or of the DEM arch over sine
frequencies (``--engine dem``) plotted over the four-bar and two-bar domains of the same specimen."""
from __future__ import annotations

import argparse
import math
from dataclasses import replace

from analytic.rocking.domain import failure_domain
from dem.common.joints import contact_fraction
from dem.common.options import (
    add_options,
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
)
from dem.core.engines import check_engine
from dem.core.progress import terminal
from dem.core.settings import DYNAMICS_ENGINE
from dem.experiments.shake.domain import (
    analytic_domain_json,
    analytic_domain_lines,
    analytic_domains,
    dem_domain_json,
    dem_domain_lines,
    dem_failure_domain,
)
from dem.experiments.shake.step_shake import SHAKE_FREQS
from specimens.blocks import DEFAULT_DENSITY, discretise
from specimens.catalogue import SPECIMEN_WIDTH
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

    option_used(args, "layout", args.block is None and args.model in (None, "four-bar"),
                "it places the hinges of the four-bar (--model four-bar)")
    density = check_density(args.density) if args.density is not None else DEFAULT_DENSITY
    if args.block is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.rocking.rocking_block import RockingBlock

        if args.id is not None or any(getattr(args, k) is not None for k in ("Ri", "Re", "e", "Sh", "Sd", "Rc")):
            raise ArchdemInputError("give either --block B H or an arch, not both")
        if args.model not in (None, "block"):
            raise ArchdemInputError("--block goes with --model block")
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


def add_linkage_arguments(p: argparse.ArgumentParser, command: str, **defaults) -> None:
    """The options ``domain`` and ``rock`` share: the table's (the arch or block), the linkage, its input."""
    add_options(p, command, **defaults)
    p.add_argument("--model", choices=("four-bar", "two-bar", "block"), default=None, help="linkage (default four-bar)")
    p.add_argument("--layout", default="minimised",
                   help="four-bar hinge layout: minimised (continuous ring) | discrete (minimum mechanism of the "
                        "voussoirs, piers included; the only one on piers) | oppenheim | 'b1,b2,b3,b4' "
                        "(polar angles about O, rad)")
    p.add_argument("--input", choices=("sine", "sine0", "A", "B"), default="sine",
                   help="phased one-cycle sine (starts at the onset), plain one-cycle sine, pulse A or B")
    p.add_argument("--restitution", default="auto", help="'auto' (momentum balance) or an energy restitution in [0, 1]")


def _run_domain(args: argparse.Namespace) -> int:
    if args.engine != "analytic":
        return int(dem_domain(args) or 0)
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.impact import post_impact

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
        print_json(analytic_domain_json(mech, dom, e))
        return 0
    print("\n".join(analytic_domain_lines(label, mech, dom, e) + ([f"figure: {args.plot}"] if args.plot else [])))
    return 0


def register(sub) -> None:
    p = sub.add_parser("domain", help="failure domain of a rocking linkage (collapse amplitude vs frequency/duration)",
                       description="Failure domain: amplitude scan and bisection at every frequency (sines) or "
                                   "duration (pulses), all collapse/survival bands.")
    add_linkage_arguments(p, "domain", config=default_of(dem_failure_domain, "config"))
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
        print_json(dem_domain_json(res))
    else:
        print("\n".join(dem_domain_lines(label, res)))
    return 0
