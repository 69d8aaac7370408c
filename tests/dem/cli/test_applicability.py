"""Every (command, option) pair of the option table, in a plain context and in the contexts that flip
its condition: the option is applied (its parsed value reaches what it configures) or refused with
exit code 2 in one line naming it. Only parsing and the options' resolution run, no simulation."""
import argparse
import functools

import pytest

from dem.cli import build_parser, main
from dem.common.options import OPTIONS, TABLE, option_name, refuse_unused, settings_kwargs
from dem.common.request import ArchRequest
from dem.experiments.contract import given_options

# A plain command line of each command of the table.
PLAIN = {
    "tilt": ["Sh02-Sd015"], "shake": ["Sh02-Sd015", "--sine", "4", "--amplitude", "0.3"],
    "threshold": ["Sh02-Sd015", "--sine", "4"], "analytic": ["Sh02-Sd015"], "domain": ["Sh02-Sd015"],
    "rock": ["Sh02-Sd015", "--freq", "4", "--amplitude", "0.5"], "mesh": ["Sh02-Sd015", "--out", "m"],
    "draw": ["Sh02-Sd015", "--out", "d.png"], "assess": ["Sh02-Sd015", "--spectrum", "ec8", "--ag", "0.2"],
    "fragility": ["Sh02-Sd015", "--sine", "2", "--amplitudes", "0.3", "--realizations", "1"],
    "modes": ["Sh02-Sd015", "--kn", "1e8"], "map": ["--specimens", "Sh02-Sd015"], "campaign": [],
    "compare-engines": [], "compare-shake": [], "record": ["f.AT2"], "calibrate": [],
    "animate": ["run.h5", "--out", "a.gif"], "specimens": [],
}
# Other contexts, each changing what the options apply to (a block, the DEM's domain, an ensemble,
# records, a drawing, a campaign of named steps, the catalogue's figures).
CONTEXTS = {
    "fragility": [["--block", "0.05", "0.2", "--sine", "2", "--amplitudes", "0.3", "--realizations", "1"],
                  PLAIN["fragility"] + ["--engine", "pybullet"]],
    "modes": [["--block", "0.05", "0.2", "--kn", "1e8"]],
    "rock": [["--block", "0.05", "0.2", "--freq", "4", "--amplitude", "0.5"]],
    "domain": [["Sh02-Sd015", "--engine", "dem"]],
    "tilt": [["Sh02-Sd015", "--ensemble", "2", "--seed", "1"], ["--geometry", "arch.dxf"]],
    "shake": [PLAIN["shake"][1:] + ["--geometry", "arch.dxf"], ["Sh02-Sd015", "--record", "r.AT2", "--scale", "1"]],
    "assess": [PLAIN["assess"] + ["--records", "r.AT2"]],
    "campaign": [["--steps", "catalogue"], ["--steps", "analytic", "--fragility"]],
    "analytic": [[]],
    "map": [["--geometry", "arch.dxf"]],
}
CASES = [(c, o.dest, k) for o in OPTIONS for c in o.where for k in range(1 + len(CONTEXTS.get(c, [])))]


@functools.cache
def _parser() -> argparse.ArgumentParser:
    return build_parser()


def _argv(command: str, dest: str, k: int) -> list[str]:
    base = ([PLAIN[command]] + CONTEXTS.get(command, []))[k]
    o = TABLE[dest]
    if dest == "id":  # the positional: a context with an id gives it, the others get one
        return [command] + (base if base[:1] == ["Sh02-Sd015"] else ["Sh02-Sd015"] + base)
    if o.example is None:
        return [command] + base + [o.flags[0]] + (["0.05", "0.2"] if dest == "block" else [])
    choices = o.per.get(command, {}).get("choices") or o.kw.get("choices") or (o.example,)
    return [command] + base + [o.flags[0], o.example if o.example in choices else choices[0]]


def _parsed(argv: list[str]) -> argparse.Namespace:
    args = _parser().parse_args(argv)
    args.given = given_options(_parser(), argv, argv[0])
    return args


def _applies(command: str, dest: str, args: argparse.Namespace) -> bool:
    cond, _ = TABLE[dest].where[command]
    return cond is None or cond(args)


def _reaches(command: str, dest: str, args: argparse.Namespace) -> None:
    """The value reaches what it configures: the simulator's settings, the arch's blocks, or the
    command's own reading of it."""
    v = getattr(args, dest)
    assert v is not None and v is not False, dest
    # compliant joints on the shakes' MuJoCo need damping besides: their stiffness is checked on tilt's engine
    if command in ("tilt", "shake", "threshold", "fragility") and dest in ("mu_joint", "mu_base", "engine", "dt",
                                                                              "planar") + ("kn", "youngs") * (command == "tilt"):
        assert settings_kwargs(args)[dest] == v
    if dest in ("voussoirs", "density", "contact") and command in PLAIN and getattr(args, "geometry", 0) is None \
            and getattr(args, "block", None) is None:
        kw = ArchRequest.from_namespace(args).discretise_kwargs()
        assert kw[{"voussoirs": "n_voussoirs"}.get(dest, dest)] == v


@pytest.mark.parametrize("command, dest, k", CASES)
def test_each_option_is_applied_or_refused(command, dest, k, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    argv = _argv(command, dest, k)
    args = _parsed(argv)
    if _applies(command, dest, args):
        refuse_unused(args)  # not refused
        _reaches(command, dest, args)
        return
    monkeypatch.setattr("dem.cli.build_parser", _parser)  # one parser for the walk: its defaults are restored
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{option_name(dest)} does nothing here: " in err, err


def test_every_option_of_a_command_comes_from_the_table_once():
    """The table's options of a command are defined once in it: no command adds one of them itself."""
    subs = next(a for a in _parser()._actions if isinstance(a, argparse._SubParsersAction)).choices
    for command, p in subs.items():
        dests = [a.dest for a in p._actions if a.dest != "help"]
        assert len(dests) == len(set(dests)), command
        for dest in dests:
            if dest in TABLE and command in PLAIN:
                assert command in TABLE[dest].where, f"{command} defines {dest} outside the table"


def test_the_contexts_flip_conditions():
    """The walk is not vacuous: it holds applied pairs and refused pairs, the latter for every condition kind."""
    refused = {(c, d) for c, d, k in CASES if not _applies(c, d, _parsed(_argv(c, d, k)))}
    assert {("fragility", "mu_joint"), ("fragility", "config"), ("fragility", "solver_iterations"),
            ("tilt", "units"), ("shake", "depth"), ("analytic", "plot"), ("domain", "mu_joint"),
            ("campaign", "dynamics_engine"), ("campaign", "workers"), ("tilt", "workers"),
            ("assess", "engine")} <= refused
    assert len(refused) < len({(c, d) for c, d, _ in CASES})


@pytest.mark.parametrize("argv, msg", [
    (["map", "--mu", "0.5", "--refine", "2"], "--refine does nothing here"),
    (["rock", "Sh02-Sd020", "--model", "two-bar", "--layout", "minimised", "--freq", "4", "--amplitude", "0.5"],
     "--layout does nothing here"),
    (["rock", "--block", "0.05", "0.2", "--layout", "minimised", "--freq", "4", "--amplitude", "0.5"],
     "--layout does nothing here"),
    (["assess", "Sh02-Sd020", "--spectrum", "ec8", "--ag", "0.2", "--limit-state", "SLD", "--q", "3"],
     "--q does nothing here"),
    (["tilt", "Sh02-Sd020", "--geometry", "a.dxf", "--units", "parsec"], "argument --units: invalid choice"),
])
def test_the_commands_own_options_that_do_nothing(argv, msg, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and msg in err, err
