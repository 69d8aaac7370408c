import os

# figures are written to files in tests; never open a window
os.environ.setdefault("MPLBACKEND", "Agg")


import pytest  # noqa: E402


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
