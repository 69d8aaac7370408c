"""Sweep engine: run a study (a list of independent cases) on local cores or a Dask cluster.

A **study** is a list of cases — JSON-serialisable dicts of parameters — and a **case
function**, imported by its caller: a module-level function, so that it reaches worker
processes and Dask workers by reference (its module and name), not by pickling code; the study
file records it as ``"module:function"``. The function takes the case dict and returns a dict
of results: numbers, booleans, strings, ``None``, numpy arrays or lists, and nested dicts of
those.

Execution (:func:`run_study`): a local ``ProcessPoolExecutor`` (``spawn`` start method, all
cores by default) or, with ``scheduler="tcp://HOST:PORT"``, a ``dask.distributed.Client``;
both go through the same ``submit`` / ``as_completed`` loop. Even ``workers=1`` runs in a
worker process, so a crashing case cannot take the main process down.

Storage: **one writer** — the main process — writes each finished case into the study's
HDF5 file as soon as it completes, opening and closing the file for each case (closing
flushes HDF5's metadata too, which a bare ``flush`` does not guarantee against a later
kill). Layout::

    /                attrs: archdem_study (layout version), case_function, study_attrs (JSON),
                            seed (JSON), versions (JSON), created (UTC ISO time),
                            definition (JSON: the command line's options, when run by one)
    /cases/<key>     attrs: params (JSON), status ("ok" | "failed"), error (traceback text),
                            wall (s), worker, finished (UTC ISO time)
    /cases/<key>/results/<name>   one dataset (or group, for a nested dict) per result

``<key>`` is :func:`case_key`: the first 16 hex digits of the SHA-256 of the case's
canonical JSON (sorted keys), so the same parameters always map to the same group.

Interruption and resume: the file, with its attributes and ``definition``, is made (whole, by a
rename) before the first case runs (:func:`open_study`, for a command with work of its own before
its cases); each finished case is in it once its group is closed. Ctrl-C (``KeyboardInterrupt``,
and SIGTERM, which the ``archdem`` program raises as one) and a dead local worker
(``BrokenProcessPool``, raised here as :class:`StudyInterrupted`) stop the study; every
case finished before that point is already stored (finished results not yet collected are
stored on the way out). Local pool workers ignore SIGINT and are terminated when the study
stops, so they do not go on with queued cases; the cases that were running at that moment
are lost and will run again. Each case is written into a spare copy beside the file
(:func:`spare_path`, removed when the run ends) before the file itself: a SIGKILL in the middle of
an HDF5 write can leave that file unreadable, and a resume then takes the other, whole one
(:func:`_recover`). A SIGKILL leaves the cases stored before it (and the lock file, which locks
nothing: the next writer takes it). ``resume=True`` reopens the file, checks that its case
function, study attributes and seed are the ones given (else :class:`ArchdemInputError`),
skips the cases stored with status ``ok`` and **re-runs the failed ones** (a failure may be
transient: a killed worker, a full disk; a deterministic failure simply fails again and is
recorded again). Cases stored in the file but absent from ``cases`` are kept in the file;
``resume=True`` on a file that does not exist yet starts a new study. A case group whose
``status`` attribute is missing (written last) was interrupted while being written and
counts as not stored. A study made by the command line stores its ``definition`` (the options
that say what it computes); :func:`stored_definition` reads it back, so a resume runs that study
whatever its command line leaves out.
One process writes a study at a time: it holds ``.NAME.lock`` beside the file (see
:func:`lock_path`), and a second one is refused at once instead of interleaving its cases.
On a Dask cluster a worker that dies is retried by Dask; a case that kills workers
repeatedly (``KilledWorker``) is recorded as failed; a lost scheduler stops the study with
:class:`StudyInterrupted` (the finished cases are stored; resume it, on the cluster or locally).
"""
from __future__ import annotations

import contextlib
import datetime as _dt
import hashlib
import json
import math
import multiprocessing
import os
import shutil
import socket
import sys
import threading
import time
import traceback
from concurrent.futures import as_completed as pool_as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterator, Sequence
from urllib.parse import urlsplit

import h5py
import numpy as np

from dem.core.extras import require
from dem.core.progress import Progress, TerminalLine, terminal
from dem.core.provenance import provenance
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path, exclusive, json_default, writable_dir
from foundation.processes import StoppablePool, pool_worker_init, raise_if_stopped, stop_pool, worker_pool

LAYOUT_VERSION = 1


class StudyInterrupted(RuntimeError):
    """The study stopped early (a worker process died); finished cases are stored."""


# ----------------------------------------------------------------------------- cases
def canonical_json(obj: Any) -> str:
    """Canonical JSON (sorted keys, no blanks, no NaN) used for keys and comparisons."""
    try:
        return json.dumps(obj, sort_keys=True, separators=(",", ":"), default=json_default, allow_nan=False)
    except (TypeError, ValueError) as exc:
        raise ArchdemInputError(f"study parameters must be JSON-serialisable and finite: {exc}") from None


def case_key(case: dict) -> str:
    """Stable key of a case: 16 hex digits of the SHA-256 of its canonical JSON."""
    if not isinstance(case, dict):
        raise ArchdemInputError(f"a case must be a dict of parameters, got {type(case).__name__}")
    return hashlib.sha256(canonical_json(case).encode()).hexdigest()[:16]


def function_name(func: Callable[[dict], dict]) -> str:
    """``"module:function"`` of a case function, as the study file records it; a function that
    worker processes cannot import by that name (a lambda, a nested function) is refused."""
    mod, name = getattr(func, "__module__", None), getattr(func, "__qualname__", "")
    if not callable(func) or not mod or "." in name or "<" in name or getattr(sys.modules.get(mod), name, None) is not func:
        raise ArchdemInputError(f"a case function must be a module-level function, got {func!r}")
    return f"{mod}:{name}"


def _run_case(func: Callable[[dict], dict], case: dict) -> dict:
    """Worker side: run one case, catching its exceptions (not KeyboardInterrupt/SystemExit)."""
    t0 = time.perf_counter()
    worker = f"{socket.gethostname()}:{os.getpid()}"
    try:
        results = func(case)
        if not isinstance(results, dict):
            raise TypeError(f"case function returned {type(results).__name__}, not a dict")
        return {"status": "ok", "results": results, "error": "", "wall": time.perf_counter() - t0, "worker": worker}
    except Exception:  # noqa: BLE001 - every case error is recorded, the study goes on
        return {"status": "failed", "results": {}, "error": traceback.format_exc(),
                "wall": time.perf_counter() - t0, "worker": worker}


# ----------------------------------------------------------------------------- records
@dataclass
class CaseRecord:
    """One case of a study as stored: parameters, status, results or error, wall time [s]."""

    key: str
    params: dict
    status: str
    results: dict = field(default_factory=dict)
    error: str = ""
    wall: float = 0.0
    worker: str = ""
    finished: str = ""

    @property
    def ok(self) -> bool:
        return self.status == "ok"


@dataclass
class StudyResult:
    """The records of a study, in the order of the cases asked for, plus the file attributes."""

    path: Path
    attrs: dict
    records: list[CaseRecord]

    def __iter__(self) -> Iterator[CaseRecord]:
        return iter(self.records)

    def __len__(self) -> int:
        return len(self.records)

    def __getitem__(self, i: int) -> CaseRecord:
        return self.records[i]

    @property
    def by_key(self) -> dict[str, CaseRecord]:
        return {r.key: r for r in self.records}

    @property
    def ok(self) -> list[CaseRecord]:
        return [r for r in self.records if r.status == "ok"]

    @property
    def failed(self) -> list[CaseRecord]:
        return [r for r in self.records if r.status != "ok"]


# ----------------------------------------------------------------------------- HDF5 values
def _write_value(g, name: str, value: Any) -> None:
    if isinstance(value, dict):
        sub = g.create_group(name)
        sub.attrs["kind"] = "dict"
        for k, v in value.items():
            _write_value(sub, str(k), v)
        return
    if value is None:
        d = g.create_dataset(name, data=h5py.Empty("f8"))
        kind = "none"
    elif isinstance(value, (bool, np.bool_)):
        d, kind = g.create_dataset(name, data=bool(value)), "bool"
    elif isinstance(value, (int, np.integer)):
        d, kind = g.create_dataset(name, data=np.int64(value)), "int"
    elif isinstance(value, (float, np.floating)):
        d, kind = g.create_dataset(name, data=np.float64(value)), "float"
    elif isinstance(value, str):
        d, kind = g.create_dataset(name, data=value, dtype=h5py.string_dtype()), "str"
    elif isinstance(value, (list, tuple)) and value and all(isinstance(v, str) for v in value):
        d, kind = g.create_dataset(name, data=list(value), dtype=h5py.string_dtype()), "str_list"
    else:
        arr = np.asarray(value)
        if arr.dtype == object or arr.dtype.kind in "US":
            raise TypeError(f"result {name!r}: cannot store a value of type {type(value).__name__}")
        d = g.create_dataset(name, data=arr)
        kind = "list" if isinstance(value, (list, tuple)) else "array"
    d.attrs["kind"] = kind


def _read_value(obj) -> Any:
    kind = obj.attrs.get("kind", "array")
    if kind == "dict":
        return {k: _read_value(obj[k]) for k in obj}
    if kind == "none":
        return None
    if kind == "bool":
        return bool(obj[()])
    if kind == "int":
        return int(obj[()])
    if kind == "float":
        return float(obj[()])
    if kind == "str":
        return obj.asstr()[()]
    if kind == "str_list":
        return list(obj.asstr()[()])
    if kind == "list":
        return obj[()].tolist()
    return obj[()]


def _now() -> str:
    return _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds")


def _versions() -> dict:
    return provenance(extra=("dask", "distributed", "tqdm"))


def _write_case(path: Path, key: str, case: dict, out: dict) -> CaseRecord:
    """Store one finished case (replacing an earlier failed entry) and close the file."""
    rec = CaseRecord(key, case, out["status"], out["results"], out["error"], float(out["wall"]),
                     out.get("worker", ""), _now())
    _write_both(path, lambda f: _write_group(f, key, case, rec))
    return rec


def _write_group(f, key: str, case: dict, rec: CaseRecord) -> None:
    """One case's group in an open study file (replacing an earlier entry)."""
    cases = f.require_group("cases")
    if key in cases:
        del cases[key]
    g = cases.create_group(key)
    g.attrs["params"] = canonical_json(case)
    g.attrs["error"] = rec.error
    g.attrs["wall"] = rec.wall
    g.attrs["worker"] = rec.worker
    g.attrs["finished"] = rec.finished
    res = g.create_group("results")
    try:
        for k, v in rec.results.items():
            _write_value(res, str(k), v)
    except (TypeError, ValueError) as exc:  # an unstorable result makes the case failed
        del g["results"]
        g.create_group("results")
        rec.status, rec.results = "failed", {}
        rec.error = f"results could not be stored: {exc}"
        g.attrs["error"] = rec.error
    g.attrs["status"] = rec.status  # written last: a group without it is incomplete


#: How long the writer waits for a reader that holds the study file open (HDF5 locks it) [s].
BUSY_WAIT_S = 30.0


def _h5_append(path: Path):
    """The study file opened for writing; a reader holding it open (HDF5's file lock: a progress
    watcher, ``h5ls``) is waited for, up to ``BUSY_WAIT_S``, instead of failing the study."""
    t0 = time.monotonic()
    while True:
        try:
            return h5py.File(path, "a")
        except BlockingIOError:
            if time.monotonic() - t0 > BUSY_WAIT_S:
                raise
            time.sleep(0.05)


def spare_path(study: str | os.PathLike) -> Path:
    """The spare copy kept beside a study file while a study writes into it (removed at the end)."""
    study = Path(study)
    return study.with_name(f".{study.name}.spare")


def _write_both(path: Path, write: Callable) -> None:
    """``write(h5 file)`` into the spare copy, then into the study file: a SIGKILL in the middle of
    an HDF5 write can leave that file unreadable, and then the other one is whole (:func:`_recover`)."""
    spare = spare_path(path)
    if not spare.exists():
        with atomic_path(spare) as tmp:
            shutil.copyfile(path, tmp)
    for target in (spare, path):
        with _h5_append(target) as f:
            write(f)


def _readable(path: Path) -> bool:
    """Whether a study file opens and every attribute and value in it reads."""
    try:
        with h5py.File(path, "r") as f:
            if "archdem_study" not in f.attrs:
                return False
            _read_attrs(f)

            def read(name, obj) -> None:
                dict(obj.attrs)
                if isinstance(obj, h5py.Dataset):
                    obj[()]

            f.visititems(read)
        return True
    except Exception:  # noqa: BLE001 - whatever HDF5 says of a damaged file
        return False


def _recover(path: Path) -> None:
    """After a SIGKILL: keep the study file if it reads, else its spare copy, which then holds every
    case the file held (and maybe the one being written). Call it holding the study's lock."""
    spare = spare_path(path)
    if not spare.exists():
        return
    if not path.exists() or _readable(path):
        spare.unlink()
    elif _readable(spare):
        os.replace(spare, path)
    else:
        raise ArchdemInputError(f"{path} is damaged and so is its spare copy {spare.name}; it cannot be resumed")


def _read_attrs(f) -> dict:
    out = {}
    for k in ("archdem_study", "case_function", "created"):
        if k in f.attrs:
            v = f.attrs[k]
            out[k] = v.item() if hasattr(v, "item") else v
    for k in ("study_attrs", "seed", "versions", "notes"):
        if k in f.attrs:
            out[k] = json.loads(f.attrs[k])
    return out


def load_study(path: str | os.PathLike, cases: Sequence[dict] | None = None) -> StudyResult:
    """Records stored in a study file (all of them, or those of ``cases`` in that order)."""
    path = Path(path)
    try:
        f = h5py.File(path, "r")
    except FileNotFoundError:
        raise ArchdemInputError(f"{path}: no such study file") from None
    except OSError as exc:
        raise ArchdemInputError(f"{path}: not a readable HDF5 study file ({exc})") from None
    with f:
        if "archdem_study" not in f.attrs:
            raise ArchdemInputError(f"{path}: not an archdem study file")
        attrs = _read_attrs(f)
        stored = f.get("cases", {})
        keys = list(stored) if cases is None else [case_key(c) for c in cases]
        records = []
        for k in keys:
            if k not in stored:
                continue
            g = stored[k]
            if "status" not in g.attrs:  # interrupted while being written: not stored
                continue
            records.append(CaseRecord(
                key=k, params=json.loads(g.attrs["params"]), status=str(g.attrs["status"]),
                results={n: _read_value(g["results"][n]) for n in g["results"]},
                error=str(g.attrs["error"]), wall=float(g.attrs["wall"]), worker=str(g.attrs["worker"]),
                finished=str(g.attrs["finished"])))
    return StudyResult(path, attrs, records)


def stored_definition(path: str | os.PathLike) -> dict | None:
    """The ``definition`` a study file was made with (None for a study made without one); that of its
    spare copy if a SIGKILL left the file itself unreadable (:func:`_recover` puts it back on resume)."""
    spare = spare_path(path)
    if spare.exists() and not _readable(Path(path)) and _readable(spare):
        path = spare
    try:
        with h5py.File(path, "r") as f:
            if "archdem_study" not in f.attrs:
                raise ArchdemInputError(f"{path}: not an archdem study file; cannot resume it")
            text = f.attrs.get("definition")
    except OSError as exc:
        reason = str(exc).split("(")[0].strip() or type(exc).__name__
        raise ArchdemInputError(f"{path}: not a readable HDF5 study file ({reason})") from None
    return None if text is None else json.loads(text)


def store_note(path: str | os.PathLike, name: str, value: Any) -> None:
    """Keep ``value`` (JSON) under ``name`` in a study file: work a study does besides its cases (a
    command's reference runs), kept so that a resume does not do it again. Call it holding the
    study's lock (:func:`study_lock`)."""
    text = json.dumps(value, default=json_default)  # a NaN threshold is a result, not an error

    def write(f) -> None:
        notes = json.loads(f.attrs.get("notes", "{}"))
        notes[name] = json.loads(text)
        f.attrs["notes"] = json.dumps(notes, sort_keys=True, default=json_default)

    _write_both(Path(path), write)


def stored_note(path: str | os.PathLike, name: str) -> Any:
    """The note ``name`` of a study file (:func:`store_note`), None if it has none."""
    with h5py.File(path, "r") as f:
        return json.loads(f.attrs.get("notes", "{}")).get(name)


def open_study(path: str | os.PathLike, func: Callable[[dict], dict], study_attrs: dict | None = None,
               seed: int | None = None, resume: bool = False, definition: dict | None = None) -> set[str]:
    """Make a study file — its attributes and ``definition``, no case yet — or check it for resuming,
    as :func:`run_study` does first; returns the keys stored with status ok. A command with work to do
    before its cases calls it first (holding :func:`study_lock`), so that the file, with what a resume
    needs, exists from the start. Raises :class:`ArchdemInputError` as :func:`run_study` does."""
    path = Path(path)
    if path.is_dir():
        raise ArchdemInputError(f"{path} is a folder; a study is one .h5 file")
    writable_dir(path.parent)
    with study_lock(path):
        return _open_study(path, function_name(func), dict(study_attrs or {}), seed, resume, definition)


def _open_study(path: Path, func_name: str, study_attrs: dict, seed: int | None, resume: bool,
                definition: dict | None = None) -> set[str]:
    """Create the study file, or check it for resuming; return the keys stored with status ok."""

    params_json, seed_json = canonical_json(study_attrs), canonical_json(seed)
    _recover(path)
    if path.exists():
        if not resume:
            raise ArchdemInputError(f"{path} exists; a study is never overwritten (resume it, or choose another file)")
        try:
            with h5py.File(path, "r") as f:
                if "archdem_study" not in f.attrs:
                    raise ArchdemInputError(f"{path}: not an archdem study file; cannot resume it")
                have = (str(f.attrs["case_function"]), str(f.attrs["study_attrs"]), str(f.attrs["seed"]))
                done = {k for k, g in f.get("cases", {}).items() if g.attrs.get("status") == "ok"}
        except OSError as exc:
            reason = str(exc).split("(")[0].strip() or type(exc).__name__  # HDF5's details span several lines
            raise ArchdemInputError(f"{path}: not a readable HDF5 study file ({reason})") from None
        for what, old, new in (("case function", have[0], func_name), ("study parameters", have[1], params_json),
                               ("seed", have[2], seed_json)):
            if old != new:
                raise ArchdemInputError(f"{path} holds a study with another {what} ({old} vs {new}); not resuming it")
        return done
    with atomic_path(path) as tmp:  # the whole header or no file: a stop here leaves nothing to resume
        with h5py.File(tmp, "w") as f:
            f.attrs["archdem_study"] = LAYOUT_VERSION
            f.attrs["case_function"] = func_name
            f.attrs["study_attrs"] = params_json
            f.attrs["seed"] = seed_json
            f.attrs["versions"] = canonical_json(_versions())
            f.attrs["created"] = _now()
            if definition is not None:
                f.attrs["definition"] = canonical_json(definition)
            f.create_group("cases")
    return set()


# ----------------------------------------------------------------------------- executors
class _LocalPool:
    def __init__(self, workers: int):

        self.ex = StoppablePool(max_workers=workers, mp_context=multiprocessing.get_context("spawn"),
                                initializer=pool_worker_init)

    def submit(self, fn, *args):
        return self.ex.submit(fn, *args)

    def as_completed(self, futures):
        return pool_as_completed(futures)

    def close(self, cancel: bool) -> None:
        if cancel:
            stop_pool(self.ex)  # now: its workers would go on with the cases queued to them
        else:
            self.ex.shutdown(wait=True)


#: Seconds to wait for a Dask scheduler to accept a connection before the address is refused.
SCHEDULER_CONNECT_TIMEOUT = 3.0


def check_scheduler(address: str, timeout: float = SCHEDULER_CONNECT_TIMEOUT) -> None:
    """Refuse, in one line, a scheduler address that is not ``tcp://HOST:PORT`` or where nothing
    accepts a connection within ``timeout`` [s] (Dask's own client would retry for its full timeout)."""

    require("distributed", "a Dask scheduler (--scheduler)")  # a missing extra is named first
    try:
        u = urlsplit(str(address))
        host, port = u.hostname, u.port
    except ValueError:
        host = port = None
    if u.scheme != "tcp" or not host or port is None:
        raise ArchdemInputError(f"a Dask scheduler address is tcp://HOST:PORT, got {address!r}")
    try:
        socket.create_connection((host, port), timeout=timeout).close()
    except OSError as exc:
        raise ArchdemInputError(f"cannot connect to the Dask scheduler {address}: {exc}") from None


class _DaskPool:
    def __init__(self, address: str):
        Client = require("distributed", "a Dask scheduler (--scheduler)").Client

        try:
            self.client = Client(address, timeout="20s")
        except OSError as exc:
            raise ArchdemInputError(f"cannot connect to the Dask scheduler {address}: {exc}") from None

    def submit(self, fn, *args):
        return self.client.submit(fn, *args, pure=False)

    def as_completed(self, futures):
        # deferred: an optional extra (docs/architecture.md#imports)
        from distributed import as_completed

        return as_completed(futures)

    def close(self, cancel: bool) -> None:
        self.client.close()


@contextlib.contextmanager
def executor(workers: int, scheduler: str | None = None) -> Iterator[tuple[Any, int]]:
    """``(executor, slots)``: a ``concurrent.futures`` executor of ``workers`` local processes (that end
    with their parent), or a Dask cluster's (``scheduler``), whose slots are its workers' threads;
    for the sweeps that schedule runs themselves (threshold scans and bisections)."""
    if scheduler:
        check_scheduler(scheduler)
        pool = _DaskPool(scheduler)
        try:
            yield pool.client.get_executor(pure=False), max(1, sum(pool.client.nthreads().values()))
        finally:
            pool.close(True)
        return

    with worker_pool(workers) as ex:
        yield ex, workers


def _crash_error(exc: BaseException) -> str | None:
    """Error text if ``exc`` means 'the worker died running this case' on a Dask cluster."""
    try:
        from distributed.scheduler import KilledWorker
    except ImportError:  # pragma: no cover
        return None
    if isinstance(exc, KilledWorker):
        return f"worker died while running this case (dask KilledWorker: {exc})"
    return None


# ----------------------------------------------------------------------------- run
def run_study(cases: Sequence[dict], func: Callable[[dict], dict], out_path: str | os.PathLike, workers: int | None = None,
              scheduler: str | None = None, resume: bool = False, progress: bool | Progress = True,
              study_attrs: dict | None = None, seed: int | None = None, definition: dict | None = None) -> StudyResult:
    """Run every case of a study and store each result in ``out_path`` as it finishes.

    ``workers``: local processes (default: all cores); ignored with ``scheduler``, a Dask
    scheduler address (``"tcp://HOST:PORT"``). ``study_attrs``: JSON-serialisable
    parameters common to the study (checked on resume). ``seed``: recorded and checked on
    resume; the engine does not use it (put per-case seeds into the cases). ``definition``: the
    command line's options, stored with a new study (see :func:`stored_definition`). ``progress``: True,
    the cases done on a terminal line (:func:`dem.core.progress.terminal`: stderr, only a terminal); False,
    nothing; a callable, called ``progress(done, total, note)`` as each case ends. Returns the
    records of ``cases`` in their order, read back from the file.
    Raises :class:`ArchdemInputError` (bad cases, existing file without ``resume``, a
    mismatching study on resume), :class:`StudyInterrupted` (a local worker died) and
    ``KeyboardInterrupt``; in each case the finished cases are in the file.
    """
    (res,) = run_studies([(cases, out_path, study_attrs, seed, definition)], func, workers, scheduler, resume, progress)
    return res


def run_studies(studies: Sequence[tuple], func: Callable[[dict], dict], workers: int | None = None,
                scheduler: str | None = None, resume: bool = False, progress: bool | Progress = True) -> list[StudyResult]:
    """Several studies of one case function, each ``(cases, out_path, study_attrs, seed[, definition])`` and stored in
    its own file as :func:`run_study` stores one, run by one pool of workers: its processes start once
    and no core waits for the end of one study before the next begins. Returns one result per study."""
    func_name = function_name(func)  # fail early, in the main process
    plan = []
    for cases, out_path, study_attrs, seed, *definition in studies:
        cases = list(cases)
        keys = [case_key(c) for c in cases]
        if len(set(keys)) != len(keys):
            dup = next(c for c, k in zip(cases, keys) if keys.count(k) > 1)
            raise ArchdemInputError(f"duplicate case in the study: {canonical_json(dup)}")
        plan.append((Path(out_path), cases, keys, dict(study_attrs or {}), seed, definition[0] if definition else None))
    if len({p for p, *_ in plan}) != len(plan):
        raise ArchdemInputError("two studies of one run share a file")
    if workers is not None and (int(workers) != workers or workers < 1):
        raise ArchdemInputError(f"workers must be a positive integer, got {workers!r}")
    if scheduler:
        check_scheduler(scheduler)  # before the study file is made: a refused address leaves nothing behind
    for path, *_ in plan:
        if path.is_dir():
            raise ArchdemInputError(f"{path} is a folder; a study is one .h5 file")
        writable_dir(path.parent)
    with contextlib.ExitStack() as locks:
        for path, *_ in plan:  # every file is ours before any is made
            locks.enter_context(study_lock(path))
        todo = []
        for path, cases, keys, study_attrs, seed, definition in plan:
            done = _open_study(path, func_name, study_attrs, seed, resume, definition)
            todo += [(k, c, path) for k, c in zip(keys, cases) if k not in done]
        if todo:
            _execute(todo, func, workers, scheduler, progress)
    return [load_study(path, cases) for path, cases, *_ in plan]


def lock_path(study: str | os.PathLike) -> Path:
    """The lock file held beside a study file while a study writes into it (removed at the end)."""
    study = Path(study)
    return study.with_name(f".{study.name}.lock")


_held = threading.local()  # the study locks this thread holds (.counts: path -> times taken)


@contextlib.contextmanager
def study_lock(path: str | os.PathLike) -> Iterator[None]:
    """Hold a study file's lock (:func:`lock_path`; another process is refused in one line) across
    several calls: a command that works before and between its runs of the study keeps the file its
    own throughout; the calls inside, :func:`run_study` among them, take it again at no cost."""
    key, held = Path(os.path.abspath(path)), _held.__dict__.setdefault("counts", {})
    if key in held:
        held[key] += 1
        try:
            yield
        finally:
            held[key] -= 1
        return
    with exclusive(lock_path(path), f"the study file {path}", remove=True):
        held[key] = 1
        try:
            yield
        finally:
            del held[key]
            # every write is whole unless a SIGKILL cut it (then nothing runs here)
            with contextlib.suppress(FileNotFoundError):
                spare_path(path).unlink()


def _execute(todo, func, workers, scheduler, progress) -> None:

    pool = _DaskPool(scheduler) if scheduler else _LocalPool(min(int(workers or os.cpu_count() or 1), len(todo)))
    files = list(dict.fromkeys(Path(p).name for *_, p in todo))
    what = f"study {files[0]}" if len(files) == 1 else f"{len(files)} studies"
    bar = progress if callable(progress) else terminal(what, unit="cases", enabled=bool(progress))
    n_ok = n_failed = 0
    written: set = set()
    futures: dict = {}
    path = " and ".join(dict.fromkeys(str(p) for *_, p in todo))  # where the finished cases are, for the messages

    def store(fut, out) -> None:
        nonlocal n_ok, n_failed
        key, case, where = futures[fut]
        rec = _write_case(where, key, case, out)
        written.add(fut)
        if rec.ok:
            n_ok += 1
        else:
            n_failed += 1
            last = rec.error.strip().splitlines()[-1] if rec.error.strip() else "error"
            msg = f"case {key} {canonical_json(case)} failed: {last}"
            if isinstance(bar, TerminalLine):
                bar.write(msg)
            else:
                print(msg, file=sys.stderr)
        bar(n_ok + n_failed, len(todo), f"ok {n_ok}, failed {n_failed}")

    cancel = True
    bar(0, len(todo), "starting")
    try:
        for key, case, where in todo:
            futures[pool.submit(_run_case, func, case)] = (key, case, where)
        for fut in pool.as_completed(list(futures)):
            try:
                out = fut.result()
            except BrokenProcessPool:
                raise StudyInterrupted(
                    f"a worker process died; {n_ok + n_failed} finished cases of this run are stored in {path}; "
                    f"resume the study to run the other {len(todo) - n_ok - n_failed}") from None
            except Exception as exc:  # noqa: BLE001
                msg = _crash_error(exc)
                if msg is None and scheduler:  # case errors come back as results: this is the cluster
                    raise StudyInterrupted(
                        f"lost the Dask cluster ({type(exc).__name__}); {n_ok + n_failed} finished cases of this run "
                        f"are stored in {path}; resume the study to run the other {len(todo) - n_ok - n_failed}") from None
                if msg is None:
                    raise
                out = {"status": "failed", "results": {}, "error": msg, "wall": math.nan, "worker": ""}
            store(fut, out)
            raise_if_stopped()  # an interrupt Python dropped (raised where it cannot propagate)
        cancel = False
    except BaseException:
        # interrupted: keep whatever finished but was not collected yet, then stop
        for fut in futures:
            if fut not in written and _finished_ok(fut):
                try:
                    store(fut, fut.result())
                except Exception:  # noqa: BLE001 - best effort while stopping
                    pass
        raise
    finally:
        if isinstance(bar, TerminalLine):
            bar.close()
        pool.close(cancel)


def _finished_ok(fut) -> bool:
    """True if a (concurrent.futures or Dask) future finished with a returned value."""
    try:
        if not fut.done() or fut.cancelled():
            return False
        status = getattr(fut, "status", None)  # Dask futures
        if status is not None:
            return status == "finished"
        return fut.exception(timeout=0) is None
    except BaseException:  # noqa: BLE001
        return False
