"""A study's file, chosen before any case runs: a new one (never overwritten) or one to resume (it must
exist: a mistyped name is refused rather than starting a new study under it)."""
from __future__ import annotations

import os
from pathlib import Path

from foundation.errors import ArchdemInputError
from foundation.io import can_make_dir, check_name, unique_run_path


def resumed_study(path: str) -> str:
    """``path``, an existing study file to resume; a folder or a missing file is refused."""
    if os.path.isdir(path):
        raise ArchdemInputError(f"--resume {path} is a folder; a study is one .h5 file")
    if not os.path.isfile(path):
        raise ArchdemInputError(f"--resume {path!r}: no such study file; start a new study with --out")
    return path


def study_file(out: str | None, resume: str | None, default_dir: str, stem: str) -> tuple[str, bool]:
    """``(path, resume)`` of a study: ``resume`` (an existing file), else ``out`` (a new file, its folder
    writable or makeable), else a new ``stem[-N].h5`` under ``default_dir``; one rule for every study."""
    if resume is not None and out is not None:
        raise ArchdemInputError("give --out (new study) or --resume STUDY.h5, not both")
    if resume is not None:
        return resumed_study(resume), True
    if out is None:
        return str(unique_run_path(can_make_dir(default_dir), stem)), False
    p = Path(out)
    if p.name:
        check_name(p)
    # "x/" names a folder even before it exists (Path drops the slash)
    if not p.name or p.is_dir() or out.endswith(("/", os.sep)):
        raise ArchdemInputError(f"--out {out!r}: give a study file name (STUDY.h5), not a folder")
    if p.exists() or p.is_symlink():
        raise ArchdemInputError(f"--out {p} exists; a study is never overwritten (resume it with --resume, "
                                "or choose another file)")
    can_make_dir(p.parent)
    return out, False
