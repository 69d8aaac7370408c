"""Optional dependencies: a missing extra is named in one line (exit 2 from the CLI), never a traceback."""
import sys

import pytest

from dem.cli import main
from dem.core.extras import require
from foundation.errors import ArchdemInputError


@pytest.mark.parametrize("module, extra", [("mujoco", "mujoco"), ("distributed", "cluster"), ("compas_lmgc90", "lmgc90")])
def test_a_missing_extra_is_named(monkeypatch, module, extra):
    monkeypatch.setitem(sys.modules, module, None)  # importing it now raises ImportError
    with pytest.raises(ArchdemInputError, match=rf"pip install 'archdem\[{extra}\]'"):
        require(module, "this command")


def test_cli_without_mujoco_says_which_extra(monkeypatch, capsys, tmp_path):
    monkeypatch.setitem(sys.modules, "mujoco", None)
    assert main(["tilt", "Sh02-Sd020", "--engine", "mujoco", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "archdem[mujoco]" in err


def test_cli_without_lmgc90_says_which_extra(monkeypatch, capsys, tmp_path):
    monkeypatch.setitem(sys.modules, "compas_lmgc90", None)
    assert main(["tilt", "Sh02-Sd020", "--engine", "lmgc90", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "archdem[lmgc90]" in err


def test_map_on_a_cluster_without_dask_says_which_extra(monkeypatch, capsys, tmp_path):
    monkeypatch.setitem(sys.modules, "distributed", None)
    rc = main(["map", "--specimens", "Sh02-Sd020", "--mu", "0.5", "--refine", "0", "--scheduler", "tcp://127.0.0.1:1",
               "--out", str(tmp_path / "m.h5")])
    err = capsys.readouterr().err
    assert rc == 2 and "archdem[cluster]" in err and err.count("\n") == 1
