"""The rest state of an arch: a catalogue arch left under gravity settles at rest with sub-millimetre
motion; its result declares its table once."""
import json
import math

import pytest

from dem.experiments.settle.run import SettleResult, SettleSpec, run
from foundation.errors import ArchdemInputError


@pytest.fixture(scope="module")
def settled():
    return run(SettleSpec("Sh02-Sd020", duration=0.3))


def test_a_catalogue_arch_settles_at_rest_with_sub_millimetre_motion(settled):
    assert settled.at_rest and not settled.collapsed
    assert 0 < settled.max_displacement_mm < 1.0
    assert 0 < settled.max_rotation_mrad < 1.0
    # a 6 kg arch that moved less than 1 mm holds far less than 1 mJ at the end
    assert 0 <= settled.final_kinetic_energy_J < 1e-3
    assert (settled.id, settled.config, settled.engine, settled.duration_s) == ("Sh02-Sd020", "glued", "pybullet", 0.3)


def test_its_row_json_and_table_come_from_the_one_schema(settled, tmp_path):
    from dem.common.tables import read_csv

    (row,) = settled.rows()
    assert list(row) == SettleResult.SCHEMA.names
    assert json.loads(json.dumps(settled.to_json()))[0] == row
    settled.write_csv(tmp_path / "settle.csv")
    schema, rows = read_csv(tmp_path / "settle.csv")
    assert schema == SettleResult.SCHEMA and rows == [row]
    assert rows[0]["at_rest"] is True and isinstance(rows[0]["max_displacement_mm"], float)
    assert SettleResult.SCHEMA.column("max_rotation_mrad").unit == "mrad"


@pytest.mark.parametrize("duration", [0.0, 0.05, -1.0, math.nan, math.inf, 61.0])
def test_a_duration_outside_the_rule_s_reach_is_refused(duration):
    with pytest.raises(ArchdemInputError, match="settle duration"):
        SettleSpec("Sh02-Sd020", duration=duration)
