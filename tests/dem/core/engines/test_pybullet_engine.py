"""PyBullet backend specifics (the validation shared with every engine is in test_engines_shared.py)."""
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from dem.core.engines import get_engine
from dem.core.engines.pybullet_engine import mesh_dir
from dem.core.model import from_assembly
from dem.core.settings import Settings
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError


def test_unknown_engine():
    with pytest.raises(ArchdemInputError):
        get_engine("nope")


def test_friction_product_rule_gives_the_requested_pairs():
    # Bullet combines a contact pair's friction as the product of the bodies' coefficients
    # (docs/engines.md#2-pybullet-settings): block-block must come out as mu_joint and block-base as mu_base
    m = from_assembly(discretise(get_specimen("Sh06-Sd015").arch, config="glued"))
    s = Settings(mu_joint=0.577, mu_base=1.0)
    e = get_engine("pybullet")
    e.build(m, s)
    try:
        f = [e._p.getDynamicsInfo(b, -1)[1] for b in e._ids]
        f_base = e._p.getDynamicsInfo(e._base, -1)[1]
        assert len(f) == len(m.bodies) > 1
        assert all(a * b == pytest.approx(0.577, rel=1e-12) for a, b in zip(f, f[1:]))
        assert all(a * f_base == pytest.approx(1.0, rel=1e-12) for a in f)
    finally:
        e.close()


def test_the_mesh_folder_of_a_killed_run_is_removed_by_the_next_one(tmp_path, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    code = ("import sys, time; from dem.core.engines.pybullet_engine import mesh_dir; "
            "print(mesh_dir(), flush=True); time.sleep(60)")
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    left = Path(p.stdout.readline().strip())
    p.send_signal(signal.SIGKILL)  # no handler runs: the folder stays behind
    p.wait()
    assert left.is_dir() and left.parent == tmp_path
    mine = mesh_dir()
    assert not left.exists() and mine.is_dir() and mine.parent == tmp_path
    other = mesh_dir()  # a live process's folder (this one's) is kept
    assert mine.is_dir() and other.is_dir()


def test_building_an_engine_prints_nothing():
    # pybullet writes a "build time" banner to stderr at import and argv[0] on connection: a
    # campaign's workers would print them between its progress lines
    import subprocess
    import sys

    code = ("from dem.core.engines import get_engine\nfrom dem.core.model import as_model\n"
            "from dem.core.settings import Settings\ne = get_engine('pybullet')\n"
            "e.build(as_model('Sh06-Sd015'), Settings())\ne.close()\nprint('built')\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout == "built\n" and out.stderr == ""
