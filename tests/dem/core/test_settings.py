"""The settings of a dynamic experiment: the shakes' engine at its own step unless one is named."""
from dem.core.settings import DYNAMICS_DT, DYNAMICS_ENGINE, Settings, dynamics_settings


def test_dynamics_settings_pick_the_shakes_engine_and_its_step():
    s = dynamics_settings()
    assert (s.engine, s.dt) == (DYNAMICS_ENGINE, DYNAMICS_DT) and DYNAMICS_DT < Settings().dt
    assert dynamics_settings(dt=2.5e-4).dt == 2.5e-4  # a step given wins
    assert dynamics_settings(dt=None).dt == DYNAMICS_DT
    other = dynamics_settings(engine="pybullet", mu_joint=0.7)  # another engine: the protocol's step
    assert (other.engine, other.dt, other.mu_joint) == ("pybullet", Settings().dt, 0.7)
    assert Settings().engine == "pybullet"  # tilts keep theirs


def test_collapse_confirmation_round_trips_and_old_results_load():
    import json

    import pytest

    from foundation.errors import ArchdemInputError

    assert Settings().collapse_confirm is None  # the tilt's: a firing is the collapse
    s = Settings(collapse_fraction=1.0, mode_window=(0.015, 0.06), collapse_confirm=2.0)
    d = json.loads(json.dumps(s.to_dict()))  # as result files store it
    assert d["collapse_confirm"] == 2.0 and Settings.from_dict(d) == s
    assert Settings.from_dict(json.loads(json.dumps(Settings().to_dict()))) == Settings()  # None -> null -> None
    # a result written before the field: the firing was the collapse, which is what None says
    d.pop("collapse_confirm")
    assert Settings.from_dict(d).collapse_confirm is None
    for bad in (1.0, 0.5, float("nan"), float("inf"), True, "2"):
        with pytest.raises(ArchdemInputError, match="collapse_confirm"):
            Settings(collapse_fraction=1.0, collapse_confirm=bad)


# the flat keys a result file written before the engine options holds (Settings.to_dict then)
OLD_FILE_SETTINGS = {
    "mu_joint": 0.577, "mu_base": 1.0, "restitution": 0.0, "g": 9.81, "planar": False, "engine": "pybullet", "dt": 0.0005,
    "solver_iterations": 150, "contact_slop": 0.0, "warm_starting": 1.0, "friction_anchor": 1, "sat_features": True,
    "inflate": 2e-06, "inflate_normal": False, "contact_erp": 0.2, "friction_erp": 0.9, "contact_law": "rigid", "kn": 0.0,
    "youngs": 0.0, "damping_beta": 0.0, "damping_xi": 0.0, "collapse_fraction": 0.06, "collapse_speed": 0.001,
    "mode_window": [0.015, 0.06], "hinge_fraction": 0.05, "slide_fraction": 0.05, "record_every": 0.01,
}


def test_the_engine_options_are_the_engines_defaults_unless_given():
    from dem.core.engines.options import LMGC90Options, MuJoCoOptions, PyBulletOptions

    assert Settings().engine_options == PyBulletOptions()
    assert Settings(engine="mujoco").engine_options == MuJoCoOptions()
    assert dynamics_settings().engine_options == MuJoCoOptions()
    o = PyBulletOptions(solver_iterations=50)
    assert Settings(engine_options=o).engine_options is o
    assert Settings(engine_options={"solver_iterations": 50}).engine_options == o  # as a study case stores it
    # another engine without its options: that engine's defaults, not the options of the first one
    assert Settings(engine_options=o).with_(engine="lmgc90").engine_options == LMGC90Options()
    assert Settings(engine_options=o).with_(mu_joint=0.7).engine_options is o


def test_nothing_engine_specific_is_left_in_settings():
    from dataclasses import fields

    from dem.core.engines.options import LEGACY_KEYS

    assert not set(LEGACY_KEYS) & {f.name for f in fields(Settings)}


def test_another_engines_options_and_bad_ones_are_refused_in_one_line():
    import pytest

    from dem.core.engines.options import MuJoCoOptions
    from foundation.errors import ArchdemInputError

    for kw, what in (({"engine_options": MuJoCoOptions()}, "the pybullet engine takes PyBulletOptions"),
                     ({"engine_options": {"solver_iterations": 0}}, "solver_iterations"),
                     ({"engine_options": {"iterations": 10}}, "unknown option"),
                     ({"engine": "nope"}, "unknown engine")):
        with pytest.raises(ArchdemInputError, match=what) as e:
            Settings(**kw)
        assert "\n" not in str(e.value)


def test_the_engine_options_are_stored_and_read_back():
    import json

    from dem.core.engines.options import MuJoCoOptions

    for s in (Settings(engine_options={"solver_iterations": 50, "friction_erp": 0.8}),
              Settings(engine="mujoco", engine_options=MuJoCoOptions(solref=(0.002, 1.0), extra={"impratio": 2})),
              Settings(engine="lmgc90")):
        d = json.loads(json.dumps(s.to_dict()))
        assert d["engine_options"] == s.engine_options.to_dict() and "solver_iterations" not in d
        assert Settings.from_dict(d) == s


def test_a_result_file_written_before_the_engine_options_loads():
    import json

    from dem.core.engines.options import MuJoCoOptions, PyBulletOptions

    d = json.loads(json.dumps(OLD_FILE_SETTINGS))
    s = Settings.from_dict(d)
    assert s.engine_options == PyBulletOptions(solver_iterations=150, inflate=2e-6, friction_erp=0.9)
    assert (s.mu_joint, s.dt, s.mode_window) == (0.577, 5e-4, (0.015, 0.06))
    # MuJoCo read only the hull offset of them; LMGC90 none
    assert Settings.from_dict({**d, "engine": "mujoco"}).engine_options == MuJoCoOptions(inflate=2e-6)
    assert Settings.from_dict({**d, "engine": "lmgc90"}).engine_options == Settings(engine="lmgc90").engine_options
    # a study written then keeps them as flat keys of its cases' settings (the fragility's --solver-iterations)
    assert dynamics_settings(engine="pybullet", solver_iterations=150).engine_options.solver_iterations == 150
    assert dynamics_settings(solver_iterations=150).engine_options == MuJoCoOptions()
