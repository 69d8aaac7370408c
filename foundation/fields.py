"""An option's help text from the metadata of the dataclass field it sets, and a field's or a parameter's
default: declared once, in the library, and read by every parser that offers them
(``dem.experiments.contract.add_spec_options``, the option table of ``dem.common.options``)."""
from __future__ import annotations

import dataclasses
import inspect
from collections.abc import Mapping
from typing import Any


def option_help(metadata: Mapping[str, Any], default: Any) -> str:
    """``help [unit] (default X)`` of a field's ``metadata`` (keys ``help``, ``unit``, ``shown``): X is
    ``shown`` if the metadata has it, else ``default`` (floats as ``:g``); no default is said for None."""
    shown = metadata.get("shown", default)
    shown = f"{shown:g}" if isinstance(shown, float) else shown
    unit = metadata.get("unit")
    return metadata["help"] + (f" [{unit}]" if unit else "") + ("" if shown is None else f" (default {shown})")


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
