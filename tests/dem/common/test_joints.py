"""The joint law of its parts (dem/common/joints.py): the commands' rule for a Python caller."""
from __future__ import annotations

import pytest

from dem.common.joints import joint_law_settings
from dem.core.settings import Settings
from foundation.errors import ArchdemInputError


def test_the_law_of_its_parts():
    assert joint_law_settings() == {}
    assert joint_law_settings("rigid") == {}
    assert joint_law_settings(kn=1e8) == {"contact_law": "compliant", "kn": 1e8}
    assert joint_law_settings(youngs=1e9, damping_xi=0.5, engines=["mujoco"]) == {
        "contact_law": "compliant", "youngs": 1e9, "damping_xi": 0.5}
    assert joint_law_settings(joints="table-5.1", specimen_id="Sh1-Sd020") == {
        "contact_law": "compliant", "kn": 4.1e8, "damping_beta": 1.38e-3}


@pytest.mark.parametrize("kw", [{"joints": "table-5.1", "specimen_id": "Sh1-Sd020", "kn": 1e8},
                                {"joints": "table-5.1", "specimen_id": "Sh1-Sd020", "law": "rigid"},
                                {"joints": "table-5.1", "specimen_id": "Sh1-Sd020", "damping_beta": 0.0}])
def test_the_studys_joints_come_alone(kw):
    with pytest.raises(ArchdemInputError, match="--joints table-5.1 sets the joints"):
        joint_law_settings(**kw)


def test_the_studys_joints_are_a_catalogue_specimens():
    with pytest.raises(ArchdemInputError, match="catalogue specimens only"):
        joint_law_settings(joints="table-5.1")


@pytest.mark.parametrize("fields", [{"kn": -1.0}, {"law": "rigid", "kn": 1e8}, {"law": "compliant"},
                                    {"kn": 1e8, "youngs": 1e9}, {"kn": 1e8, "damping_xi": 3.0}])
def test_a_bad_law_is_refused_in_the_settings_words(fields):
    with pytest.raises(ArchdemInputError) as mine:
        joint_law_settings(**fields)
    law = {"contact_law": fields.pop("law", "compliant"), **fields}
    with pytest.raises(ArchdemInputError) as lib:
        Settings(**law)
    assert str(mine.value) == str(lib.value)


def test_compliant_joints_on_mujoco_need_a_damping():
    with pytest.raises(ArchdemInputError, match="need --damping-beta or --damping-xi"):
        joint_law_settings(kn=1e8, engines=(None, "mujoco"))
    with pytest.raises(ArchdemInputError, match="need --damping-beta or --damping-xi"):
        joint_law_settings(kn=1e8, damping_beta=0.0, engines=("mujoco",))
    assert joint_law_settings(kn=1e8, engines=("pybullet",)) == {"contact_law": "compliant", "kn": 1e8}
    assert joint_law_settings("rigid", engines=("mujoco",)) == {}  # rigid joints need none
