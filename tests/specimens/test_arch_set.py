"""The arches outside the catalogue (specimens/arch_set.py): every member builds, stands, and its
drawings read back as the blocks they were drawn from."""
import math

import pytest

from analytic.limit.limit_discrete import solve_lp
from specimens.arch_set import ARCH_SET, set_arch
from specimens.drawn import DrawnAssembly
from foundation.errors import ArchdemInputError


def test_the_set_spans_what_users_bring():
    params = [m for m in ARCH_SET if not m.drawn]
    spans = [m.span for m in params]
    assert min(spans) == pytest.approx(0.5) and max(spans) == pytest.approx(10.0)
    assert {m.e == 0 for m in params} == {True, False}  # round and pointed
    assert {m.config for m in params} == {"glued", "free"}
    assert {m.fmt for m in ARCH_SET if m.drawn} >= {"dxf", "csv", "obj"}
    ratios = [m.thickness_ratio for m in params]
    assert min(ratios) < 0.1 and max(ratios) > 0.3  # near the least thickness to thick


@pytest.mark.slow
def test_every_member_stands_with_5_to_15_bodies(tmp_path):
    for m in ARCH_SET:
        asm = m.assembly(tmp_path)
        assert 5 <= len(asm.bodies) <= 23, m.name  # the arch on piers adds its 8 courses to 15 voussoirs
        assert isinstance(asm, DrawnAssembly) == m.drawn
        lp = solve_lp(asm, 0.577, 1.0)
        assert lp.success and 0 < lp.lam < 1, m.name


def test_drawings_of_one_ring_read_back_alike(tmp_path):
    # the same ring drawn in mm (DXF) and in m (CSV): the same blocks, the same LP
    dxf = set_arch("drawn-ring-dxf-mm").assembly(tmp_path)
    csv = set_arch("drawn-ring-csv").assembly(tmp_path)
    assert dxf.source["units"] == "mm" and csv.source["units"] == "m"
    assert solve_lp(dxf, math.inf, math.inf).lam == pytest.approx(solve_lp(csv, math.inf, math.inf).lam, rel=1e-9)
    convex = [set_arch(n).assembly(tmp_path) for n in ("drawn-ring-convex-dxf", "drawn-ring-convex-obj")]
    assert solve_lp(convex[0], 0.577, 1.0).lam == pytest.approx(solve_lp(convex[1], 0.577, 1.0).lam, rel=1e-9)
    # straight-sided voussoirs: the same ring by parameters in its linearised cut
    ring = set_arch("drawn-ring-convex-dxf")
    from specimens.blocks import discretise

    by_params = discretise(ring.arch, n_voussoirs=ring.n, config="free")
    assert solve_lp(convex[0], math.inf, math.inf).lam == pytest.approx(
        solve_lp(by_params, math.inf, math.inf).lam, rel=1e-6)


def test_unknown_member_and_missing_folder_are_input_errors():
    with pytest.raises(ArchdemInputError, match="no arch"):
        set_arch("nope")
    with pytest.raises(ArchdemInputError, match="folder"):
        set_arch("drawn-ring-csv").assembly()
