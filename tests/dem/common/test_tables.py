"""A schema derived from a dataclass's fields: kinds from their types, units from their metadata."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import pytest

from dem.common.tables import Column, Schema
from dem.experiments.contract import COLUMNS_ARE_FIELDS, Result


@dataclass(frozen=True)
class Row(Result):
    SCHEMA: ClassVar[Schema] = COLUMNS_ARE_FIELDS

    id: str
    n: int
    at_rest: bool
    amplitude_g: float | None = field(default=None, metadata={"unit": "g"})
    bands: list | None = None


def test_a_rows_columns_are_its_fields_in_order():
    assert Row.SCHEMA == Schema((Column("id", "str"), Column("n", "int"), Column("at_rest", "bool"),
                                 Column("amplitude_g", "float", "g"), Column("bands", "json")))
    assert Row("a", 2, True, 0.5).rows() == [{"id": "a", "n": 2, "at_rest": True, "amplitude_g": 0.5, "bands": None}]
    assert Row("a", 2, True).SCHEMA is Row.SCHEMA  # read from an instance too, built once


def test_a_field_of_no_column_kind_is_refused_by_name():
    @dataclass(frozen=True)
    class Bad:
        when: complex

    with pytest.raises(TypeError, match=r"Bad\.when: a column's type is one of"):
        Schema.of_fields(Bad)
