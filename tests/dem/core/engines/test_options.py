"""Each engine's options: defaults, validation, their stored form, and get_engine taking them."""
import json
import subprocess
import sys

import pytest

from dem.core.engines import available_engines, get_engine
from dem.core.engines.options import (
    OPTIONS,
    LMGC90Options,
    MuJoCoOptions,
    PyBulletOptions,
    engine_options,
    legacy_options,
)
from foundation.errors import ArchdemInputError


def test_every_engine_has_its_options_class():
    assert sorted(OPTIONS) == available_engines()
    assert {c.engine for c in OPTIONS.values()} == set(available_engines())


@pytest.mark.parametrize("cls", [PyBulletOptions, MuJoCoOptions, LMGC90Options])
def test_options_round_trip_through_json_and_are_hashable(cls):
    o = cls()
    d = json.loads(json.dumps(o.to_dict()))  # as result files store them
    assert cls.from_dict(d) == o and hash(cls.from_dict(d)) == hash(o)
    assert o.with_() == o


def test_every_field_is_documented_with_its_default():
    # the options' documentation: a docstring under each field that starts with its default
    import ast
    import inspect

    from dem.core.engines import options

    tree = ast.parse(inspect.getsource(options))
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and node.name in {c.__name__ for c in OPTIONS.values()}:
            body = node.body
            for k, stmt in enumerate(body):
                if isinstance(stmt, ast.AnnAssign) and "ClassVar" not in ast.unparse(stmt.annotation):
                    doc = body[k + 1]
                    assert isinstance(doc, ast.Expr) and isinstance(doc.value, ast.Constant), stmt.target.id
                    assert doc.value.value.startswith("Default"), stmt.target.id


def test_values_read_from_a_file_get_their_types_back():
    o = PyBulletOptions.from_dict({"solver_iterations": 50.0, "friction_anchor": 0, "sat_features": 1})
    assert o.solver_iterations == 50 and o.friction_anchor is False and o.sat_features is True
    m = MuJoCoOptions.from_dict({"solref": [0.002, 1.0], "solimp": [0.9, 0.95, 0.001], "cone": b"pyramidal"})
    assert m.solref == (0.002, 1.0) and m.solimp == (0.9, 0.95, 0.001) and m.cone == "pyramidal"


@pytest.mark.parametrize("cls, kw, what", [
    (PyBulletOptions, {"solver_iterations": 0}, "solver_iterations"),
    (PyBulletOptions, {"solver_iterations": 2.5}, "solver_iterations"),
    (PyBulletOptions, {"solver_iterations": True}, "solver_iterations"),
    (PyBulletOptions, {"contact_slop": -1e-6}, "contact_slop"),
    (PyBulletOptions, {"inflate": float("nan")}, "inflate"),
    (PyBulletOptions, {"warm_starting": 1.5}, "warm_starting"),
    (PyBulletOptions, {"friction_anchor": "yes"}, "friction_anchor"),
    (MuJoCoOptions, {"max_dt": 0.0}, "max_dt"),
    (MuJoCoOptions, {"solref": (0.001,)}, "solref"),
    (MuJoCoOptions, {"noslip_iterations": -1}, "noslip_iterations"),
    (MuJoCoOptions, {"cone": "round"}, "cone"),
    (MuJoCoOptions, {"compliant_impedance": 0.0}, "compliant_impedance"),
    (LMGC90Options, {"theta": 1.5}, "theta"),
    (LMGC90Options, {"alert": 0}, "alert"),
    (LMGC90Options, {"law": ""}, "law"),
])
def test_bad_options_are_refused_in_one_line(cls, kw, what):
    with pytest.raises(ArchdemInputError, match=what) as e:
        cls(**kw)
    assert "\n" not in str(e.value)


def test_unknown_option_names_are_refused():
    with pytest.raises(ArchdemInputError, match="unknown option.*solver_iterations.*mujoco"):
        MuJoCoOptions.from_dict({"solver_iterations": 50})


def test_engine_options_resolves_none_dicts_and_refuses_another_engines():
    assert engine_options("mujoco") == MuJoCoOptions()
    assert engine_options("pybullet", {"solver_iterations": 50}) == PyBulletOptions(solver_iterations=50)
    o = LMGC90Options(theta=1.0)
    assert engine_options("lmgc90", o) is o
    with pytest.raises(ArchdemInputError, match="the mujoco engine takes MuJoCoOptions, not the options of pybullet"):
        engine_options("mujoco", PyBulletOptions())
    with pytest.raises(ArchdemInputError, match="unknown engine 'nope'"):
        engine_options("nope")


def test_get_engine_takes_its_options_and_refuses_another_engines():
    o = PyBulletOptions(solver_iterations=50)
    e = get_engine("pybullet", o)
    assert e.options is o
    assert get_engine("pybullet").options == PyBulletOptions()
    with pytest.raises(ArchdemInputError, match="the pybullet engine takes PyBulletOptions") as err:
        get_engine("pybullet", MuJoCoOptions())
    assert "\n" not in str(err.value)


def test_legacy_flat_keys_set_what_each_engine_read():
    kw = {"mu_joint": 0.7, "solver_iterations": 50, "inflate": 2e-6, "friction_erp": 0.9}
    assert legacy_options("pybullet", dict(kw)) == {"solver_iterations": 50, "inflate": 2e-6, "friction_erp": 0.9}
    assert legacy_options("mujoco", dict(kw)) == {"inflate": 2e-6}  # MuJoCo offset its hulls by it too
    assert legacy_options("lmgc90", dict(kw)) == {}
    left = dict(kw)
    legacy_options("lmgc90", left)
    assert left == {"mu_joint": 0.7}  # the flat keys are taken out whatever the engine


def test_the_options_import_no_engine_library():
    code = ("import sys\nimport dem.core.settings, dem.core.engines.options\n"
            "print(' '.join(sorted({m.split('.')[0] for m in sys.modules} & {'pybullet', 'mujoco', 'compas_lmgc90'})))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == ""
