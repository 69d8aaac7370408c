"""Helpers shared by the sub-commands: arch selection, JSON output, output paths."""
from __future__ import annotations

import argparse
import dataclasses
import inspect
import json
import math
import os
import sys
from pathlib import Path
from typing import Any

from dem.common.joints import CALIBRATED, JOINT_SETS, STUDY_JOINTS, contact_fraction, joint_law
from dem.core.engines import available_engines
from dem.core.settings import CONTACT_LAWS, DYNAMICS_DT, DYNAMICS_ENGINE, MAX_DAMPING_XI, Settings
from specimens.blocks import DEFAULT_DENSITY, DEFAULT_VOUSSOIRS, check_contact, discretise
from specimens.catalogue import SPECIMEN_WIDTH, get_specimen
from specimens.constants import DRAWN_DENSITY, MAX_LENGTH_M, MIN_LENGTH_M  # lengths an option takes [m]
from specimens.drawn import DRAWN_CONFIG, MAX_BLOCKS, DrawnAssembly, gaps_text
from foundation.errors import ArchdemInputError
from specimens.exchange import UNITS, read_assembly
from specimens.geometry import PointedArch
from foundation.io import can_make_dir, check_name, json_default, unique_run_path, writable_dir, writable_file  # noqa: F401 (the CLI modules import them from here)
from foundation.io import parse_grid as _parse_grid
from specimens.piers import MAX_COURSES, Piers

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


def add_arch_arguments(p: argparse.ArgumentParser, id_required: bool = False) -> None:
    """Arch by catalogue id (positional) or by parameters."""
    p.add_argument("id", nargs=None if id_required else "?", help="specimen id (see `archdem specimens`)")
    g = p.add_argument_group(f"arch by parameters (instead of an id; SI units, m; lengths {MIN_LENGTH_M:g} to "
                                f"{MAX_LENGTH_M:g} m)")
    for name in ("Ri", "Re", "e", "Sh", "Sd", "Rc"):
        g.add_argument(f"--{name}", type=float, default=None)
    g.add_argument("--width", type=float, default=None,
                   help=f"out-of-plane width [m] (default: the specimen's, else {SPECIMEN_WIDTH:g})")
    g.add_argument("--voussoirs", type=int, default=None,
                   help=f"voussoirs per side, 1 to {MAX_VOUSSOIRS} (default {DEFAULT_VOUSSOIRS})")
    g.add_argument("--density", type=float, default=None,
                   help=f"density [kg/m^3], {DENSITY_RANGE[0]:g} to {DENSITY_RANGE[1]:g} (default {DEFAULT_DENSITY:g}) "
                        f"of the specimens' aerated concrete; a drawing's: the one its file states, else "
                        f"{DRAWN_DENSITY:g}, masonry. Masses and forces scale with it; a uniform density changes no "
                        "multiplier (LP, tilt lambda)")
    add_pier_arguments(p)
    add_geometry_arguments(p)
    p.add_argument("--contact", type=contact_option, default=None, metavar="C|calibrated",
                   help="effective contact: every joint touches within its central fraction C of the depth, "
                        "in (0, 1]; 'calibrated': from the edge loss fitted to laboratory tilt tests "
                        "(archdem calibrate); masses stay those of the full blocks "
                        f"(default {default_of(discretise, 'contact'):g}: the full joint)")


def add_geometry_arguments(p: argparse.ArgumentParser) -> None:
    """``--geometry FILE --units U --depth D`` (see :func:`specimens.exchange.read_assembly`); ``--density``
    is the arch's option (read by :func:`geometry_from_args` where the command has it)."""
    g = p.add_argument_group("a structure from a drawing instead (docs/physics/geometry.md#16-assemblies-from-drawings)")
    g.add_argument("--geometry", default=None, metavar="FILE",
                   help="blocks drawn as closed outlines: .dxf (polylines), .csv (block,x,z[,layer]), .obj/.stl (convex prisms); "
                        f"at most {MAX_BLOCKS} blocks and {MAX_LENGTH_M:g} m across")
    g.add_argument("--units", default=None, metavar="U",
                   help=f"length unit of the drawing if the file does not state it ({', '.join(UNITS)}; default m); "
                        "with --record, the record's units if its file does not say (g, m/s2, cm/s2, mm/s2)")
    g.add_argument("--depth", type=float, default=None, metavar="D",
                   help="out-of-plane depth of the drawn blocks [m] where the drawing does not state it "
                        "(archdem draw: optional, a plane drawing needs none)")


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


def add_pier_arguments(p: argparse.ArgumentParser) -> None:
    """The ``--pier-*`` options (see :func:`piers_from_args`)."""
    g = p.add_argument_group("piers (the arch on two equal piers instead of the rigid base; lengths in m)")
    g.add_argument("--pier-height", type=float, default=None, metavar="H",
                   help="pier height from the ground to the springing line")
    g.add_argument("--pier-width", type=float, default=None, metavar="B",
                   help="in-plane pier width, at least the ring thickness plus the offset")
    g.add_argument("--pier-depth", type=float, default=None, metavar="D",
                   help="out-of-plane pier depth (default: the arch's width)")
    g.add_argument("--pier-offset", type=float, default=None, metavar="O",
                   help="how far the pier's inner face stands inside the opening beyond the intrados springing "
                        f"(default {default_of(Piers, 'offset'):g})")
    g.add_argument("--pier-courses", type=int, default=None, metavar="N",
                   help=f"courses per pier, 1 to {MAX_COURSES} (default {default_of(Piers, 'courses')})")
    g.add_argument("--pier-load", type=float, default=None, metavar="KN",
                   help=f"superimposed load on each pier [kN], 0 to {MAX_PIER_LOAD_KN:g}, e.g. the masonry above: "
                        "carried as mass at the centre of the pier's top (default 0)")


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
    """``(B, H)`` [m] of ``--block`` (half-width, half-height) when given; refused beside an arch, its
    piers or its contact; with neither a block nor an arch, one line asking for one."""
    arch_given = args.id is not None or any(getattr(args, k, None) is not None for k in ("Ri", "Re", "e", "Sh", "Sd", "Rc",
                                                                                        "geometry"))
    if args.block is None:
        if not arch_given:
            raise ArchdemInputError("give a specimen id, the arch parameters or --block B H")
        return None
    if arch_given:
        raise ArchdemInputError("give either --block B H or an arch, not both")
    if piers_from_args(args) is not None or getattr(args, "contact", None) is not None:
        raise ArchdemInputError("--pier-* and --contact belong to an arch, not to --block")
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

    if not os.path.isfile(args.resume):
        return  # study_path refuses it in its words
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


def add_friction_arguments(p: argparse.ArgumentParser, what: str = "") -> None:
    """``--mu-joint`` and ``--mu-base`` with the settings' defaults."""
    for name, text in (("mu_joint", "block-block"), ("mu_base", "block-base")):
        p.add_argument(f"--{name.replace('_', '-')}", dest=name, type=float, default=default_of(Settings, name),
                       help=f"{what}{text} friction (default {default_of(Settings, name):g})")


def print_json(obj: Any) -> None:
    print(json.dumps(obj, indent=2, default=json_default, allow_nan=True))


def add_engine_argument(p: argparse.ArgumentParser, dynamics: bool = False) -> None:
    """``--engine pybullet|mujoco|lmgc90`` (the physics backend of the simulator); its default is the
    statics' (:class:`Settings`), or with ``dynamics`` the shakes' (:data:`DYNAMICS_ENGINE`)."""
    engine = DYNAMICS_ENGINE if dynamics else default_of(Settings, "engine")
    p.add_argument("--engine", choices=tuple(available_engines()), default=engine,
                   help=f"physics engine (default {engine}; see docs/engines.md §5)")


def add_dynamics_dt_argument(p: argparse.ArgumentParser, prefix: str = "") -> None:
    """``--dt`` of a dynamic command: :data:`DYNAMICS_DT` on the shakes' engine, the protocol's step on
    the others (:func:`dem.core.settings.dynamics_settings`)."""
    p.add_argument("--dt", type=float, default=None,
                   help=f"{prefix}time step [s] (default {DYNAMICS_DT:g} on {DYNAMICS_ENGINE}, "
                        f"{default_of(Settings, 'dt'):g} on the other engines)")


def parse_grid(text: str, what: str = "--freq") -> list[float]:
    """A grid option: :func:`foundation.io.parse_grid` (one parser for every command)."""
    return _parse_grid(text, what)


#: The destinations of :func:`add_contact_law_arguments`.
CONTACT_LAW_DESTS = ("contact_law", "kn", "youngs", "ks", "damping_beta", "damping_xi", "joints")


def add_contact_law_arguments(p: argparse.ArgumentParser) -> None:
    """``--contact-law rigid|compliant --kn --damping-beta|--damping-xi`` and ``--joints table-5.1``."""
    law = default_of(Settings, "contact_law")
    p.add_argument("--contact-law", dest="contact_law", choices=CONTACT_LAWS, default=None,
                   help=f"joints: as stiff as the engine makes them, or springs (default {law}; compliant with --kn)")
    p.add_argument("--kn", type=float, default=None, help="normal joint stiffness per unit area [Pa/m] (compliant)")
    p.add_argument("--youngs", type=float, default=None, metavar="E_PA",
                   help="or the blocks' Young's modulus [Pa]: kn = E / the blocks' length across their joints")
    p.add_argument("--ks", type=float, default=None, help="not taken: the engines' joints stick rigidly until they slide")
    p.add_argument("--damping-beta", dest="damping_beta", type=float, default=None,
                   help="stiffness-proportional Rayleigh damping beta_R of the joints [s] "
                        f"(default {default_of(Settings, 'damping_beta'):g})")
    p.add_argument("--damping-xi", dest="damping_xi", type=float, default=None,
                   help=f"or the joints' damping ratio at the rotational-impact frequency, 0-{MAX_DAMPING_XI:g}")
    p.add_argument("--joints", choices=JOINT_SETS, default=None,
                   help="the reference study's joints of a catalogue specimen (k_n and beta_R of its Table 5.1)")


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
    command line adds only what is its own: --ks, --joints beside the other options, and the law
    implied by --kn/--youngs/--damping-* without --contact-law."""
    kn, youngs, beta, xi = (getattr(args, k, None) for k in ("kn", "youngs", "damping_beta", "damping_xi"))
    law = getattr(args, "contact_law", None)
    if getattr(args, "ks", None) is not None:
        raise ArchdemInputError("--ks: the engines' joints stick rigidly until they slide; shear stiffness goes to "
                                "archdem modes")
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
