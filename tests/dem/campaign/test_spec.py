"""What a campaign is asked to run: its steps, the parameters its folder resumes with, its duration text."""
import json

import pytest

from dem.campaign.runner import default_steps
from dem.campaign.spec import campaign_steps, duration, resumed
from foundation.errors import ArchdemInputError


def test_steps_named_checked_and_the_optional_ones_added():
    assert campaign_steps(None) is None
    assert campaign_steps(" tilt, map") == ["tilt", "map"]
    assert campaign_steps(None, ("piers",)) == [*default_steps(), "piers"]
    assert campaign_steps("piers,tilt", ("piers", "drawing")) == ["piers", "tilt", "drawing"]
    with pytest.raises(ArchdemInputError, match="--steps: give step names separated by commas"):
        campaign_steps("tilt,,map")
    with pytest.raises(ArchdemInputError, match="unknown campaign step.s. nope, zz; steps: catalogue,"):
        campaign_steps("tilt,nope,zz")


def _values(**kw):
    return {"specimens": "all", "config": "glued", "engine": "pybullet", "dynamics_engine": "mujoco", "quick": False,
            "contact": 1.0, "joints": None} | kw


def test_a_campaign_folder_gives_its_parameters_and_refuses_others_given(tmp_path):
    assert resumed(tmp_path, _values(), frozenset()) == _values()  # no campaign there
    (tmp_path / "campaign.json").write_text(json.dumps({"parameters": {
        "specimens": ["Sh02-Sd020"], "config": "free", "engine": "pybullet", "quick": True, "joints": "table-5.1"}}))
    got = resumed(tmp_path, _values(), frozenset())
    assert got == _values(specimens="Sh02-Sd020", config="free", quick=True, joints="table-5.1")
    assert resumed(tmp_path, _values(config="free"), frozenset({"config"}))["config"] == "free"
    with pytest.raises(ArchdemInputError, match=r"--config glued is not the campaign's in .* \(free\)"):
        resumed(tmp_path, _values(), frozenset({"config"}))
    with pytest.raises(ArchdemInputError, match=r"--specimens Sh02-Sd020,Sh1-Sd010 is not the campaign's"):
        resumed(tmp_path, _values(specimens="Sh02-Sd020,Sh1-Sd010"), frozenset({"specimens"}))


@pytest.mark.parametrize("seconds, text", [(89, "89 s"), (90, "2 min"), (5399, "90 min"), (5400, "1.5 h")])
def test_duration(seconds, text):
    assert duration(seconds) == text
