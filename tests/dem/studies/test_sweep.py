"""The sweep engine (dem/studies/sweep.py): one writer, resume, failures, local pool vs Dask.

The case function is ``dem.studies.selftest_cases.evaluate`` (in the package, so spawned pool
workers and Dask workers import it by reference). Evaluations are counted by the files the
case function writes into ``count_dir``. The independent truth for results is the same
function called directly in this process.
"""
from __future__ import annotations

import os
import signal
import socket
import threading
import time
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

from dem.studies.selftest_cases import _take, evaluate
from dem.studies.sweep import StudyInterrupted, case_key, load_study, run_study
from foundation.errors import ArchdemInputError

FUNC = evaluate
NO_DASK = "the cluster extra is not installed (pip install -e '.[cluster]')"


def kill_or_evaluate(case: dict) -> dict:
    """Stand-in case: ``die`` kills the process running it (SIGKILL, as the OOM killer does), every
    time; any other case is ``evaluate``'s. Dask workers import it by name, as pytest imported it."""
    if case.get("die"):
        os.kill(os.getpid(), signal.SIGKILL)
    return evaluate(case)


KILL_FUNC = kill_or_evaluate


def _cases(n, count_dir=None, **extra):
    out = []
    for i in range(n):
        c = {"x": i, **extra}
        if count_dir is not None:
            c["count_dir"] = str(count_dir)
        out.append(c)
    return out


def _counts(count_dir: Path) -> Counter:
    return Counter(int(p.name.split("-")[0]) for p in count_dir.iterdir())


def _assert_same(a, b):
    """Two result dicts are equal (arrays elementwise, everything else by ==)."""
    assert a.keys() == b.keys()
    for k in a:
        if isinstance(a[k], dict):
            _assert_same(a[k], b[k])
        elif isinstance(a[k], np.ndarray) or isinstance(b[k], np.ndarray):
            np.testing.assert_array_equal(a[k], b[k])
        else:
            assert a[k] == b[k] and type(a[k]) is type(b[k]), (k, a[k], b[k])


def test_results_identical_with_1_and_2_workers_and_equal_direct_call(tmp_path):
    cases = _cases(8)
    r1 = run_study(cases, FUNC, tmp_path / "w1.h5", workers=1, progress=False)
    r2 = run_study(cases, FUNC, tmp_path / "w2.h5", workers=2, progress=False)
    assert [r.key for r in r1] == [r.key for r in r2] == [case_key(c) for c in cases]
    for a, b, c in zip(r1, r2, cases):
        assert a.status == b.status == "ok"
        _assert_same(a.results, b.results)
        # stored and read back == computed directly (lists of strings come back as lists)
        _assert_same(a.results, evaluate(c))
    # load_study gives the same records as run_study returned
    again = load_study(tmp_path / "w2.h5", cases)
    for a, b in zip(r2, again):
        assert (a.key, a.params, a.status, a.error, a.wall) == (b.key, b.params, b.status, b.error, b.wall)
        _assert_same(a.results, b.results)
    assert again.attrs["case_function"] == "dem.studies.selftest_cases:evaluate"
    assert {"archdem", "python", "numpy", "h5py"} <= set(again.attrs["versions"])


def test_failing_case_recorded_others_complete(tmp_path, capsys):
    cases = _cases(5)
    cases[2]["fail"] = True
    res = run_study(cases, FUNC, tmp_path / "s.h5", workers=2, progress=False)
    assert [r.status for r in res] == ["ok", "ok", "failed", "ok", "ok"]
    bad = res[2]
    assert "Traceback" in bad.error and "ValueError: case x=2 fails on purpose" in bad.error
    assert bad.results == {}
    stored = load_study(tmp_path / "s.h5").by_key[bad.key]
    assert stored.status == "failed" and stored.error == bad.error
    err = capsys.readouterr().err
    assert sum("failed: ValueError: case x=2 fails on purpose" in line for line in err.splitlines()) == 1


def test_refuses_to_overwrite_and_to_resume_another_study(tmp_path):
    p = tmp_path / "s.h5"
    run_study(_cases(2), FUNC, p, workers=1, progress=False, study_attrs={"config": "glued"})
    before = p.read_bytes()
    with pytest.raises(ArchdemInputError, match="never overwritten"):
        run_study(_cases(2), FUNC, p, workers=1, progress=False, study_attrs={"config": "glued"})
    with pytest.raises(ArchdemInputError, match="study parameters"):
        run_study(_cases(2), FUNC, p, resume=True, progress=False, study_attrs={"config": "free"})
    with pytest.raises(ArchdemInputError, match="case function"):
        run_study(_cases(2), _take, p, resume=True, progress=False,
                  study_attrs={"config": "glued"})
    with pytest.raises(ArchdemInputError, match="seed"):
        run_study(_cases(2), FUNC, p, resume=True, progress=False, study_attrs={"config": "glued"}, seed=3)
    assert p.read_bytes() == before  # nothing touched the existing study
    with pytest.raises(ArchdemInputError, match="duplicate"):
        run_study(_cases(2) + _cases(1), FUNC, tmp_path / "d.h5", progress=False)
    for not_importable in ("dem.studies.selftest_cases:evaluate", lambda case: {}):
        with pytest.raises(ArchdemInputError, match="module-level function"):
            run_study(_cases(1), not_importable, tmp_path / "e.h5", progress=False)
    assert not (tmp_path / "e.h5").exists()


def test_resume_subset_then_full_evaluates_each_case_once(tmp_path):
    counts = tmp_path / "counts"
    counts.mkdir()
    cases = _cases(10, counts)
    p = tmp_path / "s.h5"
    run_study(cases[:4], FUNC, p, workers=2, progress=False)
    res = run_study(cases, FUNC, p, workers=2, resume=True, progress=False)
    assert [r.status for r in res] == ["ok"] * 10
    assert _counts(counts) == Counter(range(10))  # every case exactly once over both runs


def test_resume_retries_failed_cases_only(tmp_path):
    counts = tmp_path / "counts"
    counts.mkdir()
    marker = tmp_path / "fail-once"
    marker.touch()
    cases = _cases(6, counts)
    cases[3]["fail_marker"] = str(marker)
    p = tmp_path / "s.h5"
    first = run_study(cases, FUNC, p, workers=2, progress=False)
    assert [r.status for r in first].count("failed") == 1 and not first[3].ok
    second = run_study(cases, FUNC, p, workers=2, resume=True, progress=False)
    assert [r.status for r in second] == ["ok"] * len(cases)
    assert _counts(counts) == Counter({0: 1, 1: 1, 2: 1, 3: 2, 4: 1, 5: 1})


@pytest.mark.slow
def test_crashed_worker_loses_and_repeats_nothing_finished(tmp_path):
    counts = tmp_path / "counts"
    counts.mkdir()
    marker = tmp_path / "crash-once"
    marker.touch()
    cases = _cases(10, counts)
    cases[5]["crash_marker"] = str(marker)  # the worker running case 5 dies (os._exit) the first time
    p = tmp_path / "s.h5"
    with pytest.raises(StudyInterrupted, match="resume"):
        run_study(cases, FUNC, p, workers=2, progress=False)
    stored_first = {r.key for r in load_study(p) if r.ok}
    assert case_key(cases[5]) not in stored_first
    assert 1 <= len(stored_first) < 10  # a real interruption: some stored, some not
    after_first = _counts(counts)
    res = run_study(cases, FUNC, p, workers=2, resume=True, progress=False)
    assert [r.status for r in res] == ["ok"] * len(cases)
    total = _counts(counts)
    for i, c in enumerate(cases):
        if case_key(c) in stored_first:
            assert total[i] == after_first[i] == 1  # stored cases are not evaluated again
        else:
            # not stored: run (again) on resume; at most once more than before (it may have
            # been running in the other worker when the pool broke — in-flight work is lost)
            assert total[i] == after_first[i] + 1
    assert len(load_study(p)) == 10


def test_keyboard_interrupt_keeps_finished_cases(tmp_path):
    counts = tmp_path / "counts"
    counts.mkdir()
    marker = tmp_path / "interrupt-once"
    marker.touch()
    cases = _cases(6, counts)
    cases[3]["interrupt_marker"] = str(marker)
    p = tmp_path / "s.h5"
    with pytest.raises(KeyboardInterrupt):
        run_study(cases, FUNC, p, workers=1, progress=False)
    stored_first = {r.key for r in load_study(p)}
    # one worker runs the cases in order: 0-2 finished (and are stored) before 3 interrupted
    assert {case_key(c) for c in cases[:3]} <= stored_first and case_key(cases[3]) not in stored_first
    after_first = _counts(counts)
    res = run_study(cases, FUNC, p, workers=1, resume=True, progress=False)
    assert [r.status for r in res] == ["ok"] * len(cases)
    total = _counts(counts)
    for i, c in enumerate(cases):
        assert total[i] == after_first[i] + (case_key(c) not in stored_first)


@pytest.mark.slow
def test_dask_local_cluster_gives_same_results_as_local_pool(tmp_path):
    distributed = pytest.importorskip("distributed", reason=NO_DASK)
    cases = _cases(6)
    cases[4]["fail"] = True
    local = run_study(cases, FUNC, tmp_path / "local.h5", workers=2, progress=False)
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                  dashboard_address=None) as cluster:
        remote = run_study(cases, FUNC, tmp_path / "dask.h5", scheduler=cluster.scheduler_address, progress=False)
    assert [r.status for r in remote] == [r.status for r in local]
    for a, b in zip(local, remote):
        assert a.key == b.key and a.params == b.params
        _assert_same(a.results, b.results)
    assert remote[4].error.splitlines()[-1] == local[4].error.splitlines()[-1]


@pytest.mark.slow
def test_case_interrupted_while_written_counts_as_not_stored(tmp_path):
    import h5py

    counts = tmp_path / "counts"
    counts.mkdir()
    cases = _cases(4, counts)
    p = tmp_path / "s.h5"
    run_study(cases, FUNC, p, workers=2)  # default progress=True: disabled off a terminal
    with h5py.File(p, "a") as f:  # a kill between the group's data and its status attribute
        del f["cases"][case_key(cases[1])].attrs["status"]
    assert case_key(cases[1]) not in load_study(p).by_key
    res = run_study(cases, FUNC, p, workers=2, resume=True)
    assert [r.status for r in res] == ["ok"] * len(cases)
    assert _counts(counts) == Counter({0: 1, 1: 2, 2: 1, 3: 1})


@pytest.mark.slow
def test_dask_killed_worker_recorded_as_failed_others_complete(tmp_path):
    distributed = pytest.importorskip("distributed", reason=NO_DASK)
    marker = tmp_path / "crash-once"
    marker.touch()
    cases = _cases(5)
    cases[0]["crash_marker"] = str(marker)  # kills the first worker to run it (os._exit): Dask retries it
    cases[4]["die"] = True  # kills every worker that runs it: Dask gives up (KilledWorker)
    # Dask counts a death against every case running or queued on the dying worker: the killer is
    # submitted last, so that the others have run before it (default Dask settings: 4 deaths)
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                  dashboard_address=None) as cluster:
        res = run_study(cases, KILL_FUNC, tmp_path / "s.h5", scheduler=cluster.scheduler_address, progress=False)
    assert res[4].status == "failed"
    assert res[4].error.startswith("worker died while running this case (dask KilledWorker")
    # Dask also blames a case that was queued on a dying worker (seen in 1 of about 6 full runs):
    # such a case is recorded as failed by the kill, never stored with wrong results
    for r in res[:4]:
        assert r.ok or r.error.startswith("worker died while running this case (dask KilledWorker")
    assert sum(r.ok for r in res[:4]) >= 3
    assert res[4].results == {} and load_study(tmp_path / "s.h5").by_key[res[4].key].status == "failed"
    assert not marker.exists()  # case 0 did kill a worker before it succeeded
    for r, c in zip(res, cases):
        if r.ok:
            _assert_same(r.results, evaluate(c))


def _refusing_address() -> tuple[socket.socket, str]:
    """A local TCP port bound but never listening: connecting is refused, and while the socket is
    open no other process can take the port (a port merely found free may be reused at once)."""
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    return s, f"tcp://127.0.0.1:{s.getsockname()[1]}"


def test_dask_unreachable_scheduler_is_an_input_error_and_leaves_no_file(tmp_path):
    pytest.importorskip("distributed", reason=NO_DASK)
    sock, address = _refusing_address()
    with sock, pytest.raises(ArchdemInputError) as exc:
        run_study(_cases(2), FUNC, tmp_path / "s.h5", scheduler=address, progress=False)
    msg = str(exc.value)
    assert msg.startswith(f"cannot connect to the Dask scheduler {address}: ") and "\n" not in msg
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("address", ["garbage", "tcp://", "tcp://host", "udp://127.0.0.1:8786", "tcp://h:notaport"])
def test_malformed_scheduler_address_is_an_input_error(tmp_path, address):
    with pytest.raises(ArchdemInputError, match="tcp://HOST:PORT"):
        run_study(_cases(1), FUNC, tmp_path / "s.h5", scheduler=address, progress=False)
    assert list(tmp_path.iterdir()) == []


def test_dask_unreachable_scheduler_fails_quickly(tmp_path, monkeypatch):
    """A refused address is answered by archdem's own connection check, before a Dask client exists
    (the client would retry for its full 20 s): no wall-clock limit, which a busy machine can miss."""
    distributed = pytest.importorskip("distributed", reason=NO_DASK)

    def no_client(*args, **kwargs):
        raise AssertionError("a Dask client was made for a refused address")

    monkeypatch.setattr(distributed, "Client", no_client)
    sock, address = _refusing_address()
    with sock, pytest.raises(ArchdemInputError, match="cannot connect to the Dask scheduler"):
        run_study(_cases(1), FUNC, tmp_path / "s.h5", scheduler=address, progress=False)


@pytest.mark.slow
def test_a_second_writer_of_a_study_file_is_refused_and_the_lock_goes_away(tmp_path):
    """Two studies into one file at once: the second is refused at once (it would interleave its
    cases with the first one's); the first completes, and its lock file is removed."""
    from dem.studies.sweep import lock_path

    p = tmp_path / "s.h5"
    first = threading.Thread(target=run_study, args=(_cases(2, sleep=1.5), FUNC, p),
                             kwargs={"workers": 1, "progress": False})
    first.start()
    try:
        deadline = time.monotonic() + 30
        while not p.exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert p.exists()
        with pytest.raises(ArchdemInputError, match="being written by another archdem process"):
            run_study(_cases(2, sleep=1.5), FUNC, p, resume=True, workers=1, progress=False)
    finally:
        first.join()
    assert [r.ok for r in load_study(p).records] == [True, True]
    assert not lock_path(p).exists()
    run_study(_cases(3, sleep=1.5), FUNC, p, resume=True, workers=1, progress=False)  # the lock is free again
    assert len(load_study(p).records) == 3


def test_a_folder_is_not_a_study_file(tmp_path):
    (tmp_path / "d").mkdir()
    with pytest.raises(ArchdemInputError, match="is a folder"):
        run_study(_cases(1), FUNC, tmp_path / "d", resume=True, progress=False)
    bad = tmp_path / "bad.h5"
    bad.write_text("not hdf5\n")
    with pytest.raises(ArchdemInputError, match=r"not a readable HDF5 study file \([^\n]*\)$"):
        run_study(_cases(1), FUNC, bad, resume=True, progress=False)


@pytest.mark.slow
def test_a_scheduler_lost_mid_study_leaves_a_resumable_study(tmp_path, monkeypatch):
    """The cluster goes away while cases run: the study stops with StudyInterrupted (one line for the
    CLI), the finished cases are in the file, and a resume on the local pool completes it."""
    from dem.studies import sweep

    distributed = pytest.importorskip("distributed", reason=NO_DASK)
    cases = _cases(8, sleep=0.6)
    p = tmp_path / "s.h5"
    cluster = distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None)
    # counted where the study writes: reading the file from this process while it is written makes
    # HDF5 refuse the writer ("already open for read-only")
    written = []

    def counted(*args, **kw):
        rec = write_case(*args, **kw)
        written.append(rec)
        return rec

    write_case = sweep._write_case
    monkeypatch.setattr(sweep, "_write_case", counted)

    def stop_later():
        while len(written) < 2:
            time.sleep(0.05)
        cluster.close()

    threading.Thread(target=stop_later, daemon=True).start()
    with pytest.raises(StudyInterrupted, match="lost the Dask cluster") as exc:
        run_study(cases, FUNC, p, scheduler=cluster.scheduler_address, progress=False)
    assert "\n" not in str(exc.value)
    done = len(load_study(p).by_key)
    assert 2 <= done < len(cases)
    res = run_study(cases, FUNC, p, workers=2, resume=True, progress=False)
    assert [r.status for r in res] == ["ok"] * len(cases)


def test_the_definition_of_a_new_study_is_stored_and_a_resume_keeps_it(tmp_path):
    from dem.studies.sweep import stored_definition

    p = tmp_path / "s.h5"
    run_study(_cases(2), FUNC, p, workers=1, progress=False, definition={"mu": "0.4,0.8", "specimens": "A,B"})
    assert stored_definition(p) == {"mu": "0.4,0.8", "specimens": "A,B"}
    # a resume does not rewrite it, whatever it is given
    run_study(_cases(3), FUNC, p, workers=1, resume=True, progress=False, definition={"mu": "other"})
    assert stored_definition(p) == {"mu": "0.4,0.8", "specimens": "A,B"}
    run_study(_cases(1), FUNC, tmp_path / "bare.h5", workers=1, progress=False)
    assert stored_definition(tmp_path / "bare.h5") is None
    (tmp_path / "x.h5").write_text("not hdf5")
    with pytest.raises(ArchdemInputError, match="not a readable HDF5 study file"):
        stored_definition(tmp_path / "x.h5")


@pytest.mark.slow
def test_studies_on_one_pool_store_what_each_stores_alone(tmp_path):
    """run_studies: each study in its own file with its own parameters, the records run_study gives it
    alone; a file named twice is refused before anything is written."""
    from dem.studies.sweep import run_studies

    a, b = _cases(3), _cases(2, y=1.0)
    both = run_studies([(a, tmp_path / "a.h5", {"s": "a"}, 1), (b, tmp_path / "b.h5", {"s": "b"}, 2)], FUNC,
                       workers=2, progress=False)
    alone = [run_study(a, FUNC, tmp_path / "a1.h5", workers=1, progress=False, study_attrs={"s": "a"}, seed=1),
             run_study(b, FUNC, tmp_path / "b1.h5", workers=1, progress=False, study_attrs={"s": "b"}, seed=2)]
    for x, y in zip(both, alone):
        assert (x.attrs["study_attrs"], x.attrs["seed"]) == (y.attrs["study_attrs"], y.attrs["seed"])
        assert [r.key for r in x] == [r.key for r in y] and all(r.ok for r in x)
        for r, q in zip(x, y):
            _assert_same(r.results, q.results)
    with pytest.raises(ArchdemInputError, match="share a file"):
        run_studies([(a, tmp_path / "c.h5", None, None), (b, tmp_path / "c.h5", None, None)], FUNC, progress=False)
    assert not (tmp_path / "c.h5").exists()


def test_progress_callable_sees_every_case_and_a_failure(tmp_path):
    # progress=callable: progress(done, total, note) as each case ends (a failing one counted too)
    calls = []
    cases = _cases(3) + [{"x": 9, "fail": True}]
    run_study(cases, FUNC, tmp_path / "s.h5", workers=1, progress=lambda *a: calls.append(a))
    assert calls[0] == (0, 4, "starting")
    assert [c[:2] for c in calls[1:]] == [(1, 4), (2, 4), (3, 4), (4, 4)]
    assert calls[-1][2] == "ok 3, failed 1"


def test_progress_line_is_silent_off_a_terminal(tmp_path, capsys):
    # progress=True (the commands' default) draws nothing when stderr is not a terminal (pytest captures it)
    run_study(_cases(2), FUNC, tmp_path / "s.h5", workers=1, progress=True)
    assert capsys.readouterr().err == ""
