"""The ``archdem`` command-line program.

Each sub-command lives in a module named after it, beside its experiment (``dem/experiments/NAME/``)
or here for the commands that are no experiment, and exposes ``register(subparsers)``; the module adds its parser and sets ``func`` (a
callable taking the parsed namespace and returning an exit code).
Bad input raises :class:`foundation.errors.ArchdemInputError`, which becomes one
line on stderr and exit code 2.
"""
from __future__ import annotations

import argparse
import os
import select
import sys
from importlib.metadata import version

# a Ctrl-C while the program starts (about a second of imports) ends it in one line, not a traceback:
# nothing has begun yet (docs/decisions/010-input-rules.md#interruption)
try:
    from dem.campaign import campaign_cmd
    from dem.cli import analytic_cmd, draw_cmd, mesh_cmd, rock_cmd, specimens_cmd
    from dem.common.options import common_rules, restore_study
    from dem.experiments.contract import resolve
    from dem.experiments.registry import commands as experiment_commands
    from foundation.errors import ArchdemInputError
    from foundation.processes import stop_signals

    # The sub-command modules, in the order they appear in ``archdem --help``: those that are no experiment,
    # then each experiment's, as the registry lists them (docs/architecture.md#the-experiment-contract).
    _COMMANDS = [specimens_cmd, mesh_cmd, draw_cmd, analytic_cmd, rock_cmd, campaign_cmd,
                 *(resolve(m) for m in experiment_commands())]
except KeyboardInterrupt:
    print("archdem: interrupted", file=sys.stderr)
    raise SystemExit(130) from None


class _Parser(argparse.ArgumentParser):
    """argparse that reports usage errors in one line with exit code 2, and takes no abbreviation: an
    option a command does not have (``--engine`` beside ``--engines``, ``--e`` beside ``--experiments``)
    is refused, not read as another one."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **{"allow_abbrev": False, **kwargs})

    def error(self, message: str) -> None:  # pragma: no cover - argparse hook
        self.exit(2, f"archdem: error: {message}\n")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="archdem", description=__doc__.splitlines()[0])

    parser.add_argument("--version", action="version", version=f"archdem {version('archdem')}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    for command in _COMMANDS:
        command.register(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        parser = build_parser()
        args = parser.parse_args(argv)
    except SystemExit as exc:  # a usage error (one line, code 2) or --help / --version (code 0)
        return int(exc.code or 0)
    except KeyboardInterrupt:  # while the parser is built (the commands' modules): nothing has begun
        print("archdem: interrupted", file=sys.stderr)
        return 130
    # SIGTERM (timeout, a service manager) stops a command as Ctrl-C does, with the same cleanup;
    # the exit code tells them apart: 130 for Ctrl-C, 143 for SIGTERM (docs/decisions/010-input-rules.md)
    with stop_signals() as stop:
        try:
            args.given = given_options(parser, argv, args.command)
            if getattr(args, "resume", None):
                restore_study(args)
            common_rules(args)
            code = int(args.func(args) or 0)
            # a reader that went away shows here, not at exit (where Python 3.13 exits with 120)
            sys.stdout.flush()
            return stop.exit_code if stop.signum else code  # the command said "interrupted" itself
        except ArchdemInputError as exc:
            print(f"archdem: error: {exc}", file=sys.stderr)
            return 2
        except KeyboardInterrupt:
            print("archdem: interrupted", file=sys.stderr)
            return stop.exit_code if stop.signum else 130
        except BrokenPipeError:
            if not _stdout_gone():
                raise  # a pipe of our own (e.g. to a worker) broke: that is a failure, not a closed reader
            # the reader of our output went away (e.g. | head): no traceback, and none at exit either
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            return 1
        except Exception:
            if not stop.signum:
                raise
            # the stop's exception, wrapped by the code it interrupted (an import's class __set_name__)
            print("archdem: interrupted", file=sys.stderr)
            return stop.exit_code


def given_options(parser: argparse.ArgumentParser, argv: list[str], command: str) -> frozenset[str]:
    """The destinations ``argv`` sets explicitly (a default given by hand counts): the command's
    options parsed again with every default suppressed."""
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction)).choices[command]
    saved = [(a, a.default) for a in sub._actions]
    try:
        for a, _ in saved:
            a.default = argparse.SUPPRESS
        ns, _ = sub.parse_known_args(argv[argv.index(command) + 1:])
    finally:
        for a, d in saved:
            a.default = d
    return frozenset(vars(ns)) - {"func"}


def _stdout_gone() -> bool:
    """Whether standard output is a pipe whose reader has closed it."""
    try:
        poller = select.poll()
        poller.register(sys.stdout.fileno(), select.POLLOUT)
        return any(ev & select.POLLERR for _, ev in poller.poll(0))
    except (OSError, ValueError, AttributeError):  # no file descriptor (e.g. captured output)
        return False


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
