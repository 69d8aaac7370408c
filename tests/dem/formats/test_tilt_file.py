"""HDF5 result files: round trip, never overwrite, atomic."""
import numpy as np
import pytest

from dem.core.model import single_block
from dem.core.settings import Settings
from dem.experiments.tilt import TiltProtocol, tilt
from dem.formats.tilt import load_result, save_result
from specimens.errors import ArchdemInputError


@pytest.fixture(scope="module")
def result():
    return tilt(single_block(0.1, 0.2), Settings(mu_joint=1.0, mu_base=1.0), TiltProtocol(tol=0.02))


def test_round_trip(tmp_path, result):
    p = save_result(result, tmp_path / "r.h5")
    r = load_result(p)
    assert r.lam == result.lam and r.bracket == result.bracket and r.mode == result.mode
    assert r.settings == result.settings and r.protocol == result.protocol
    assert r.summary()["joints"] == result.summary()["joints"]
    assert r.levels == [tuple(x) for x in result.levels]
    assert np.array_equal(r.collapse.history.pos, result.collapse.history.pos)
    assert np.array_equal(r.stable.history.quat, result.stable.history.quat)
    # the stable level ended at rest (the block's rest rule); the time is kept
    assert not np.isnan(result.stable.t_rest) and r.stable.t_rest == result.stable.t_rest
    assert np.isnan(r.collapse.t_rest)
    assert r.model.bodies[0].mass == result.model.bodies[0].mass
    assert np.array_equal(r.model.bodies[0].pieces[0], result.model.bodies[0].pieces[0])
    assert r.versions["pybullet"] == result.versions["pybullet"]
    assert r.criterion == result.criterion


def test_never_overwrites_and_atomic(tmp_path, result):
    p = save_result(result, tmp_path / "r.h5")
    before = p.read_bytes()
    with pytest.raises(ArchdemInputError):
        save_result(result, p)
    assert p.read_bytes() == before
    assert [q.name for q in tmp_path.iterdir()] == ["r.h5"]  # no temporary left behind


def test_result_written_before_the_rest_rule_loads_as_held_the_full_time(tmp_path, result):
    # such a file's protocol has no rest_after: every level was held hold_time, not the new default
    import json

    import h5py

    p = save_result(result, tmp_path / "old.h5")
    with h5py.File(p, "r+") as f:
        d = json.loads(f.attrs["protocol"])
        for k in ("rest_after", "rest_window", "rest_growth", "guess_bracket", "probe_ends"):
            d.pop(k)
        f.attrs["protocol"] = json.dumps(d)
        del f["stable"].attrs["t_rest"]
    r = load_result(p)
    assert r.protocol.rest_after is None and np.isnan(r.stable.t_rest)
    # ... and, older than guess_bracket, it bisected from (0.95, 1.01) x the guess
    assert r.protocol.guess_bracket == (0.95, 1.01)
    # ... and, older than probe_ends, simulated both ends of it first
    assert r.protocol.probe_ends == "first" != result.protocol.probe_ends
    new = load_result(save_result(result, tmp_path / "new.h5")).protocol
    assert (new.guess_bracket, new.probe_ends) == (result.protocol.guess_bracket, result.protocol.probe_ends)
