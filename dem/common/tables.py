"""Typed tables: a schema (columns with a name, a kind and a unit) declared once, from which a table's
rows are written as CSV (with the schema beside it), as JSON, as an HDF5 group and as HTML, and read
back typed (docs/architecture.md#the-experiment-contract).

The kinds are ``float``, ``int``, ``bool``, ``str`` and ``json`` (a value written as JSON text). A
missing value (``None``) is an empty cell; a float column reads it back as None, as every other kind.
"""
from __future__ import annotations

import csv
import dataclasses
import functools
import html
import json
import math
import numbers
import typing
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable

KINDS = ("float", "int", "bool", "str", "json")
#: The column kind of a field's type (``X | None`` reads as ``X``).
KIND_OF_TYPE = {float: "float", int: "int", bool: "bool", str: "str", dict: "json", list: "json"}
#: The file beside ``NAME.csv`` that holds its schema: ``NAME.schema.json``.
SCHEMA_SUFFIX = ".schema.json"


@dataclass(frozen=True)
class Column:
    """One column: its name (the CSV header), its kind (:data:`KINDS`) and its unit ("" if none)."""

    name: str
    kind: str = "float"
    unit: str = ""

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"column {self.name!r}: kind must be one of {', '.join(KINDS)}, got {self.kind!r}")

    def cell(self, value: Any) -> Any:
        """``value`` as the CSV writer takes it (json as JSON text; None as an empty cell)."""
        if value is None:
            return ""
        return json.dumps(value) if self.kind == "json" else value

    def parse(self, text: str) -> Any:
        """The typed value of a CSV cell of this column."""
        if text == "" and self.kind != "str":
            return None
        if self.kind == "float":
            return float(text)
        if self.kind == "int":
            return int(text)
        if self.kind == "bool":
            if text not in ("True", "False"):
                raise ValueError(f"column {self.name!r}: {text!r} is no bool")
            return text == "True"
        return json.loads(text) if self.kind == "json" else text


@dataclass(frozen=True)
class Schema:
    """The columns of a table, in order."""

    columns: tuple[Column, ...]

    def __post_init__(self) -> None:
        names = [c.name for c in self.columns]
        if len(set(names)) != len(names):
            raise ValueError(f"a schema names a column twice: {names}")

    @property
    def names(self) -> list[str]:
        return [c.name for c in self.columns]

    def column(self, name: str) -> Column:
        return next(c for c in self.columns if c.name == name)

    def to_dict(self) -> dict:
        return {"columns": [{"name": c.name, "kind": c.kind, "unit": c.unit} for c in self.columns]}

    @classmethod
    @functools.cache
    def of_fields(cls, row_type: type) -> "Schema":
        """The schema of a dataclass whose fields are its columns, in their order: each kind from the field's
        type (:data:`KIND_OF_TYPE`), each unit from its metadata's ``unit``."""
        hints = typing.get_type_hints(row_type)
        cols = []
        for f in dataclasses.fields(row_type):
            t = hints[f.name]
            t = next((a for a in typing.get_args(t) if a is not type(None)), t) if type(None) in typing.get_args(t) else t
            kind = KIND_OF_TYPE.get(typing.get_origin(t) or t)
            if kind is None:
                raise TypeError(f"{row_type.__name__}.{f.name}: a column's type is one of {list(KIND_OF_TYPE)}, got {t}")
            cols.append(Column(f.name, kind, f.metadata.get("unit", "")))
        return cls(tuple(cols))

    @classmethod
    def from_dict(cls, d: dict) -> "Schema":
        return cls(tuple(Column(c["name"], c["kind"], c.get("unit", "")) for c in d["columns"]))

    def check(self, rows: list[dict]) -> None:
        """Every row holds exactly the schema's columns (in any order)."""
        for r in rows:
            if set(r) != set(self.names):
                raise ValueError(f"a row's columns {list(r)} are not the schema's {self.names}")


def _kind_of(value: Any) -> str | None:
    """The kind of one Python value (None for a missing one); numpy's scalars count as their kinds."""
    if value is None:
        return None
    if isinstance(value, bool) or getattr(getattr(value, "dtype", None), "kind", "") == "b":
        return "bool"
    if isinstance(value, numbers.Integral):
        return "int"
    if isinstance(value, numbers.Real):
        return "float"
    return "str"  # a dict or list written by csv's str() is no JSON: it stays its text


def infer_schema(rows: list[dict]) -> Schema:
    """The schema of rows written without one, from their Python values: a column of ints and floats is
    float, of anything else with a string text (str); an empty string in a number column is a missing value."""
    cols = []
    for name in rows[0]:
        vals = [r.get(name, "") for r in rows]
        kinds = {_kind_of(None if v == "" else v) for v in vals} - {None}
        kinds = {"float" if k == "int" else k for k in kinds} if kinds == {"int", "float"} else kinds
        if len(kinds) != 1:  # mixed, or all empty
            kinds = {"str"} if kinds or any(isinstance(v, str) for v in vals) else {"float"}
        cols.append(Column(name, kinds.pop()))
    return Schema(tuple(cols))


def schema_path(csv_path: Path) -> Path:
    """``NAME.schema.json`` beside ``NAME.csv``."""
    return Path(csv_path).with_suffix(SCHEMA_SUFFIX)


def write_csv(path: Path, rows: list[dict], schema: Schema | None = None) -> Schema:
    """Write ``rows`` (dicts of typed values, every row with the same columns) to ``path`` and their
    schema (given, or inferred from the values) beside it; return the schema."""
    if schema is None:
        schema = infer_schema(rows)
    else:
        schema.check(rows)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=schema.names)
        w.writeheader()
        w.writerows({c.name: c.cell(r.get(c.name)) for c in schema.columns} for r in rows)
    cols = schema.to_dict()["columns"]  # one column a line: the file reads as the table's legend
    schema_path(path).write_text('{"columns": [\n' + ",\n".join(f"  {json.dumps(c)}" for c in cols) + "\n]}\n")
    return schema


def read_csv(path: Path, schema: Schema | None = None) -> tuple[Schema, list[dict]]:
    """The schema and the typed rows of a CSV table: with ``schema``, or the one written beside it.
    A table written before schemas were (no file beside it) is read with :func:`schema_of_text`."""
    path = Path(path)
    with open(path, newline="") as fh:
        text_rows = list(csv.DictReader(fh))
        fh.seek(0)
        header = next(csv.reader(fh), [])
    if schema is None:
        side = schema_path(path)
        schema = Schema.from_dict(json.loads(side.read_text())) if side.is_file() else schema_of_text(header, text_rows)
    if header != schema.names:
        raise ValueError(f"{path}: columns {header} are not the schema's {schema.names}")
    return schema, [{c.name: c.parse(r[c.name]) for c in schema.columns} for r in text_rows]


def schema_of_text(header: list[str], rows: list[dict]) -> Schema:
    """The schema of a table that has none written beside it (an older campaign folder): a column whose
    every cell reads as a number is float, of True and False bool, else str."""
    def number(t: str) -> bool:
        try:
            float(t)
            return True
        except ValueError:
            return t == ""

    def kind(n: str) -> str:
        if rows and all(r[n] in ("True", "False") for r in rows):
            return "bool"
        return "float" if rows and all(number(r[n]) for r in rows) else "str"

    return Schema(tuple(Column(n, kind(n)) for n in header))


def to_json_rows(rows: list[dict], schema: Schema) -> list[dict]:
    """The rows as JSON-ready dicts in the schema's column order (NaN stays NaN: the JSON encoder decides)."""
    return [{c.name: _plain(r[c.name], c.kind) for c in schema.columns} for r in rows]


def _plain(v: Any, kind: str) -> Any:
    if v is None or kind in ("json", "str"):
        return v
    return {"float": float, "int": int, "bool": bool}[kind](v)


def write_h5_group(group, rows: list[dict], schema: Schema) -> None:
    """One dataset per column into the HDF5 ``group``: float (a missing value NaN), int (float with NaN when
    a value is missing), bool, str and json (UTF-8 text); the unit, if any, as the dataset's ``unit``."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    import h5py
    import numpy as np

    for c in schema.columns:
        vals = [r[c.name] for r in rows]
        if c.kind == "float" or (c.kind == "int" and None in vals):
            data = np.array([math.nan if v is None else float(v) for v in vals], dtype=float)
        elif c.kind == "int":
            data = np.array(vals, dtype=np.int64)
        elif c.kind == "bool" and None not in vals:
            data = np.array(vals, dtype=bool)
        else:
            text = ["" if v is None else (json.dumps(v) if c.kind == "json" else str(v)) for v in vals]
            data = np.array(text, dtype=h5py.string_dtype())
        ds = group.create_dataset(c.name, data=data)
        if c.unit:
            ds.attrs["unit"] = c.unit


def fmt(v: Any) -> str:
    """A typed cell as the report shows it: floats to 4 significant digits, NaN as a dash, None empty."""
    if v is None:
        return ""
    if isinstance(v, bool):
        return str(v)
    if isinstance(v, numbers.Integral):
        return str(int(v)) if abs(v) < 1e6 else f"{float(v):.4g}"
    if isinstance(v, numbers.Real):
        return "–" if v != v else f"{float(v):.4g}"
    if isinstance(v, (dict, list)):
        v = json.dumps(v)
    return _text(str(v))


def _text(v: str) -> str:
    """A text cell; a number written in a text column (a column of mixed values, as a calculation's) shows
    as a number: written without a point or exponent as a whole number, else to 4 significant digits."""
    try:
        x = float(v)
    except ValueError:
        return html.escape(v)
    if not math.isfinite(x):
        return "–" if x != x else html.escape(v)
    if x == int(x) and abs(x) < 1e6 and "." not in v and "e" not in v.lower():
        return str(int(x))
    return f"{x:.4g}"


def table_html(rows: list[dict], schema: Schema, title: str, name: str) -> str:
    """One table of the report: a header per column (its unit as the header's tooltip), a row per row."""
    if not rows:
        return f"<p>(table {html.escape(title)} is empty)</p>"
    head = "".join(f"<th{f' title={chr(34)}{html.escape(c.unit)}{chr(34)}' if c.unit else ''}>{html.escape(c.name)}</th>"
                   for c in schema.columns)
    body = "".join("<tr>" + "".join(f"<td>{fmt(r[c])}</td>" for c in schema.names) + "</tr>" for r in rows)
    return (f'<div class="wrap"><table class="data" data-name="{html.escape(name)}"><caption>{html.escape(title)}</caption>'
            f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></div>")


def cells_html(caption: str, headers: Iterable[str], rows: Iterable[Iterable[str]]) -> str:
    """A summary table of cells already written as HTML text."""
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headers)
    body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in r) + "</tr>" for r in rows)
    return (f"<div class='wrap'><table class='data'><caption>{html.escape(caption)}</caption><tr>{head}</tr>"
            f"{body}</table></div>")
