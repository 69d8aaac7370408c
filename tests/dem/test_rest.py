"""At rest (spec §3.2, §3.4.5): drift < 0.1 mm in 5 s. Representative subset (thin pointed arch
free — its crown joints are nearest to the friction limit — and a glued one); all 22 cases run in
benchmarks/validate_dem.py."""
import pytest

from dem.load import Rest
from dem.model import from_assembly
from dem.protocols import simulate
from dem.settings import Settings
from specimens.blocks import discretise
from specimens.catalogue import get_specimen


@pytest.mark.parametrize("sid,config", [("Sh06-Sd010", "free"), ("Sh1-Sd025", "glued")])
def test_rest_drift(sid, config):
    m = from_assembly(discretise(get_specimen(sid).arch, config=config))
    r = simulate(m, Settings(), Rest(), 5.0, record_every=0.1, stop_on_collapse=False, friction_work=False)
    assert not r.collapsed
    assert r.history.dmax.max() < 1e-4  # 0.1 mm, the gate
