"""What ``archdem tilt`` asks for besides the structure, as a spec: its refusals, the protocol it builds."""
import pytest

from dem.experiments.tilt.spec import TiltOptions
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError


@pytest.mark.parametrize("kw, msg", [
    ({"ensemble": 3, "seed": 1, "protocol": "ramp"}, "an ensemble runs the default hold protocol"),
    ({"ensemble": 3, "seed": 1, "full_hold": True}, "an ensemble runs the default hold protocol"),
    ({"ensemble": 3}, "--ensemble needs --seed S"),
    ({"scatter": 1.0}, "--seed and --scatter go with --ensemble N"),
    ({"protocol": "ramp", "given": frozenset({"start"})}, "--start does nothing here: it belongs to --protocol hold"),
    ({"protocol": "staircase", "full_hold": True, "given": frozenset({"full_hold"})}, "--full-hold does nothing"),
])
def test_refused_when_built(kw, msg):
    with pytest.raises(ArchdemInputError, match=msg):
        TiltOptions(**kw)


def test_the_protocol_of_one_tilt():
    assert TiltOptions().tilt_protocol().rest_after is not None
    p = TiltOptions(start="scan", full_hold=True).tilt_protocol()
    assert (p.kind, p.start, p.rest_after) == ("hold", "scan", None)
    assert TiltOptions(protocol="ramp", start="lp").tilt_protocol().kind == "ramp"  # at its default: not given


def test_an_ensemble_scatter_beyond_half_the_ring_is_refused():
    arch = get_specimen("Sh02-Sd020").arch
    opts = TiltOptions(ensemble=2, seed=1, scatter=1e3 * arch.t / 2 * 1.01)
    with pytest.raises(ArchdemInputError, match="--scatter must be between 0 and half the ring thickness"):
        opts.imperfection(1.0, arch)
    assert TiltOptions(ensemble=2, seed=1, scatter=0.5).imperfection(0.9, arch) is not None
