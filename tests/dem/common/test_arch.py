"""The arch as stored parameters and back (dem/common/arch.py)."""
from __future__ import annotations

import json

from dem.common.arch import arch_from_params, arch_params
from specimens.catalogue import get_specimen


def test_an_arch_survives_its_parameters_through_json():
    arch = get_specimen("Sh06-Sd015").arch
    p = json.loads(json.dumps(arch_params(arch)))
    assert set(p) == {"e", "t", "Rp", "width"}
    back = arch_from_params(p)
    assert (back.e, back.t, back.Rp, back.width) == (arch.e, arch.t, arch.Rp, arch.width)
    assert back.Rc == arch.Rc
