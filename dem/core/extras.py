"""Optional dependencies: a missing one is named, with the extra that installs it, in one line."""
from __future__ import annotations

import importlib
from types import ModuleType

from foundation.errors import ArchdemInputError

EXTRAS = {"mujoco": "mujoco", "distributed": "cluster", "compas_lmgc90": "lmgc90"}  # importable module -> archdem extra


def require(module: str, purpose: str) -> ModuleType:
    """Import optional ``module`` for ``purpose``, or raise a one-line :class:`ArchdemInputError`."""
    try:
        return importlib.import_module(module)
    except ImportError:
        extra = EXTRAS.get(module, "all")
        raise ArchdemInputError(f"{purpose} needs the optional package {module!r}: "
                                f"pip install 'archdem[{extra}]'") from None
