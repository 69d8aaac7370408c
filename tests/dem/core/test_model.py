"""The engine-neutral model: mass properties carried over from specimens, principal frames."""
import numpy as np
import pytest

from dem.core.model import from_assembly, side_by_side, single_block
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError


@pytest.mark.parametrize("config", ["glued", "free"])
def test_model_carries_assembly(config):
    asm = discretise(get_specimen("Sh06-Sd015").arch, config=config)
    m = from_assembly(asm)
    assert m.n_bodies == asm.n_bodies and len(m.joints) == len(asm.joints)
    # identity: same total mass as the assembly (pure copy; 1e-12 relative = rounding)
    assert m.total_mass == pytest.approx(asm.total_mass, rel=1e-12)
    assert m.size == pytest.approx(asm.arch.t)
    assert m.bodies[m.crown].name == "C"
    # base pads carry the springing joints: their top is the springing line y = 0
    for p in m.base.pieces:
        assert p[:, 1].max() == pytest.approx(0.0, abs=1e-15)


def test_single_block_closed_form():
    m = single_block(0.1, 0.2, width=0.1, density=1000.0)
    b = m.bodies[0]
    assert b.mass == pytest.approx(2.0)  # 1000 * 0.1 * 0.2 * 0.1
    # in-plane moment of a rectangle: m (b^2 + h^2) / 12
    assert b.inertia[2, 2] == pytest.approx(2.0 * (0.01 + 0.04) / 12)
    assert m.joints[0].length == pytest.approx(0.1)


def test_side_by_side_copies():
    m = from_assembly(discretise(get_specimen("Sh02-Sd015").arch))
    m4 = side_by_side(m, 4)
    assert m4.n_bodies == 4 * m.n_bodies and len(m4.joints) == 4 * len(m.joints)
    z = sorted({float(b.centroid[2]) for b in m4.bodies})
    assert len(z) == 4 and min(np.diff(z)) > m.bodies[0].width  # copies do not touch


def test_bad_input():
    with pytest.raises(ArchdemInputError):
        single_block(-0.1, 0.2)
    with pytest.raises(ArchdemInputError):
        side_by_side(single_block(0.1, 0.2), 0)
