"""File basics shared by every layer: atomic result files, output paths, one JSON encoder, the
parser of value grids.

A result is written to a temporary name beside the target and then renamed: an interrupted
write leaves no half-written file under the final name, and an existing result is never
silently replaced.
"""
from __future__ import annotations

import contextlib
import fcntl
import json
import math
import os
import tempfile
from pathlib import Path
from typing import Any, Iterator

import numpy as np

from foundation.errors import ArchdemInputError


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


def writable_dir(path: str | os.PathLike) -> Path:
    """Create ``path`` (a directory) or fail with a one-line input error."""
    if not str(path).strip():
        raise ArchdemInputError("an output path is empty; give a name (\".\" for the current folder)")
    p = _parts_fit(Path(path))
    try:
        p.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ArchdemInputError(f"cannot create output directory {p}: {exc.strerror}") from None
    if not os.access(p, os.W_OK):
        raise ArchdemInputError(f"output directory {p} is not writable")
    return p


def _parts_fit(p: Path) -> Path:
    """``p`` whose every component fits a file name (255 bytes): longer ones make the system's calls fail."""
    for part in p.parts:
        if len(os.fsencode(part)) > 255:
            raise ArchdemInputError(f"the name {part[:40]}... is too long ({len(part)} characters; at most 255)")
    return p


def can_make_dir(path: str | os.PathLike) -> Path:
    """Check, without making anything, that the folder ``path`` exists and is writable or can be
    made (its nearest existing parent is a writable folder): a run fails before it starts, and a
    run that fails leaves no empty folder behind."""
    if not str(path).strip():
        raise ArchdemInputError("an output path is empty; give a name (\".\" for the current folder)")
    p = _parts_fit(Path(path))
    q = p
    while not q.exists() and q != q.parent:
        q = q.parent
    if not q.is_dir():
        raise ArchdemInputError(f"cannot create directory {p}: {q} is not a folder")
    if not os.access(q, os.W_OK | os.X_OK):
        raise ArchdemInputError(f"cannot create directory {p}: {q} is not writable")
    try:  # the permissions do not tell for root, nor on /proc or a read-only mount: try it
        fd, probe = tempfile.mkstemp(prefix=".archdem-probe-", dir=q)
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise ArchdemInputError(f"cannot create directory {p}: {q} is not writable ({exc.strerror})") from None
    return p


#: Characters a result's temporary or lock file adds to its name (``.NAME.XXXXXXXX.part``, ``.NAME.lock``).
NAME_MARGIN = 16


def check_name(path: str | os.PathLike) -> Path:
    """A result file name the file system takes with its temporary and lock files beside it."""
    p = _parts_fit(Path(path))
    q = p.parent
    while not q.exists() and q != q.parent:
        q = q.parent
    try:
        limit = os.pathconf(q, "PC_NAME_MAX")
    except (OSError, ValueError):
        limit = 255
    if len(os.fsencode(p.name)) + NAME_MARGIN > limit:
        raise ArchdemInputError(f"the file name {p.name[:40]}... is too long ({len(p.name)} characters; at most "
                                f"{limit - NAME_MARGIN} here)")
    return p


def writable_file(path: str | os.PathLike, overwrite: bool = True) -> Path:
    """Check, without making anything, that the file ``path`` can be written (its folder exists or
    can be made, the name is not a folder), before the work that produces it."""
    if not str(path).strip():
        raise ArchdemInputError("an output file name is empty")
    p = check_name(path)  # first: a name too long breaks even the questions below
    if p.is_dir():
        raise ArchdemInputError(f"{p} is a folder; give a file name")
    can_make_dir(p.parent)
    if p.exists() and not overwrite:
        raise ArchdemInputError(f"{p} exists; not overwriting it (choose another name)")
    return p


def json_default(o: Any) -> Any:
    """The JSON encoder of every archdem file and answer: numpy arrays and scalars, paths."""
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, (np.floating, np.integer, np.bool_)):
        return o.item()
    if isinstance(o, Path):
        return str(o)
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


@contextlib.contextmanager
def exclusive(lock_file: str | os.PathLike, what: str, remove: bool = False) -> Iterator[None]:
    """Hold an advisory lock on ``lock_file`` (made if missing) while writing ``what``; a second
    writer is refused in one line instead of mixing its files with the first one's.

    ``remove``: delete the lock file when done (for a lock beside a result file). A writer that
    locked a file already removed by the previous holder notices it and locks the new one.
    """
    lock_file = Path(lock_file)
    while True:
        try:
            fd = os.open(lock_file, os.O_CREAT | os.O_RDWR, 0o644)
        except OSError as exc:
            raise ArchdemInputError(f"cannot make the lock file {lock_file} for {what}: {exc.strerror}") from None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            raise ArchdemInputError(f"{what} is being written by another archdem process; "
                                    "wait for it to finish or choose another output") from None
        try:
            same = os.stat(lock_file).st_ino == os.fstat(fd).st_ino
        except FileNotFoundError:
            same = False
        if same:
            break
        os.close(fd)  # the previous holder removed this file after we opened it: lock the new one
    try:
        yield
    finally:
        if remove:
            with contextlib.suppress(FileNotFoundError):
                lock_file.unlink()  # before unlocking, so that nobody locks a file about to vanish
        fcntl.flock(fd, fcntl.LOCK_UN)
        os.close(fd)


def to_json(obj: Any, **kw) -> str:
    """``json.dumps`` with :func:`json_default`."""
    return json.dumps(obj, default=json_default, **kw)


#: Most values a grid option may hold (a typo such as 1:1e9:1e-9 would otherwise exhaust memory).
MAX_GRID_POINTS = 1000


def parse_grid(text: str, what: str = "grid") -> list[float]:
    """``"0.5,1,2"`` or an inclusive range ``"start:stop:step"``: positive values, at most
    ``MAX_GRID_POINTS``; an empty text or an empty item is refused."""
    try:
        if ":" in text:
            a, b, s = (float(v) for v in text.split(":"))
        else:
            items = text.split(",")
            if any(not v.strip() for v in items):
                raise ValueError
            vals = [float(v) for v in items]
    except ValueError:
        raise ArchdemInputError(f"{what}: expected a list '0.5,1,2' or a range 'start:stop:step', got {text!r}") from None
    if ":" in text:
        if not (all(math.isfinite(v) for v in (a, b, s)) and s > 0 and b >= a):
            raise ArchdemInputError(f"{what}: a range start:stop:step needs start <= stop and step > 0, got {text!r}")
        n = int(math.floor((b - a) / s + 1e-9)) + 1
        vals = [a + k * s for k in range(min(n, MAX_GRID_POINTS + 1))]
    if len(vals) > MAX_GRID_POINTS:
        raise ArchdemInputError(f"{what}: {text!r} holds more than {MAX_GRID_POINTS} values")
    if not vals or not all(math.isfinite(v) and v > 0 for v in vals):
        raise ArchdemInputError(f"{what}: values must be positive, got {text!r}")
    return vals
