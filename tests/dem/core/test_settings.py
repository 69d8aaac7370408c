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
