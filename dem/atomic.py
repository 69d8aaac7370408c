"""Atomic result files: write to a temporary name beside the target, then rename.

An interrupted write leaves no half-written file under the final name, and an
existing result is never silently replaced.
"""
from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path
from typing import Iterator

from specimens.errors import ArchdemInputError


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike, overwrite: bool = False) -> Iterator[Path]:
    """Yield a temporary path; on success it is renamed to ``target``.

    Raises :class:`ArchdemInputError` if ``target`` exists and ``overwrite`` is False,
    or if its directory cannot be created.
    """
    target = Path(target)
    if target.exists() and not overwrite:
        raise ArchdemInputError(f"{target} exists; an existing result is never overwritten (choose another --out)")
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ArchdemInputError(f"cannot create directory {target.parent}: {exc.strerror}") from None
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".part", dir=target.parent)
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        yield tmp_path
        if target.exists() and not overwrite:
            raise ArchdemInputError(f"{target} appeared while writing; not overwriting it")
        # mkstemp creates 0600 files; give results the usual permissions of the umask
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp_path, 0o666 & ~umask)
        os.replace(tmp_path, target)
    finally:
        if tmp_path.exists():
            tmp_path.unlink()


def unique_run_path(directory: str | os.PathLike, stem: str, suffix: str = ".h5") -> Path:
    """A path ``directory/stem[-N]suffix`` that does not exist yet."""
    directory = Path(directory)
    p = directory / f"{stem}{suffix}"
    n = 1
    while p.exists():
        n += 1
        p = directory / f"{stem}-{n}{suffix}"
    return p
