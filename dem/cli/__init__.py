"""The ``archdem`` command-line program.

Its sub-commands, those that are no experiment then every experiment's as the registry lists them, each
add their parser (``register``); bad input (:class:`foundation.errors.ArchdemInputError`) is one line, code 2.
"""
from __future__ import annotations

import argparse
import sys
from importlib.metadata import version

# a Ctrl-C while the program starts (about a second of imports) ends it in one line, not a traceback:
# nothing has begun yet (docs/decisions/010-input-rules.md#interruption)
try:
    from dem.campaign import campaign_cmd
    from dem.cli import analytic_cmd, draw_cmd, mesh_cmd, rock_cmd, specimens_cmd
    from dem.common.options import common_rules, restore_study
    from dem.experiments.contract import given_options, resolve
    from dem.experiments.registry import commands as experiment_commands
    from foundation.errors import ArchdemInputError
    from foundation.processes import stdout_reader_gone, stop_signals

    # in the order of ``archdem --help``
    _COMMANDS = [specimens_cmd, mesh_cmd, draw_cmd, analytic_cmd, rock_cmd, campaign_cmd,
                 *(resolve(m) for m in experiment_commands())]
except KeyboardInterrupt:
    print("archdem: interrupted", file=sys.stderr)
    raise SystemExit(130) from None


class _Parser(argparse.ArgumentParser):
    """argparse with usage errors in one line (exit code 2) and no abbreviation: an option a command lacks
    (``--engine`` beside ``--engines``) is refused, not read as another one."""

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
            if not stdout_reader_gone():  # else the reader of our output went away (e.g. | head): no traceback
                raise  # a pipe of our own (e.g. to a worker) broke: that is a failure, not a closed reader
            return 1
        except Exception:
            if not stop.signum:
                raise
            # the stop's exception, wrapped by the code it interrupted (an import's class __set_name__)
            print("archdem: interrupted", file=sys.stderr)
            return stop.exit_code

