"""Writing a figure to a file, the one way every experiment does it (atomically, format from the suffix)."""
from __future__ import annotations

from pathlib import Path

from foundation.io import atomic_path


def save_figure(fig, path: str | Path, overwrite: bool = False, dpi: int = 120, tight: bool = True) -> Path:
    """Write matplotlib ``fig`` to ``path`` (png/pdf/svg by its suffix, png without one) at ``dpi``
    [dots per inch]; ``tight`` crops to the drawn area. Returns ``path``."""
    path = Path(path)
    with atomic_path(path, overwrite=overwrite) as tmp:
        fig.savefig(tmp, format=path.suffix.lstrip(".") or "png", dpi=dpi, bbox_inches="tight" if tight else None)
    return path
