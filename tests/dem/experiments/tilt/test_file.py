"""HDF5 result files: round trip, never overwrite, atomic."""
import dataclasses
import math

import numpy as np
import pytest

from dem.core.model import from_assembly, single_block
from dem.core.settings import Settings
from dem.experiments.tilt.file import load_result, save_result
from dem.experiments.tilt.run import TiltProtocol, tilt
from foundation.errors import ArchdemInputError


@pytest.fixture(scope="module")
def result():
    return tilt(single_block(0.1, 0.2), Settings(mu_joint=1.0, mu_base=1.0), TiltProtocol(tol=0.02))


@pytest.fixture(scope="module")
def arch_result():
    # a small free arch (7 bodies, 8 joints, 2 base pads) under a short hold protocol: both a
    # collapsing and a stable simulation, several joint states
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    m = from_assembly(discretise(get_specimen("Sh06-Sd015").arch, n_voussoirs=3, config="free"), name="small")
    return tilt(m, Settings(), TiltProtocol(tol=0.05, ramp_time=0.2, hold_time=0.4, rest_after=0.2))


@pytest.fixture(scope="module")
def ramp_result():
    # a ramp has no stable simulation (None in the result)
    return tilt(single_block(0.1, 0.2), Settings(mu_joint=1.0, mu_base=1.0), TiltProtocol(kind="ramp", rate=0.5))


NOT_STORED = {"assembly"}  # Model.assembly: the blocks the model was cut from are not written


def assert_same(a, b, path="result"):
    """``a`` and ``b`` equal field by field, recursively: dataclasses, dicts, sequences, arrays
    (bit for bit, NaN equal to NaN, same dtype), numbers (NaN equal to NaN). Lists read back from
    JSON stand for tuples."""
    if dataclasses.is_dataclass(a) and not isinstance(a, type):
        assert type(a) is type(b), path
        for f in dataclasses.fields(a):
            if f.name not in NOT_STORED:
                assert_same(getattr(a, f.name), getattr(b, f.name), f"{path}.{f.name}")
    elif isinstance(a, np.ndarray):
        assert isinstance(b, np.ndarray) and a.dtype == b.dtype and a.shape == b.shape, path
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), path
    elif isinstance(a, dict):
        assert isinstance(b, dict) and sorted(a) == sorted(b), path
        for k in a:
            assert_same(a[k], b[k], f"{path}[{k!r}]")
    elif isinstance(a, (list, tuple)):
        assert isinstance(b, (list, tuple)) and len(a) == len(b), path
        for k, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, f"{path}[{k}]")
    elif isinstance(a, float) and math.isnan(a):
        assert isinstance(b, float) and math.isnan(b), path
    else:
        assert type(a) is type(b) or (isinstance(a, (int, float)) and not isinstance(a, bool)
                                      and isinstance(b, (int, float)) and not isinstance(b, bool)), path
        assert a == b, path


@pytest.mark.parametrize("which", ["result", "arch_result", "ramp_result"])
def test_round_trip_keeps_every_field(tmp_path, request, which):
    # every field of the result, its model (bodies, joints, base, crown, size, source) and both
    # simulations (load, outcome, joint states, every history array) read back as written
    res = request.getfixturevalue(which)
    r = load_result(save_result(res, tmp_path / "r.h5"))
    assert_same(res, r)
    assert_same(res.summary(), r.summary(), "summary")
    # the comparison saw a non-trivial result
    assert res.model.joints and res.joints and len(res.collapse.history.t) > 2
    assert (res.stable is None) is (res.protocol.kind == "ramp")


def test_stored_summary_is_the_result_summary(tmp_path, arch_result):
    # the JSON answer kept in the file (read by no loader) is the result's own
    import json

    import h5py

    p = save_result(arch_result, tmp_path / "r.h5")
    with h5py.File(p, "r") as f:
        stored = json.loads(f.attrs["summary"])
    assert_same(arch_result.summary(), stored, "summary")


def test_arch_round_trip_sees_several_bodies_joints_and_states(arch_result):
    # what the field-by-field comparison above covers on the arch
    m = arch_result.model
    assert m.n_bodies == 7 and len(m.joints) == 8 and len(m.base.pieces) == 2 and 0 < m.crown < 6
    assert {j.state for j in arch_result.joints} >= {"hinge", "closed"}
    assert arch_result.stable is not None and not math.isnan(arch_result.stable.t_rest)


def test_comparison_detects_a_changed_field(result):
    # assert_same is not vacuous: one changed joint end, state or history value is seen
    j = result.model.joints[0]
    moved = dataclasses.replace(result.model, joints=(dataclasses.replace(j, p_e=j.p_e + 1e-12),))
    with pytest.raises(AssertionError):
        assert_same(result, dataclasses.replace(result, model=moved))
    st = dataclasses.replace(result.joints[0], state="slide")
    with pytest.raises(AssertionError):
        assert_same(result, dataclasses.replace(result, joints=[st]))
    h = result.collapse.history
    dm = h.dmax.copy()
    dm[-1] = np.nextafter(dm[-1], np.inf)
    sim = dataclasses.replace(result.collapse, history=dataclasses.replace(h, dmax=dm))
    with pytest.raises(AssertionError):
        assert_same(result, dataclasses.replace(result, collapse=sim))


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


def test_result_written_before_the_engine_options_loads_them_from_its_flat_keys(tmp_path, result):
    # such a file's settings hold PyBullet's options as keys of their own; the engine's options are
    # stored with the settings and with the versions of every result since
    import json

    import h5py

    from dem.core.engines.options import LEGACY_KEYS, PyBulletOptions

    assert result.versions["pybullet_options"] == result.settings.engine_options.to_dict() == PyBulletOptions().to_dict()
    p = save_result(result, tmp_path / "old.h5")
    with h5py.File(p, "r+") as f:
        d = json.loads(f.attrs["settings"])
        assert d.pop("engine_options") == PyBulletOptions().to_dict()
        d |= {**PyBulletOptions().to_dict(), "solver_iterations": 150, "friction_erp": 0.9}
        f.attrs["settings"] = json.dumps(d)
    s = load_result(p).settings
    assert set(LEGACY_KEYS) <= set(d)
    assert s.engine_options == PyBulletOptions(solver_iterations=150, friction_erp=0.9)
    assert s.with_(engine_options=None) == result.settings
