"""The experiment contract: what an experiment declares once, and what the program, the campaign and the
report derive from it (docs/architecture.md#the-experiment-contract).

* A result type declares its table's :class:`~dem.common.tables.Schema` once (:class:`Result`); its rows
  are written as CSV (schema beside it), JSON, an HDF5 group and a report table by shared code
  (:mod:`dem.common.tables`), and read back typed.
* An :class:`Experiment` names its sub-command modules and its campaign steps (dotted paths, imported when
  used, so that ``archdem --help`` stays light) and its part of the report's summary.
* ``dem.experiments.registry`` lists the experiments; the program's commands, the campaign's steps and the
  report's sections and summary come from it.
"""
from __future__ import annotations

import argparse
import dataclasses
import importlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, ClassVar, get_args, get_type_hints

from dem.common.tables import (
    Column,
    Schema,
    cells_html,
    fmt,
    read_csv,
    table_html,
    to_json_rows,
    write_csv,
    write_h5_group,
)
from foundation.fields import option_help

__all__ = ["Column", "Schema", "Result", "COLUMNS_ARE_FIELDS", "Step", "Summary", "Experiment", "Tables", "resolve", "cells_html", "fmt", "read_csv",
           "table_html", "to_json_rows", "write_csv", "write_h5_group", "spec_options", "add_spec_options",
           "spec_from_args", "given_options"]

#: Typed tables by name (a step's table name -> its typed rows), as the report's summary reads them.
Tables = dict[str, list[dict]]


class _ColumnsAreFields:
    """``SCHEMA`` of a dataclass result whose fields are its columns: :meth:`Schema.of_fields` of its class."""

    def __get__(self, obj: Any, owner: type) -> Schema:
        # while @dataclass builds the class it reads every class attribute, this one too
        return Schema.of_fields(owner) if dataclasses.is_dataclass(owner) else self


#: ``SCHEMA = COLUMNS_ARE_FIELDS``: a one-row result's columns are its fields (kinds from their types, units
#: from their metadata's ``unit``), declared once.
COLUMNS_ARE_FIELDS: Any = _ColumnsAreFields()


class Result:
    """A result whose table declares its schema once: ``SCHEMA`` and ``rows()`` (dicts of typed values in
    the schema's columns); the CSV, JSON, HDF5 and HTML forms follow."""

    SCHEMA: ClassVar[Schema]

    def rows(self) -> list[dict]:
        """One row: each column of the schema read from the attribute of its name (a result holding one
        row as its fields); a result of several rows, or named otherwise, says how."""
        return [{c.name: getattr(self, c.name) for c in self.SCHEMA.columns}]

    def write_csv(self, path: Path) -> None:
        """The rows as CSV, with the schema beside them (``NAME.schema.json``)."""
        write_csv(path, self.rows(), self.SCHEMA)

    def to_json(self) -> list[dict]:
        """The rows as JSON-ready dicts."""
        return to_json_rows(self.rows(), self.SCHEMA)

    def write_h5_group(self, group) -> None:
        """One dataset per column into an open HDF5 group."""
        write_h5_group(group, self.rows(), self.SCHEMA)

    def table_html(self, title: str, name: str) -> str:
        return table_html(self.rows(), self.SCHEMA, title, name)


def resolve(path: str) -> Any:
    """The object a dotted path names: ``"package.module"`` or ``"package.module:name"``."""
    module, _, name = path.partition(":")
    mod = importlib.import_module(module)
    return getattr(mod, name) if name else mod


@dataclass(frozen=True)
class Step:
    """A campaign step: its name (its folder in the campaign), the step function as
    ``"module:function"`` (``(CampaignContext, folder) -> outputs``), what it does (the report's section
    title), whether it runs only when asked for, and its rank: the campaign runs its steps by rank."""

    name: str
    function: str
    description: str
    rank: int
    optional: bool = False

    def load(self) -> Callable:
        return resolve(self.function)


@dataclass(frozen=True)
class Summary:
    """An experiment's part of the report's summary.

    ``columns``: the headers of its columns in the per-specimen table, placed by ``rank`` (left to right),
    ``cells(tables, specimen_id)`` their texts (HTML, "" when nothing); ``ids``: the tables whose ``id``
    column lists specimens. ``table(tables)``: a table of its own, ``(caption, headers, rows of cell
    texts)``, or None when it has nothing to show."""

    columns: tuple[str, ...] = ()
    cells: Callable[[Tables, str], tuple[str, ...]] | None = None
    ids: tuple[str, ...] = ()
    rank: int = 0
    table: Callable[[Tables], tuple[str, tuple[str, ...], list[tuple[str, ...]]] | None] | None = None


@dataclass(frozen=True)
class Experiment:
    """One experiment as the program, the campaign and the report see it: its name (its folder), a title,
    its sub-command modules (dotted paths), its campaign steps and its part of the summary."""

    name: str
    title: str
    commands: tuple[str, ...] = ()
    steps: tuple[Step, ...] = ()
    summary: Summary | None = None

    def __post_init__(self) -> None:
        names = [s.name for s in self.steps]
        if len(set(names)) != len(names):
            raise ValueError(f"experiment {self.name}: a step named twice in {names}")


# ------------------------------------------------------------------ a command's options from a spec
def spec_options(spec: type) -> list[dataclasses.Field]:
    """The fields of the dataclass ``spec`` that are options: those whose metadata has a ``help``."""
    return [f for f in dataclasses.fields(spec) if "help" in f.metadata]


def _option_type(hint: Any) -> Any:
    """The argparse type of a field's annotation: ``X`` of ``X | None`` and of ``tuple[X, ...]``."""
    while get_args(hint):
        hint = next(a for a in get_args(hint) if a is not type(None))
    return hint


def add_spec_options(parser: argparse.ArgumentParser, spec: type) -> None:
    """One option of ``parser`` per option field of ``spec`` (:func:`spec_options`): its flag from the
    field's name (``Tc_star``: ``--Tc-star``) and the metadata's ``aliases``, its type from the annotation (``bool``: a flag), its
    ``choices``, ``metavar``, ``nargs`` and ``required`` from the metadata, its default the field's (the library's),
    its help the metadata's ``help``, ``unit`` and the default (``shown`` where the field's is None)."""
    hints = get_type_hints(spec)
    for f in spec_options(spec):
        m, kind = f.metadata, _option_type(hints[f.name])
        text = option_help(m, f.default)
        kw = {k: m[k] for k in ("choices", "metavar", "nargs", "required") if k in m}
        kw |= {"action": "store_true"} if kind is bool else {"type": kind, "default": f.default}
        parser.add_argument("--" + f.name.replace("_", "-"), *m.get("aliases", ()), dest=f.name, help=text.replace("%", "%%"), **kw)


def spec_from_args(spec: type, args: argparse.Namespace, **fixed: Any) -> Any:
    """``spec`` of the parsed options (lists as tuples) and ``fixed`` (its fields that are no option); its
    field ``given``, if it has one, receives the options set by hand (``args.given``, which ``archdem`` records)."""
    kw = {f.name: getattr(args, f.name) for f in spec_options(spec)}
    kw = {k: tuple(v) if isinstance(v, list) else v for k, v in kw.items()}
    if "given" in {f.name for f in dataclasses.fields(spec)} and getattr(args, "given", None) is not None:
        kw["given"] = frozenset(args.given) & kw.keys()
    return spec(**kw, **fixed)


def given_options(parser: argparse.ArgumentParser, argv: list[str], command: str) -> frozenset[str]:
    """The destinations ``argv`` sets explicitly for the sub-command ``command`` of ``parser`` (a default
    given by hand counts): the command's options parsed again with every default suppressed."""
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
