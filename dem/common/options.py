"""What the sub-commands share: the option table (every shared option declared once, with where it
applies), the arch options as a :class:`~dem.common.request.ArchRequest`, JSON output, output paths."""
from __future__ import annotations

import argparse
import dataclasses
import json
import math
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

from analytic.compliant.modes import KS_OVER_KN
from analytic.motions.records import UNIT_FACTORS
from dem.common.figures import figure_file  # noqa: F401 (the CLI modules import it from here)
from dem.common.joints import CALIBRATED, JOINT_SETS, STUDY_JOINTS, joint_law_settings
from dem.common.request import ArchRequest
from dem.core.engines import available_engines
from dem.core.engines.options import PyBulletOptions
from dem.core.settings import CONTACT_LAWS, DYNAMICS_DT, DYNAMICS_ENGINE, Settings
from dem.studies.files import resumed_study
from foundation.errors import ArchdemInputError
from foundation.fields import default_of, option_help  # noqa: F401 (the CLI modules import default_of from here)
from foundation.io import can_make_dir, json_default, writable_dir, writable_file  # noqa: F401 (the CLI modules import them from here)
from specimens.blocks import check_contact, discretise
from specimens.constants import MAX_LENGTH_M, MIN_LENGTH_M  # lengths an option takes [m]
from specimens.drawn import DRAWN_CONFIG
from specimens.exchange import UNITS

#: The units of a record's numbers (archdem shake --record --units).
RECORD_UNITS = tuple(UNIT_FACTORS)


def arch_request(args: argparse.Namespace) -> ArchRequest:
    """The :class:`~dem.common.request.ArchRequest` of the arch options (checked); with ``--geometry`` the
    command's configuration becomes :data:`~specimens.drawn.DRAWN_CONFIG` (a drawing's bodies are as drawn)
    in its output and file names."""
    req = ArchRequest.from_namespace(args)
    if req.geometry is not None:
        option_used(args, "config", False, "a drawing's blocks are as drawn, with no glued or free crown")
        if hasattr(args, "config"):
            args.config = DRAWN_CONFIG
    return req


#: Most local worker processes a command starts.
MAX_WORKERS = 256


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
        return check_contact(float(text))  # the library's rule; its refusal (a ValueError) in the option's words
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a fraction in (0, 1] or '{CALIBRATED}', got {text!r}") from None


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
    # the file checked before any option the study would have given is missed
    stored = stored_definition(resumed_study(args.resume))
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


def answer(as_json: bool, obj: Any, lines: Iterable[str]) -> None:
    """A command's answer: ``obj`` as JSON (``--json``), otherwise its ``lines`` of text."""
    print_json(obj) if as_json else print("\n".join(lines))


def settings_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    """The :class:`Settings` fields of a simulating command's options: frictions, engine, the plane, the
    step and the joint law (``--joints table-5.1`` of the specimen id)."""
    kw = {"mu_joint": args.mu_joint, "mu_base": args.mu_base, "planar": bool(args.planar), "engine": args.engine,
          **contact_law_settings(args, getattr(args, "id", None))}
    return kw | ({"dt": args.dt} if args.dt is not None else {})


def contact_law_settings(args: argparse.Namespace, specimen_id: str | None) -> dict[str, Any]:
    """:func:`dem.common.joints.joint_law_settings` of the joint-law options and the engines of ``args``."""
    law = (getattr(args, k, None) for k in ("contact_law", "kn", "youngs", "damping_beta", "damping_xi", "joints"))
    return joint_law_settings(*law, specimen_id, (getattr(args, "engine", None), getattr(args, "dynamics_engine", None)))


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
    """One command-line option, declared once: its flags, its help (the library field ``(cls, name)`` whose
    metadata holds it, :func:`~foundation.fields.option_help`, or a text whose ``{default}`` is the
    command's), argparse keywords (``type`` is its one validator where the library has none of its own; a
    default only from a library object; ``shown``: the default its help says), ``where``: per command,
    the condition under which it does something and what it belongs to otherwise, and ``per``: a
    command's own keywords (help, choices, default, shown)."""

    flags: tuple[str, ...]
    help: str | tuple[type, str]
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
_SWEEPS = _steps("tilt lab map piers shake record fragility mode-map", "runs a sweep")
#: The default the dynamic commands' --dt help says: the dynamics engine's step, else the field's.
_DT = f"{DYNAMICS_DT:g} on {DYNAMICS_ENGINE}, {default_of(Settings, 'dt'):g} on the other engines"
_A, _S = ArchRequest, Settings  # the library objects whose fields' metadata hold the options' help

OPTIONS: tuple[Option, ...] = (
    Option(("id",), (_A, "id"), _on(ARCH_COMMANDS), {"nargs": "?"}, example="Sh02-Sd020"),
    *(Option((f"--{k}",), "", _on(ARCH_COMMANDS), {"type": float}, group="arch", example="0.2") for k in ARCH_PARAMETERS),
    Option(("--width",), (_A, "width"), _on(ARCH_COMMANDS), {"type": float}, group="arch", example="0.2"),
    Option(("--voussoirs",), (_A, "voussoirs"), _on(ARCH_COMMANDS) | _ARCH_ONLY, {"type": int}, group="arch",
           example="4"),
    Option(("--density",), (_A, "density"), _on(ARCH_COMMANDS, tilt=(_no_ensemble, "an ensemble uses the default "
                                                                       "density")), {"type": float}, group="arch",
           example="2000"),
    *(Option((f"--pier-{k}",), (_A, f"pier_{k}"), _on(ARCH_COMMANDS + " map") | _on(BLOCK_COMMANDS, _arch, "it sets "
             "an arch on piers, not a --block"), {"type": kind, "metavar": m}, group="piers", example=x)
      for k, m, kind, x in (("height", "H", float, "0.2"), ("width", "B", float, "0.1"), ("depth", "D", float, "0.1"),
                            ("offset", "O", float, "0"), ("courses", "N", int, "2"), ("load", "KN", float, "1"))),
    Option(("--geometry",), (_A, "geometry"), _on(ARCH_COMMANDS + " map"), {"metavar": "FILE"}, group="drawing",
           example="arch.dxf"),
    Option(("--units",), (_A, "units"),
           _on(ARCH_COMMANDS + " map", _drawing, "it is a drawing's length unit (--geometry)", shake=(
               lambda a: _drawing(a) or a.record is not None, "it is a drawing's length unit (--geometry) or a "
                                                              "record's (--record)"), record=(None, "")),
           {"metavar": "U", "choices": tuple(UNITS)},
           {"shake": {"choices": (*UNITS, *RECORD_UNITS), "help": "length unit of the drawing if the file does not "
                      f"state it ({', '.join(UNITS)}; default m); with --record, the record's units if its file does "
                      f"not say ({', '.join(RECORD_UNITS)})"},
            "record": {"choices": RECORD_UNITS, "help": "units of the numbers in the file (needed for CSV without units "
                                                        "in its header)"}}, group="drawing", example="mm"),
    Option(("--depth",), (_A, "depth"), _on(ARCH_COMMANDS + " map", _drawing, "it is the depth of a drawing's blocks "
                                                                                "(--geometry)"),
           {"type": float, "metavar": "D"}, group="drawing", example="0.1"),
    Option(("--contact",), (_A, "contact"), _on(ARCH_COMMANDS + " map") | _ARCH_ONLY
           | {"campaign": _steps("catalogue analytic modes tilt map piers shake record mode-map", "cuts joints")},
           {"type": contact_option, "metavar": "C|calibrated"},
           {c: {"help": "effective contact of every joint, in (0, 1], or 'calibrated' (archdem calibrate)"}
            for c in ("map", "campaign")}, example="0.9"),
    Option(("--block",), (_A, "block"), _on(BLOCK_COMMANDS), {"nargs": 2, "type": float, "metavar": ("B", "H")},
           example=None),
    Option(("--config",), "discrete configuration: the crown glued or free (default {default})",
           _on("tilt shake threshold analytic mesh draw map", lambda a: not _drawing(a),
               "a drawing's blocks are as drawn, with no glued or free crown")
           | _on("fragility modes", lambda a: _arch(a) and not _drawing(a),
                 "a drawing's blocks are as drawn, and a --block is one block: no glued or free crown")
           | _on("campaign compare-engines compare-shake", domain=_DEM),
           {"choices": ("glued", "free"), "default": default_of(discretise, "config")},
           {"domain": {"help": "DEM: discrete configuration"}}, example="free"),
    *(Option((f"--mu-{k}",), (_S, f"mu_{k}"), where, {"type": friction_option, "default": default_of(Settings, f"mu_{k}")},
             {"fragility": {"help": f"nominal block-{on} friction"}, "analytic": {"default": None},
              "domain": {"default": None, "help": f"DEM: block-{on} friction"}}, example=x)
      for k, on, where, x in (("joint", "block", _on("tilt shake threshold analytic", domain=_DEM, fragility=(
          _arch, "a --block has no joint between blocks (its friction is --mu-base)")), "0.6"),
          ("base", "base", _on("tilt shake threshold analytic fragility map", domain=_DEM), "0.7"))),
    Option(("--planar",), (_S, "planar"), _on("shake threshold fragility", tilt=_ENSEMBLE_RUNS),
           {"action": "store_true"}, example=None),
    Option(("--dt",), (_S, "dt"), _on("shake threshold fragility compare-engines", tilt=_ENSEMBLE_RUNS,
                                      domain=(_dem, "it is the DEM's time step (--engine dem or a named engine)")),
           {"type": float}, {c: {"shown": _DT} for c in ("shake", "threshold", "fragility")}
           | {"compare-engines": {"help": "time step for both engines"}, "domain": {"help": "DEM: time step", "shown": _DT}},
           example="2.5e-4"),
    Option(("--engine",), (_S, "engine"), _on("tilt map shake threshold fragility domain",
           campaign=_steps("tilt lab map piers drawing", "tilts (--dynamics-engine runs the shakes)"),
           assess=(lambda a: bool(a.records), "the engine runs the --records on the DEM")),
           {"choices": tuple(available_engines()), "default": default_of(Settings, "engine")},
           {c: {"default": DYNAMICS_ENGINE} for c in ("shake", "threshold", "fragility", "assess")}
           | {"domain": {"choices": ("analytic", "dem", *available_engines()), "default": "analytic", "shown": None,
                         "help": "analytic linkage, or the DEM: 'dem' runs the shakes' default engine "
                                 f"({DYNAMICS_ENGINE}), or name one"}}, example="pybullet"),
    Option(("--dynamics-engine",), "engine of the shake, record and fragility steps (default {default}; --engine "
           "runs the others)", {"campaign": _steps("shake record fragility", "shakes")},
           {"choices": tuple(available_engines())}, example="pybullet"),
    Option(("--solver-iterations",), (PyBulletOptions, "solver_iterations"),
           {"fragility": (lambda a: a.engine == "pybullet", "it is PyBullet's solver (--engine pybullet)")},
           {"type": int}, example="50"),
    Option(("--contact-law",), (_S, "contact_law"), _LAW, {"choices": CONTACT_LAWS}, group="law", example="rigid"),
    Option(("--kn",), (_S, "kn"), _LAW | _on("modes"), {"type": float}, {"modes": {
           "help": "normal joint stiffness per unit area"}}, group="law", example="1e8"),
    Option(("--youngs",), (_S, "youngs"), _LAW | _on("modes"), {"type": float, "metavar": "E_PA"}, group="law",
           example="1e9"),
    Option(("--ks",), f"shear joint stiffness per unit area [Pa/m] (modes; default {KS_OVER_KN:.3f} kn)",
           _on(" ".join(_LAW), lambda a: False, "the engines' joints stick rigidly until they slide; shear stiffness "
               "goes to archdem modes") | _on("modes"), {"type": float}, group="law", example="1e8"),
    Option(("--damping-beta",), (_S, "damping_beta"), _LAW, {"type": float}, group="law", example="1e-3"),
    Option(("--damping-xi",), (_S, "damping_xi"), _LAW, {"type": float}, group="law", example="0.5"),
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
    Option(("--no-check",), "skip the settled-or-range check (the bracket rerun at half the step, and on LMGC90 at "
           "6-8 Hz with sliding joints)", _on("threshold", domain=(_dem, "it checks the DEM's thresholds (--engine dem)")),
           {"action": "store_true"}, {"domain": {"help": "DEM: skip the settled-or-range check of each threshold (the "
                                                         "bracket rerun at half the step, and on LMGC90 at 6-8 Hz with "
                                                         "sliding joints)"}}, example=None),
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
        if isinstance(o.help, str):
            text = kw.get("help", o.help)
            kw["help"] = text.format(default=kw["default"]) if "{default" in text else text
        else:  # the field's help; the default said: the command's, else the library's (none for a flag)
            f = next(f for f in dataclasses.fields(o.help[0]) if f.name == o.help[1])
            meta = {**f.metadata, **{k: kw.pop(k) for k in ("help", "shown") if k in kw}}
            meta |= {"shown": None} if kw.get("action") == "store_true" else {}
            kw["help"] = option_help(meta, f.default if kw["default"] is None else kw["default"])
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
