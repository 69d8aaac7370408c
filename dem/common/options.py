"""What the sub-commands share: the option table (every shared option declared once, with where it
applies), arch selection, JSON output, output paths."""
from __future__ import annotations

import argparse
import dataclasses
import inspect
import json
import math
import os
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from analytic.compliant.modes import KS_OVER_KN
from analytic.motions.records import UNIT_FACTORS
from dem.common.joints import CALIBRATED, JOINT_SETS, STUDY_JOINTS, contact_fraction, joint_law
from dem.core.engines import available_engines
from dem.core.engines.options import PyBulletOptions
from dem.core.settings import CONTACT_LAWS, DYNAMICS_DT, DYNAMICS_ENGINE, MAX_DAMPING_XI, Settings
from specimens.blocks import DEFAULT_DENSITY, DEFAULT_VOUSSOIRS, check_contact, discretise
from specimens.catalogue import SPECIMEN_WIDTH, get_specimen
from specimens.constants import DRAWN_DENSITY, MAX_LENGTH_M, MIN_LENGTH_M  # lengths an option takes [m]
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from specimens.drawn import DRAWN_CONFIG, MAX_BLOCKS, DrawnAssembly, gaps_text
from foundation.errors import ArchdemInputError
from specimens.exchange import UNITS, read_assembly
from specimens.geometry import PointedArch
from foundation.io import can_make_dir, check_name, json_default, unique_run_path, writable_dir, writable_file  # noqa: F401 (the CLI modules import them from here)
from foundation.io import parse_grid as _parse_grid
from specimens.piers import MAX_COURSES, Piers

#: The units of a record's numbers (archdem shake --record --units).
RECORD_UNITS = tuple(UNIT_FACTORS)
#: Densities the commands take [kg/m^3].
DENSITY_RANGE = (1.0, 1e5)


def default_of(obj: Any, name: str) -> Any:
    """The library's default of ``name``: a field of dataclass ``obj`` or a parameter of function ``obj``.

    The sub-commands take their defaults (and the values their help texts show) from here, so a
    default is declared once, in the library. Raises ``LookupError`` if ``obj`` has no such default."""
    if dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            if f.name == name:
                if f.default is not dataclasses.MISSING:
                    return f.default
                if f.default_factory is not dataclasses.MISSING:
                    return f.default_factory()
                break
        raise LookupError(f"{getattr(obj, '__name__', obj)} has no default for {name!r}")
    par = inspect.signature(obj).parameters.get(name)
    if par is None or par.default is inspect.Parameter.empty:
        raise LookupError(f"{getattr(obj, '__name__', obj)}() has no default for {name!r}")
    return par.default


#: The depth [m] `archdem draw` gives blocks that state none (a plane drawing: masses per metre of depth).
PLANE_DEPTH_M = 1.0


def geometry_from_args(args: argparse.Namespace, plane: bool = False):
    """``(label, DrawnAssembly)`` of ``--geometry`` (the arch and pier options refused beside it, and
    ``--config``: a drawing's bodies are as drawn, so the command's configuration becomes
    :data:`~specimens.drawn.DRAWN_CONFIG` in its output and file names). ``plane``: the command draws the
    blocks in their plane, so a block without a depth takes :data:`PLANE_DEPTH_M`."""
    given_arch = [f"--{k.replace('_', '-')}" for k in ("Ri", "Re", "e", "Sh", "Sd", "Rc", "width", "voussoirs")
                  + PIER_OPTIONS if getattr(args, k, None) is not None]
    if getattr(args, "id", None) is not None or given_arch:
        drop = "the specimen id" if getattr(args, "id", None) is not None else given_arch[0]
        raise ArchdemInputError(f"--geometry gives the whole structure: drop {drop}")
    option_used(args, "config", False, "a drawing's blocks are as drawn, with no glued or free crown")
    if hasattr(args, "config"):
        args.config = DRAWN_CONFIG
    if args.depth is not None and not (math.isfinite(args.depth) and MIN_LENGTH_M <= args.depth <= MAX_LENGTH_M):
        raise ArchdemInputError(f"--depth must be a length between {MIN_LENGTH_M:g} and {MAX_LENGTH_M:g} m, got {args.depth:g}")
    units = args.units if args.units in UNITS else None  # otherwise a record's units (shake)
    density = check_density(args.density) if getattr(args, "density", None) is not None else None
    depth = PLANE_DEPTH_M if plane and args.depth is None else args.depth
    return Path(args.geometry).stem, read_assembly(args.geometry, units=units, depth=depth, density=density)


def density_text(asm: DrawnAssembly) -> str:
    """``density 2000 kg/m^3 (archdem's default for drawings)``: a drawing's density and where it came from."""
    why = {"given": "--density", "file": "stated by the file"}.get(asm.source.get("density_from"),
                                                                   "archdem's default for drawings; --density sets it")
    return f"density {asm.density:g} kg/m^3 ({why})"


def arch_from_args(args: argparse.Namespace):
    """Return ``(label, PointedArch)`` from the id or the parameter options; the label names the
    piers too when the ``--pier-*`` options set them. With ``--geometry``: ``(label, DrawnAssembly)``,
    which :func:`specimens.blocks.discretise` returns as drawn."""
    if getattr(args, "geometry", None) is not None:
        return geometry_from_args(args)
    label, arch = _arch_from_args(args)
    piers = piers_from_args(args)
    if piers is None:
        return label, arch
    return (f"{label}-piers-H{piers.height:g}-B{piers.width:g}" + (f"-N{piers.courses}" if piers.courses > 1 else "")
            + (f"-P{piers.load / 1e3:g}kN" if piers.load else "")), arch


def _arch_from_args(args: argparse.Namespace):
    for name in ("Ri", "Re", "e", "Rc", "width"):
        v = getattr(args, name, None)
        lo = 0.0 if name == "e" else MIN_LENGTH_M
        if v is not None and not (math.isfinite(v) and lo <= v <= MAX_LENGTH_M):
            raise ArchdemInputError(f"--{name} must be a length between {lo:g} and {MAX_LENGTH_M:g} m, got {v:g}")
    width = args.width if args.width is not None else SPECIMEN_WIDTH
    by_radii = [args.Ri, args.Re, args.e]
    by_ratio = [args.Sh, args.Sd, args.Rc]
    if args.id is not None:
        if any(v is not None for v in by_radii + by_ratio):
            raise ArchdemInputError("give either a specimen id or --Ri/--Re/--e or --Sh/--Sd/--Rc, not both")
        spec = get_specimen(args.id)
        arch = spec.arch if args.width is None else spec.arch.with_width(width)
        return spec.id, arch
    if all(v is not None for v in by_radii) and all(v is None for v in by_ratio):
        arch = PointedArch.from_radii(args.Ri, args.Re, args.e, width=width)
    elif all(v is not None for v in by_ratio) and all(v is None for v in by_radii):
        arch = PointedArch.from_ratios(args.Sh, args.Sd, args.Rc, width=width)
    else:
        raise ArchdemInputError("give a specimen id, or all of --Ri --Re --e, or all of --Sh --Sd --Rc")
    # lengths that follow from the given ones are bounded too (a ring 1e-280 m thick has no blocks)
    for what, v in (("ring thickness", arch.t), ("span", arch.span), ("rise", arch.rise)):
        if not MIN_LENGTH_M <= v:
            raise ArchdemInputError(f"these parameters give a {what} of {v:.3g} m, below {MIN_LENGTH_M:g} m")
    label = f"Sh{arch.Sh:.3g}-Sd{arch.Sd:.3g}-Rc{arch.Rc:.3g}"
    return label, arch


PIER_OPTIONS = ("pier_height", "pier_width", "pier_depth", "pier_offset", "pier_courses", "pier_load")
#: Largest superimposed load on a pier [kN] (a 50 m column of masonry 3 m square is about 10^4 kN).
MAX_PIER_LOAD_KN = 1e6


def piers_from_args(args: argparse.Namespace) -> Piers | None:
    """The :class:`~specimens.piers.Piers` of the ``--pier-*`` options (None without ``--pier-height``)."""
    given = {k: getattr(args, k, None) for k in PIER_OPTIONS if getattr(args, k, None) is not None}
    if not given:
        return None
    if "pier_height" not in given or "pier_width" not in given:
        raise ArchdemInputError("piers need both --pier-height and --pier-width")
    for k in ("pier_height", "pier_width", "pier_depth", "pier_offset"):
        v = given.get(k)
        lo = 0.0 if k == "pier_offset" else MIN_LENGTH_M
        if v is not None and not (math.isfinite(v) and lo <= v <= MAX_LENGTH_M):
            raise ArchdemInputError(f"--{k.replace('_', '-')} must be a length between {lo:g} and {MAX_LENGTH_M:g} m, "
                                    f"got {v:g}")
    load = given.get("pier_load", 0.0)
    if not (math.isfinite(load) and 0 <= load <= MAX_PIER_LOAD_KN):
        raise ArchdemInputError(f"--pier-load must be a force between 0 and {MAX_PIER_LOAD_KN:g} kN, got {load:g}")
    return Piers(given["pier_height"], given["pier_width"], given.get("pier_depth"), given.get("pier_offset", 0.0),
                 given.get("pier_courses", 1), load * 1e3)


#: Most local worker processes a command starts.
MAX_WORKERS = 256
#: Most voussoirs per side (a typo such as 100000 would otherwise take the machine's memory).
MAX_VOUSSOIRS = 100


def block_from_args(args: argparse.Namespace) -> tuple[float, float] | None:
    """``(B, H)`` [m] of ``--block`` (half-width, half-height) when given; refused beside an arch (the
    option table refuses its piers and contact); with neither a block nor an arch, one line asking for one."""
    arch_given = args.id is not None or any(getattr(args, k, None) is not None for k in ("Ri", "Re", "e", "Sh", "Sd", "Rc",
                                                                                        "geometry"))
    if args.block is None:
        if not arch_given:
            raise ArchdemInputError("give a specimen id, the arch parameters or --block B H")
        return None
    if arch_given:
        raise ArchdemInputError("give either --block B H or an arch, not both")
    return float(args.block[0]), float(args.block[1])


def workers_option(text: str) -> int:
    """``--workers``: a whole number of processes, 1 to MAX_WORKERS (the same rule on every command)."""
    try:
        n = int(text)
    except ValueError:
        n = 0
    if not 1 <= n <= MAX_WORKERS:
        raise argparse.ArgumentTypeError(f"must be a whole number of processes >= 1 (at most {MAX_WORKERS}), got {text!r}")
    return n


def contact_option(text: str) -> float | str:
    """``--contact``: a fraction in (0, 1] or ``calibrated`` (resolved by :func:`dem.common.joints.contact_fraction`)."""
    if text.strip().lower() == CALIBRATED:
        return CALIBRATED
    try:
        return check_contact(float(text))
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a fraction in (0, 1] or '{CALIBRATED}', got {text!r}") from None
    except ArchdemInputError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def check_density(density: float) -> float:
    """``--density`` within DENSITY_RANGE [kg/m^3], or a one-line input error."""
    if not (math.isfinite(density) and DENSITY_RANGE[0] <= density <= DENSITY_RANGE[1]):
        raise ArchdemInputError(f"--density must be between {DENSITY_RANGE[0]:g} and {DENSITY_RANGE[1]:g} kg/m^3, "
                                f"got {density:g}")
    return float(density)


def discretisation_kwargs(args: argparse.Namespace, arch=None) -> dict[str, Any]:
    """The :func:`specimens.blocks.discretise` keywords of the arch options (``arch``: needed for
    ``--contact calibrated``)."""
    kw: dict[str, Any] = {}
    if getattr(args, "voussoirs", None) is not None:
        if not 1 <= args.voussoirs <= MAX_VOUSSOIRS:
            raise ArchdemInputError(f"--voussoirs must be 1 to {MAX_VOUSSOIRS}, got {args.voussoirs}")
        kw["n_voussoirs"] = args.voussoirs
    if getattr(args, "density", None) is not None:
        check_density(args.density)
        kw["density"] = args.density
    if getattr(args, "contact", None) is not None:
        kw["contact"] = contact_fraction(args.contact, arch)
    piers = piers_from_args(args)
    if piers is not None:
        if arch is not None:
            piers.check(arch)
        kw["piers"] = piers
    return kw


def require_standing(label: str, arch, **kw: Any) -> None:
    """Refuse, in one line, an arch (``discretise`` keywords ``kw``) that cannot stand under its own
    weight even without sliding: a test of its capacity would answer nothing. A drawing's refusal names
    its gaps and the parts no joint joins; a drawing that stands with gaps says so on stderr."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import require_standing as _require_standing
    from analytic.limit.limit_discrete import solve_lp

    asm = discretise(arch, **kw)
    if not isinstance(asm, DrawnAssembly):
        _require_standing(label, asm)
        return
    if not solve_lp(asm, math.inf, math.inf).stands:
        raise ArchdemInputError(asm.cannot_stand(label))
    if asm.gaps:
        print(f"archdem: warning: {label}: {gaps_text(asm.gaps)} (no joint between them; it stands without one)",
              file=sys.stderr)


#: Figure formats the commands write (matplotlib's, by the file's suffix).
FIGURE_SUFFIXES = (".png", ".pdf", ".svg")


def figure_file(path: str, option: str = "--plot"):
    """A new figure file: a known suffix, not an existing file or folder; checked before any run."""
    p = Path(path)
    if p.suffix.lower() not in FIGURE_SUFFIXES:
        raise ArchdemInputError(f"{option} must end in {', '.join(FIGURE_SUFFIXES)}, got {p.name!r}")
    check_name(p)
    if p.is_dir():
        raise ArchdemInputError(f"{option} {p} is a folder; give a file name")
    return writable_file(p, overwrite=False)


def study_path(args: argparse.Namespace, default_dir: str, stem: str) -> tuple[str, bool]:
    """``(path, resume)`` of a study command's ``--out`` / ``--resume`` (one rule for every study):
    a mistyped ``--resume`` name is refused rather than starting a new study under it, and an
    existing or unwritable ``--out`` before any run."""

    if args.resume is not None and args.out is not None:
        raise ArchdemInputError("give --out (new study) or --resume STUDY.h5, not both")
    if args.resume and os.path.isdir(args.resume):
        raise ArchdemInputError(f"--resume {args.resume} is a folder; a study is one .h5 file")
    if args.resume is not None and not os.path.isfile(args.resume):
        raise ArchdemInputError(f"--resume {args.resume!r}: no such study file; start a new study with --out")
    if args.resume:
        return args.resume, True
    if args.out is not None:
        out = Path(args.out)
        if out.name:
            check_name(out)
        if not out.name or out.is_dir():
            raise ArchdemInputError(f"--out {args.out!r}: give a study file name (STUDY.h5), not a folder")
        if out.exists() or out.is_symlink():
            raise ArchdemInputError(f"--out {out} exists; a study is never overwritten (resume it with --resume, "
                                    "or choose another file)")
        can_make_dir(out.parent)
        return args.out, False
    return str(unique_run_path(can_make_dir(default_dir), stem)), False


#: Options that say where and how a study runs, not what it computes: outside its stored definition.
RUN_OPTIONS = frozenset({"out", "resume", "workers", "scheduler", "plot", "json", "func", "command", "given"})


def study_stopped(path: str, exc: BaseException) -> int:
    """Says in one line that the study in ``path`` stopped early and how to continue it; returns the
    exit code (130 for Ctrl-C, 2 for a dead worker). Its finished cases are in the file either way."""
    why = "interrupted" if isinstance(exc, KeyboardInterrupt) else f"study interrupted: {exc}"
    print(f"archdem: {why}; finished cases are stored, continue with --resume {path}", file=sys.stderr)
    return 130 if isinstance(exc, KeyboardInterrupt) else 2


def given(args: argparse.Namespace) -> frozenset[str]:
    """The options the command line set by hand (``archdem`` records them; otherwise those set to
    something other than None or False)."""
    g = getattr(args, "given", None)
    return frozenset(k for k, v in vars(args).items() if v is not None and v is not False) if g is None else frozenset(g)


def common_rules(args: argparse.Namespace) -> None:
    """The rules every command shares, checked before its own: an output given as an empty name (which
    would mean no output at all), ``--workers`` beside ``--scheduler``."""
    for dest in sorted(OUTPUT_OPTIONS & given(args)):
        v = getattr(args, dest, None)
        if isinstance(v, str) and not v.strip():
            raise ArchdemInputError(f"{option_name(dest)} is empty; give a name")
    option_used(args, "workers", not getattr(args, "scheduler", None), "a --scheduler's cluster runs the cases")
    refuse_unused(args)


#: Options that name an output or a study file.
OUTPUT_OPTIONS = frozenset({"out", "plot", "report", "resume", "animate"})


def option_name(dest: str) -> str:
    """``--mu-base`` of the destination ``mu_base`` (``id``: the positional specimen id)."""
    return "the specimen id" if dest == "id" else "--" + dest.replace("_", "-")


def option_used(args: argparse.Namespace, dest: str, used: bool, why: str) -> None:
    """One rule for options that do nothing in their context: ``dest`` given by hand where it is
    not ``used`` is refused in one line, ``why`` saying what it belongs to."""
    if not used and dest in given(args):
        raise ArchdemInputError(f"{option_name(dest)} does nothing here: {why}")


def study_definition(args: argparse.Namespace) -> dict:
    """What a study command computes: its options but RUN_OPTIONS (stored in the study file)."""
    return {k: v for k, v in vars(args).items() if k not in RUN_OPTIONS}


def restore_study(args: argparse.Namespace) -> None:
    """``--resume STUDY.h5``: the study's options from its file, so that a resume runs that study; an
    option given by hand with another value is refused in one line (a study made without a stored
    definition keeps the command line's)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.studies.sweep import canonical_json, stored_definition

    if getattr(args, "out", None):  # said first: which of the two was meant is the user's to say
        raise ArchdemInputError("give --out (new study) or --resume STUDY.h5, not both")
    if os.path.isdir(args.resume):
        raise ArchdemInputError(f"--resume {args.resume} is a folder; a study is one .h5 file")
    if not os.path.isfile(args.resume):  # said before any option the study would have given is missed
        raise ArchdemInputError(f"--resume {args.resume!r}: no such study file; start a new study with --out")
    stored = stored_definition(args.resume)
    if stored is None:
        return
    mine = given(args)
    for k, v in stored.items():
        if k in RUN_OPTIONS or not hasattr(args, k):
            continue
        have = getattr(args, k)
        if k in mine and canonical_json(have) != canonical_json(v):
            raise ArchdemInputError(f"{option_name(k)} {_shown(have)} is not the study's ({args.resume} holds "
                                    f"{_shown(v)}); resume without it, or start a new study with --out")
        setattr(args, k, tuple(v) if isinstance(have, tuple) else v)


def _shown(v: Any) -> str:
    return " ".join(map(str, v)) if isinstance(v, (list, tuple)) else str(v)


def print_json(obj: Any) -> None:
    print(json.dumps(obj, indent=2, default=json_default, allow_nan=True))


def parse_grid(text: str, what: str = "--freq") -> list[float]:
    """A grid option: :func:`foundation.io.parse_grid` (one parser for every command)."""
    return _parse_grid(text, what)


def settings_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    """The :class:`Settings` fields of a simulating command's options: frictions, engine, the plane, the
    step and the joint law (``--joints table-5.1`` of the specimen id)."""
    kw = {"mu_joint": args.mu_joint, "mu_base": args.mu_base, "planar": bool(args.planar), "engine": args.engine,
          **contact_law_settings(args, getattr(args, "id", None))}
    return kw | ({"dt": args.dt} if args.dt is not None else {})


def contact_law_settings(args: argparse.Namespace, specimen_id: str | None) -> dict[str, Any]:
    """The contact-law fields of :class:`dem.core.settings.Settings` from the command line ({} = rigid),
    for the specimen ``specimen_id`` (``--joints table-5.1``) and the engine ``args.engine``."""
    out = _contact_law(args, specimen_id)
    engines = (getattr(args, "engine", None), getattr(args, "dynamics_engine", None))
    if out and "mujoco" in engines and not (out.get("damping_beta") or out.get("damping_xi")):
        raise ArchdemInputError("compliant joints on MuJoCo (--engine mujoco, the shakes' default) need --damping-beta or "
                                "--damping-xi: undamped, the blocks keep bouncing on their springs and the joints slip "
                                "(docs/engines.md#10-compliant-joints)")
    return out


def _contact_law(args: argparse.Namespace, specimen_id: str | None) -> dict[str, Any]:
    """The options' law, checked by :class:`dem.core.settings.Settings` (its checks and messages); the
    command line adds only what is its own: --joints beside the other options, and the law implied by
    --kn/--youngs/--damping-* without --contact-law (the option table refuses --ks)."""
    kn, youngs, beta, xi = (getattr(args, k, None) for k in ("kn", "youngs", "damping_beta", "damping_xi"))
    law = getattr(args, "contact_law", None)
    given = {k: v for k, v in (("kn", kn), ("youngs", youngs), ("damping_beta", beta), ("damping_xi", xi))
             if v is not None}
    if getattr(args, "joints", None) == STUDY_JOINTS:
        if given or law == "rigid":
            raise ArchdemInputError(f"--joints {STUDY_JOINTS} sets the joints: give it without --contact-law rigid, "
                                    "--kn or --damping-*")
        return joint_law(STUDY_JOINTS, specimen_id)
    if law is None:
        law = "compliant" if given else default_of(Settings, "contact_law")
    out = {"contact_law": law, **given}
    Settings(**out)  # the law's own checks and messages
    return {} if law == "rigid" else out


def friction_option(text: str) -> float:
    """``--mu-joint``/``--mu-base``: a friction coefficient >= 0, ``inf`` for no sliding (the limit
    analyses'); a simulation takes :data:`~dem.core.settings.MIN_FRICTION` to ``MAX_FRICTION``
    (:class:`Settings` checks it)."""
    try:
        v = float(text)
    except ValueError:
        v = math.nan
    if not v >= 0:
        raise argparse.ArgumentTypeError(f"must be a friction coefficient >= 0 (inf: no sliding), got {text!r}")
    return v


# ------------------------------------------------------------------ the option table
#: A condition under which an option does something, on the parsed options.
Condition = Callable[[argparse.Namespace], bool]
#: Where an option applies in one command: its condition (None: always) and what it belongs to.
Rule = tuple[Condition | None, str]


@dataclass(frozen=True)
class Option:
    """One command-line option, declared once: its flags, help, argparse keywords (``type`` is its one
    validator where the library has none of its own; a default only from a library object), ``where``:
    per command, the condition under which it does something and what it belongs to otherwise, and
    ``per``: a command's own keywords (help, choices, default)."""

    flags: tuple[str, ...]
    help: str
    where: dict[str, Rule]
    kw: dict[str, Any] = field(default_factory=dict)
    per: dict[str, dict[str, Any]] = field(default_factory=dict)
    group: str = ""
    example: str | None = "1"  # a value the parser takes (None: a flag)

    @property
    def dest(self) -> str:
        return self.kw.get("dest") or self.flags[0].lstrip("-").replace("-", "_")


def _on(commands: str, cond: Condition | None = None, why: str = "", **own: Rule) -> dict[str, Rule]:
    """``where``: the same rule in each of the space-separated ``commands``, other rules in ``own``."""
    return {c: (cond, why) for c in commands.split()} | {k.replace("_", "-"): v for k, v in own.items()}


def _drawing(a: argparse.Namespace) -> bool:
    return getattr(a, "geometry", None) is not None


def _arch(a: argparse.Namespace) -> bool:
    return getattr(a, "block", None) is None


def _dem(a: argparse.Namespace) -> bool:  # archdem domain: the DEM's domain, not the analytic linkage's
    return a.engine != "analytic"


def _no_ensemble(a: argparse.Namespace) -> bool:
    return a.ensemble is None


def _arch_given(a: argparse.Namespace) -> bool:
    return a.id is not None or any(getattr(a, k, None) is not None for k in ARCH_PARAMETERS + ("geometry",))


def campaign_steps(args: argparse.Namespace) -> set[str] | None:
    """The steps ``--steps`` and ``--piers/--fragility/--drawing`` name (None: the default steps, every kind)."""
    if args.steps is None:
        return None
    return {s.strip() for s in args.steps.split(",")} | {n for n in ("piers", "fragility", "drawing") if getattr(args, n)}


def _steps(names: str, what: str) -> Rule:
    return (lambda a: (s := campaign_steps(a)) is None or bool(s & set(names.split())),
            f"no step named by --steps {what}")


ARCH_PARAMETERS = ("Ri", "Re", "e", "Sh", "Sd", "Rc")
#: The commands that take an arch (an id, parameters or a drawing); those that take a --block too.
ARCH_COMMANDS = "tilt shake threshold analytic domain rock mesh draw assess fragility modes"
BLOCK_COMMANDS = "fragility modes rock domain"
_ARCH_ONLY = _on(BLOCK_COMMANDS, _arch, "it belongs to an arch, not to a --block")
_DEM = (_dem, "it is the DEM's (--engine dem)")
_ENSEMBLE_RUNS = (_no_ensemble, "an ensemble runs the default hold protocol")
#: Campaign steps by what they read: the joint law, the statics' engine, the shakes', the sweeps'
#: processes, the contact fraction.
_LAW = _on("tilt shake threshold fragility map", tilt=(_no_ensemble, "an ensemble runs rigid joints"), domain=_DEM,
           campaign=_steps("modes tilt lab map piers shake record fragility drawing", "runs joints"))
_SWEEPS = _steps("tilt lab map piers shake record fragility", "runs a sweep")
_DT = f"time step [s] (default {DYNAMICS_DT:g} on {DYNAMICS_ENGINE}, {default_of(Settings, 'dt'):g} on the other engines)"

OPTIONS: tuple[Option, ...] = (
    Option(("id",), "specimen id (see `archdem specimens`)", _on(ARCH_COMMANDS), {"nargs": "?"}, example="Sh02-Sd020"),
    *(Option((f"--{k}",), "", _on(ARCH_COMMANDS), {"type": float}, group="arch", example="0.2") for k in ARCH_PARAMETERS),
    Option(("--width",), f"out-of-plane width [m] (default: the specimen's, else {SPECIMEN_WIDTH:g})",
           _on(ARCH_COMMANDS), {"type": float}, group="arch", example="0.2"),
    Option(("--voussoirs",), f"voussoirs per side, 1 to {MAX_VOUSSOIRS} (default {DEFAULT_VOUSSOIRS})",
           _on(ARCH_COMMANDS) | _ARCH_ONLY, {"type": int}, group="arch", example="4"),
    Option(("--density",), f"density [kg/m^3], {DENSITY_RANGE[0]:g} to {DENSITY_RANGE[1]:g} (default "
           f"{DEFAULT_DENSITY:g}) of the specimens' aerated concrete; a drawing's: the one its file states, else "
           f"{DRAWN_DENSITY:g}, masonry. Masses and forces scale with it; a uniform density changes no multiplier "
           "(LP, tilt lambda)", _on(ARCH_COMMANDS, tilt=(_no_ensemble, "an ensemble uses the default density")),
           {"type": float}, group="arch", example="2000"),
    *(Option((f"--pier-{k}",), text, _on(ARCH_COMMANDS + " map") | _on(BLOCK_COMMANDS, _arch, "it sets an arch on "
             "piers, not a --block"), {"type": kind, "metavar": m}, group="piers", example=x) for k, m, kind, x, text in (
        ("height", "H", float, "0.2", "pier height from the ground to the springing line"),
        ("width", "B", float, "0.1", "in-plane pier width, at least the ring thickness plus the offset"),
        ("depth", "D", float, "0.1", "out-of-plane pier depth (default: the arch's width)"),
        ("offset", "O", float, "0", "how far the pier's inner face stands inside the opening beyond the intrados "
                                    f"springing (default {default_of(Piers, 'offset'):g})"),
        ("courses", "N", int, "2", f"courses per pier, 1 to {MAX_COURSES} (default {default_of(Piers, 'courses')})"),
        ("load", "KN", float, "1", f"superimposed load on each pier [kN], 0 to {MAX_PIER_LOAD_KN:g}, e.g. the masonry "
                                   "above: carried as mass at the centre of the pier's top (default 0)"))),
    Option(("--geometry",), "blocks drawn as closed outlines: .dxf (polylines), .csv (block,x,z[,layer]), .obj/.stl "
           f"(convex prisms); at most {MAX_BLOCKS} blocks and {MAX_LENGTH_M:g} m across", _on(ARCH_COMMANDS + " map"),
           {"metavar": "FILE"}, group="drawing", example="arch.dxf"),
    Option(("--units",), f"length unit of the drawing if the file does not state it ({', '.join(UNITS)}; default m)",
           _on(ARCH_COMMANDS + " map", _drawing, "it is a drawing's length unit (--geometry)", shake=(
               lambda a: _drawing(a) or a.record is not None, "it is a drawing's length unit (--geometry) or a "
                                                              "record's (--record)"), record=(None, "")),
           {"metavar": "U", "choices": tuple(UNITS)},
           {"shake": {"choices": (*UNITS, *RECORD_UNITS), "help": "length unit of the drawing if the file does not "
                      f"state it ({', '.join(UNITS)}; default m); with --record, the record's units if its file does "
                      f"not say ({', '.join(RECORD_UNITS)})"},
            "record": {"choices": RECORD_UNITS, "help": "units of the numbers in the file (needed for CSV without units "
                                                        "in its header)"}}, group="drawing", example="mm"),
    Option(("--depth",), "out-of-plane depth of the drawn blocks [m] where the drawing does not state it (archdem "
           "draw: optional, a plane drawing needs none)",
           _on(ARCH_COMMANDS + " map", _drawing, "it is the depth of a drawing's blocks (--geometry)"),
           {"type": float, "metavar": "D"}, group="drawing", example="0.1"),
    Option(("--contact",), "effective contact: every joint touches within its central fraction C of the depth, in "
           "(0, 1]; 'calibrated': from the edge loss fitted to laboratory tilt tests (archdem calibrate); masses stay "
           f"those of the full blocks (default {default_of(discretise, 'contact'):g}: the full joint)",
           _on(ARCH_COMMANDS + " map") | _ARCH_ONLY
           | {"campaign": _steps("catalogue analytic modes tilt map piers shake record", "cuts joints")},
           {"type": contact_option, "metavar": "C|calibrated"},
           {c: {"help": "effective contact of every joint, in (0, 1], or 'calibrated' (archdem calibrate) "
                        "(default {default:g}: the full joint)"} for c in ("map", "campaign")}, example="0.9"),
    Option(("--block",), "a rectangular block of half-width B and half-height H [m] instead of an arch",
           _on(BLOCK_COMMANDS), {"nargs": 2, "type": float, "metavar": ("B", "H")}, example=None),
    Option(("--config",), "discrete configuration: the crown glued or free (default {default})",
           _on("tilt shake threshold analytic mesh draw map", lambda a: not _drawing(a),
               "a drawing's blocks are as drawn, with no glued or free crown")
           | _on("fragility modes", lambda a: _arch(a) and not _drawing(a),
                 "a drawing's blocks are as drawn, and a --block is one block: no glued or free crown")
           | _on("campaign compare-engines compare-shake", domain=_DEM),
           {"choices": ("glued", "free"), "default": default_of(discretise, "config")},
           {"domain": {"help": "DEM: discrete configuration"}}, example="free"),
    Option(("--mu-joint",), "block-block friction (default {default:g})",
           _on("tilt shake threshold analytic", fragility=(_arch, "a --block has no joint between blocks (its "
                                                                   "friction is --mu-base)"), domain=_DEM),
           {"type": friction_option, "default": default_of(Settings, "mu_joint")},
           {"fragility": {"help": "nominal block-block friction (default {default:g})"},
            "analytic": {"default": None, "help": f"block-block friction (default {REFERENCE_MU_JOINT:g})"},
            "domain": {"default": None, "help": f"DEM: block-block friction (default {REFERENCE_MU_JOINT:g})"}},
           example="0.6"),
    Option(("--mu-base",), "block-base friction (default {default:g})",
           _on("tilt shake threshold analytic fragility map", domain=_DEM),
           {"type": friction_option, "default": default_of(Settings, "mu_base")},
           {"fragility": {"help": "nominal block-base friction (default {default:g})"},
            "analytic": {"default": None, "help": f"block-base friction (default {REFERENCE_MU_BASE:g})"},
            "domain": {"default": None, "help": f"DEM: block-base friction (default {REFERENCE_MU_BASE:g})"}},
           example="0.7"),
    Option(("--planar",), "constrain the blocks to the arch plane", _on("shake threshold fragility",
           tilt=_ENSEMBLE_RUNS), {"action": "store_true"}, example=None),
    Option(("--dt",), _DT, _on("shake threshold fragility compare-engines", tilt=_ENSEMBLE_RUNS,
                              domain=(_dem, "it is the DEM's time step (--engine dem or a named engine)")),
           {"type": float}, {"tilt": {"help": f"time step [s] (default {default_of(Settings, 'dt'):g})"},
                             "compare-engines": {"help": f"time step [s] for both engines (default "
                                                         f"{default_of(Settings, 'dt'):g})"},
                             "domain": {"help": "DEM: " + _DT}}, example="2.5e-4"),
    Option(("--engine",), "physics engine (default {default}; see docs/engines.md §5)",
           _on("tilt map shake threshold fragility domain",
               campaign=_steps("tilt lab map piers drawing", "tilts (--dynamics-engine runs the shakes)"),
               assess=(lambda a: bool(a.records), "the engine runs the --records on the DEM")),
           {"choices": tuple(available_engines()), "default": default_of(Settings, "engine")},
           {c: {"default": DYNAMICS_ENGINE} for c in ("shake", "threshold", "fragility", "assess")}
           | {"domain": {"choices": ("analytic", "dem", *available_engines()), "default": "analytic",
                         "help": "analytic linkage, or the DEM: 'dem' runs the shakes' default engine "
                                 f"({DYNAMICS_ENGINE}), or name one"}}, example="pybullet"),
    Option(("--dynamics-engine",), "engine of the shake, record and fragility steps (default {default}; --engine "
           "runs the others)", {"campaign": _steps("shake record fragility", "shakes")},
           {"choices": tuple(available_engines())}, example="pybullet"),
    Option(("--solver-iterations",), f"PyBullet's solver iterations per step (default "
           f"{default_of(PyBulletOptions, 'solver_iterations')})",
           {"fragility": (lambda a: a.engine == "pybullet", "it is PyBullet's solver (--engine pybullet)")},
           {"type": int}, example="50"),
    Option(("--contact-law",), f"joints: as stiff as the engine makes them, or springs (default "
           f"{default_of(Settings, 'contact_law')}; compliant with --kn)", _LAW, {"choices": CONTACT_LAWS}, group="law",
           example="rigid"),
    Option(("--kn",), "normal joint stiffness per unit area [Pa/m] (compliant)", _LAW | _on("modes"),
           {"type": float}, {"modes": {"help": "normal joint stiffness per unit area [Pa/m]"}}, group="law",
           example="1e8"),
    Option(("--youngs",), "or the blocks' Young's modulus [Pa]: kn = E / the blocks' length across their joints",
           _LAW | _on("modes"), {"type": float, "metavar": "E_PA"}, group="law", example="1e9"),
    Option(("--ks",), f"shear joint stiffness per unit area [Pa/m] (modes; default {KS_OVER_KN:.3f} kn)",
           _on(" ".join(_LAW), lambda a: False, "the engines' joints stick rigidly until they slide; shear stiffness "
               "goes to archdem modes") | _on("modes"), {"type": float}, group="law", example="1e8"),
    Option(("--damping-beta",), "stiffness-proportional Rayleigh damping beta_R of the joints [s] "
           f"(default {default_of(Settings, 'damping_beta'):g})", _LAW, {"type": float}, group="law", example="1e-3"),
    Option(("--damping-xi",), f"or the joints' damping ratio at the rotational-impact frequency, 0-{MAX_DAMPING_XI:g}",
           _LAW, {"type": float}, group="law", example="0.5"),
    Option(("--joints",), "the reference study's joints of a catalogue specimen (k_n and beta_R of its Table 5.1)",
           _LAW, {"choices": JOINT_SETS}, group="law", example=STUDY_JOINTS),
    Option(("--workers",), "processes (default: all cores)", _on(
           "map threshold fragility domain compare-shake compare-engines", tilt=(
               lambda a: a.ensemble is not None, "it runs the realisations of an --ensemble N"),
           assess=(lambda a: bool(a.records), "it runs the --records"), campaign=_SWEEPS),
           {"type": workers_option}, {"compare-engines": {"help": "processes (default {default})"}}, example="2"),
    Option(("--scheduler",), "Dask scheduler address tcp://HOST:PORT (instead of local workers)",
           _on("map threshold fragility compare-shake", domain=(
               _dem, "it runs the DEM's domain (--engine dem); the analytic one runs here"), campaign=_SWEEPS),
           example="tcp://127.0.0.1:8786"),
    Option(("--out",), "new study file (default: a new one under runs/)", _on(
           "map fragility compare-shake tilt shake mesh draw campaign calibrate animate"), {"metavar": "STUDY.h5"},
           {"tilt": {"metavar": None, "help": "directory for the result file (default {default})"},
            "shake": {"metavar": None, "help": "directory for the run file (default {default})"},
            "campaign": {"metavar": None, "help": "output directory (resumed if it exists)"},
            "mesh": {"metavar": None, "required": True, "help": "output directory"},
            "draw": {"metavar": None, "required": True, "help": "output image (.png/.pdf/.svg)"},
            "animate": {"metavar": None, "required": True, "help": "FILE.gif or FILE.mp4 (never overwritten)"},
            "calibrate": {"metavar": None, "help": "where to store the calibration (default {default}, read by "
                                                   "--contact calibrated)"}}, example="out.h5"),
    Option(("--resume",), "continue an interrupted study", _on("map fragility compare-shake"), {"metavar": "STUDY.h5"},
           example="s.h5"),
    Option(("--plot",), "figure file (.png/.pdf/.svg)", _on("tilt shake fragility modes domain rock compare-engines map",
           analytic=(lambda a: not _arch_given(a), "it writes the catalogue's figures; give it without an arch")),
           per={"analytic": {"metavar": "DIR", "help": "write the catalogue / full-scale figures to DIR (no arch)"},
                "map": {"metavar": "DIR", "help": "write the map figures (PNG) into DIR"}}, example="f.png"),
    Option(("--json",), "print one JSON object", _on("tilt shake threshold analytic domain rock map fragility modes "
           "assess compare-engines compare-shake record calibrate specimens"), {"action": "store_true"},
           {"specimens": {"help": "print a JSON list"}}, example=None),
)
#: The table by destination.
TABLE: dict[str, Option] = {o.dest: o for o in OPTIONS}
#: The options of an arch: its id or parameters, piers, drawing and contact.
ARCH_OPTIONS = tuple(o.dest for o in OPTIONS if o.group in ("arch", "piers", "drawing") or o.dest in ("id", "contact"))
_GROUPS = {"arch": f"arch by parameters (instead of an id; SI units, m; lengths {MIN_LENGTH_M:g} to {MAX_LENGTH_M:g} m)",
           "piers": "piers (the arch on two equal piers instead of the rigid base; lengths in m)",
           "drawing": "a structure from a drawing instead (docs/physics/geometry.md#16-assemblies-from-drawings)",
           "law": "the joints' contact law"}


def options_of(command: str) -> list[Option]:
    """The table's options of ``command``, in the table's order."""
    return [o for o in OPTIONS if command in o.where]


def add_options(p: argparse.ArgumentParser, command: str, *dests: str, **defaults: Any) -> None:
    """Add the table's options of ``command`` to ``p`` (only ``dests`` when given); ``defaults``: a
    default by destination from the command's own library object (its experiment's function)."""
    groups: dict[str, Any] = {}
    for o in options_of(command):
        if dests and o.dest not in dests:
            continue
        kw = {"default": None, **o.kw, **o.per.get(command, {})}
        kw["default"] = defaults.get(o.dest, kw["default"])
        if "{default" in (text := kw.get("help", o.help)):
            text = text.format(default=kw["default"])
        kw["help"] = text
        if kw.get("action") == "store_true" or o.flags == ("id",):
            kw.pop("default")
        if o.group and o.group not in groups:
            groups[o.group] = p.add_argument_group(_GROUPS[o.group])
        groups.get(o.group, p).add_argument(*o.flags, **kw)


def refuse_unused(args: argparse.Namespace) -> None:
    """The table's rule: an option given by hand where its condition does not hold is refused in one
    line naming the option and what it belongs to."""
    mine = given(args)
    for o in options_of(getattr(args, "command", "")):
        cond, why = o.where[args.command]
        if cond is not None and o.dest in mine:
            option_used(args, o.dest, cond(args), why)
