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
