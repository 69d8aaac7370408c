import os

# figures are written to files in tests; never open a window
os.environ.setdefault("MPLBACKEND", "Agg")


import pytest  # noqa: E402

#: Timeout [s] of a test marked ``slow`` that sets none of its own (the global one, for the rest, is in
#: pyproject.toml); a Dask cluster restarting killed workers took over 900 s on a machine shared 4 ways.
SLOW_TIMEOUT = 1200


def pytest_collection_modifyitems(items):
    for item in items:
        if item.get_closest_marker("slow") and not item.get_closest_marker("timeout"):
            item.add_marker(pytest.mark.timeout(SLOW_TIMEOUT))


#: A test not marked ``slow`` belongs to ``make test-fast`` and should take about 1 s; one that took
#: longer than this [s] (twice that, for a busy machine) is named at the end of the run, to be marked.
FAST_LIMIT = 2.0
_unmarked: dict[str, float] = {}


def pytest_runtest_logreport(report):
    if report.when in ("setup", "call") and "slow" not in report.keywords:
        _unmarked[report.nodeid] = _unmarked.get(report.nodeid, 0.0) + report.duration


def pytest_terminal_summary(terminalreporter):
    over = sorted(((d, n) for n, d in _unmarked.items() if d > FAST_LIMIT), reverse=True)
    if over:
        terminalreporter.write_sep("-", f"{len(over)} tests not marked slow took over {FAST_LIMIT:g} s: mark them slow")
        for d, n in over:
            terminalreporter.write_line(f"{d:7.1f} s  {n}")


@pytest.fixture
def short_records(tmp_path):
    """Two short CSV records (2 s, 0.2 g pulses at 2 and 3 Hz): their paths."""
    import numpy as np

    files = []
    for k, f in enumerate((2.0, 3.0)):
        t = np.arange(0, 2.0, 0.005)
        a = 0.2 * np.sin(2 * np.pi * f * t) * np.exp(-((t - 1.0) / 0.35) ** 2)
        p = tmp_path / f"r{k}.csv"
        p.write_text("time [s], acc [g]\n" + "".join(f"{x:.3f}, {y:.6f}\n" for x, y in zip(t, a)))
        files.append(str(p))
    return files
