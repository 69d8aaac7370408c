"""Writing a figure to a file, the one way every experiment does it (atomically, format from the suffix),
and the check of a new figure file's name before the work that draws it."""
from __future__ import annotations

from pathlib import Path

from foundation.errors import ArchdemInputError
from foundation.io import atomic_path, check_name, writable_file

#: Figure formats the commands write (matplotlib's, by the file's suffix).
FIGURE_SUFFIXES = (".png", ".pdf", ".svg")


def figure_file(path: str | Path, option: str = "--plot") -> Path:
    """A new figure file, checked before the work that draws it: a known suffix, not an existing file or
    folder, its folder writable or makeable; ``option`` names it in a refusal."""
    p = Path(path)
    if p.suffix.lower() not in FIGURE_SUFFIXES:
        raise ArchdemInputError(f"{option} must end in {', '.join(FIGURE_SUFFIXES)}, got {p.name!r}")
    check_name(p)
    if p.is_dir():
        raise ArchdemInputError(f"{option} {p} is a folder; give a file name")
    return writable_file(p, overwrite=False)


def save_figure(fig, path: str | Path, overwrite: bool = False, dpi: int = 120, tight: bool = True) -> Path:
    """Write matplotlib ``fig`` to ``path`` (png/pdf/svg by its suffix, png without one) at ``dpi``
    [dots per inch]; ``tight`` crops to the drawn area. Returns ``path``."""
    path = Path(path)
    with atomic_path(path, overwrite=overwrite) as tmp:
        fig.savefig(tmp, format=path.suffix.lstrip(".") or "png", dpi=dpi, bbox_inches="tight" if tight else None)
    return path
