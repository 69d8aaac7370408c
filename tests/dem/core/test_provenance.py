"""Provenance of a run: the versions, and the options of the engine that ran."""
import pytest

from dem.core.engines import engine_installed
from dem.core.engines.options import OPTIONS, PyBulletOptions
from dem.core.provenance import run_provenance


def test_a_runs_provenance_holds_the_options_it_ran_with():
    p = run_provenance("pybullet", PyBulletOptions(solver_iterations=50))
    assert p["engine"] == "pybullet" and p["pybullet_options"]["solver_iterations"] == 50
    assert run_provenance("pybullet")["pybullet_options"] == PyBulletOptions().to_dict()  # None: the defaults


@pytest.mark.parametrize("engine", ["mujoco", "lmgc90"])
def test_every_engine_stores_its_options(engine):
    if not engine_installed(engine):
        pytest.skip(f"the {engine} extra is not installed")
    opts = run_provenance(engine)[f"{engine}_options"]
    assert {k: v for k, v in opts.items() if k != "nlgs"} == OPTIONS[engine]().to_dict()
