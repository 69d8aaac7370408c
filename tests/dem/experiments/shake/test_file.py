"""Shake run files: a full round trip of a collapsed and of a survived run."""
import json
import math
from dataclasses import asdict

import h5py
import numpy as np
import pytest

from analytic.motions.inputs import SinePulse
from dem.core.model import from_assembly, single_block
from dem.core.settings import Settings
from dem.experiments.shake.file import load_shake, save_shake
from dem.experiments.shake.run import ShakeProtocol, motion_trace, shake
from specimens.constants import NO_SLIDING_MU, G
from foundation.errors import ArchdemInputError
from tests.dem.experiments.tilt.test_file import assert_same


@pytest.fixture(scope="module")
def collapsed():
    # a small free arch thrown over by one 0.8 g sine cycle: the run stops at the collapse
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    m = from_assembly(discretise(get_specimen("Sh06-Sd015").arch, n_voussoirs=3, config="free"), name="small")
    return shake(m, SinePulse(0.8 * G, 4.0), Settings(), ShakeProtocol(tail=0.25))


@pytest.fixture(scope="module")
def survived():
    # a block 0.1 x 0.4 m below its rocking onset (0.25 g): survives and ends at rest
    s = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, planar=True)
    return shake(single_block(0.1, 0.4), SinePulse(0.2 * G, 4.0), s, ShakeProtocol(tail=0.5))


@pytest.mark.parametrize("which", ["collapsed", "survived"])
def test_round_trip_keeps_every_field(tmp_path, request, which):
    res = request.getfixturevalue(which)
    p = save_shake(res, tmp_path / "run.h5")
    d = load_shake(p)
    assert d["label"] == res.label
    assert_same(res.model, d["model"], "model")
    assert_same(res.settings, d["settings"], "settings")
    # the protocol, motion description and criterion as written, the protocol rebuilt in full
    assert_same(asdict(res.protocol), d["protocol"], "protocol")
    assert ShakeProtocol(**d["protocol"]) == res.protocol
    assert_same(res.motion.describe(), d["motion"], "motion")
    assert_same(res.criterion, d["criterion"], "criterion")
    # the simulation: load, outcome (collapsed, t_collapse, mode, joints, out of plane, steps, t_rest)
    # and every history array (t, pos, quat, gravity, dmax, ke, fpower), bit for bit
    assert_same(res.sim, d["sim"], "sim")
    assert_same(res.crown_u, d["crown_u"], "crown_u")
    t, a = motion_trace(res.motion, res.sim.duration, res.settings.dt)
    assert_same(t, d["input_t"], "input_t")
    assert_same(a, d["input_a"], "input_a")
    # the scalar answers (phase, onset, rebound, peaks) are kept in the summary
    assert_same(res.summary(), d["summary"], "summary")
    with h5py.File(p, "r") as f:  # kept in the file, not returned by load_shake
        assert json.loads(f.attrs["versions"]) == res.versions
        assert bool(f.attrs["collapsed"]) is res.collapsed and str(f.attrs["mode"]) == res.mode
        assert_same(float("nan") if res.t_collapse is None else res.t_collapse, float(f.attrs["t_collapse"]))
    with pytest.raises(ArchdemInputError):
        save_shake(res, p)


def test_the_two_runs_cover_both_outcomes(collapsed, survived):
    # what the round trips above compare: a collapse (time, phase, several joints) and a survival
    # ended at rest (no collapse time stored as NaN)
    assert collapsed.collapsed and collapsed.t_collapse > 0 and collapsed.collapse_phase is not None
    assert len(collapsed.model.joints) == 8 and collapsed.mode != "none"
    assert not survived.collapsed and survived.t_collapse is None and math.isnan(survived.sim.t_collapse)
    assert not math.isnan(survived.sim.t_rest)
    for r in (collapsed, survived):
        h = r.sim.history
        assert len(h.t) > 2 and np.all(np.isfinite(h.fpower)) and h.pos.shape == (len(h.t), r.model.n_bodies, 3)


def test_a_file_from_before_the_confirmed_collapse_reads_with_its_own_rule(tmp_path, collapsed):
    # written before decision 012: no confirmation in the settings or the protocol, no t_exceed or
    # t_confirm in the simulation; it reads as what its rule was: the criterion's firing is the collapse
    p = save_shake(collapsed, tmp_path / "old.h5")
    with h5py.File(p, "r+") as f:
        settings, protocol = json.loads(f.attrs["settings"]), json.loads(f.attrs["protocol"])
        del settings["collapse_confirm"], protocol["confirm_fraction"]
        f.attrs["settings"], f.attrs["protocol"] = json.dumps(settings), json.dumps(protocol)
        del f["sim"].attrs["t_exceed"], f["sim"].attrs["t_confirm"]
    d = load_shake(p)
    assert d["settings"].collapse_confirm is None and ShakeProtocol(**d["protocol"]).confirm_fraction is None
    assert d["sim"].collapsed and d["sim"].t_exceed == d["sim"].t_confirm == d["sim"].t_collapse
