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

import importlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, ClassVar

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

__all__ = ["Column", "Schema", "Result", "Step", "Summary", "Experiment", "Tables", "resolve", "cells_html", "fmt", "read_csv",
           "table_html", "to_json_rows", "write_csv", "write_h5_group"]

#: Typed tables by name (a step's table name -> its typed rows), as the report's summary reads them.
Tables = dict[str, list[dict]]


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
