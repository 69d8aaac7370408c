"""An option's help from its field's metadata, and a field's or a parameter's default."""
from dataclasses import dataclass, field

import pytest

from foundation.fields import default_of, option_help


def test_the_help_says_the_unit_and_the_default_shown_or_given():
    assert option_help({"help": "time step", "unit": "s"}, 5e-4) == "time step [s] (default 0.0005)"
    assert option_help({"help": "width", "shown": "the specimen's"}, None) == "width (default the specimen's)"
    assert option_help({"help": "courses", "shown": 1}, None) == "courses (default 1)"


def test_none_says_no_default():
    assert option_help({"help": "stiffness", "unit": "Pa/m"}, None) == "stiffness [Pa/m]"
    assert option_help({"help": "stiffness", "shown": None}, 0.0) == "stiffness"


@dataclass
class _Spec:
    a: float = 1.5
    b: list = field(default_factory=lambda: [1])
    c: int = field(default=2, metadata={"help": "c"})


def _f(x: int, y: str = "y") -> None:
    pass


def test_defaults_of_fields_and_parameters():
    assert (default_of(_Spec, "a"), default_of(_Spec, "b"), default_of(_Spec, "c")) == (1.5, [1], 2)
    assert default_of(_f, "y") == "y"
    for obj, name in ((_Spec, "z"), (_f, "x"), (_f, "z")):
        with pytest.raises(LookupError):
            default_of(obj, name)
