"""The options of ``archdem map`` as a spec: checked when built, the specimens selected, the map's spec."""
import pytest

from dem.common.request import ArchRequest
from dem.experiments.friction_map.spec import MapOptions
from foundation.errors import ArchdemInputError


@pytest.mark.parametrize("kw, msg", [
    ({"refine": 21}, r"--refine must be in 0..20, got 21"),
    ({"tol": 1e-4}, r"--tol must be a relative tolerance in \[0.001, 0.5\]"),
    ({"mu": "0.5", "refine": 2, "given": frozenset({"refine"})}, "--refine does nothing here"),
    ({"geometry": True, "given": frozenset({"full_scale"})}, "--full-scale does nothing here"),
    ({"specimens": "L10-Sh9-Sd9", "full_scale": True}, "unknown full-scale specimen 'L10-Sh9-Sd9'"),
    ({"specimens": " , ", "full_scale": True}, "no specimens selected"),
    ({"mu": "0.3,,0.6"}, "friction grid: expected a list"),
])
def test_refused_when_built(kw, msg):
    with pytest.raises(ArchdemInputError, match=msg):
        MapOptions(**kw)


def test_one_friction_value_takes_the_default_refine_not_given():
    assert MapOptions(specimens="Sh02-Sd020", mu="0.5").mus == [0.5]


def test_the_map_spec_of_the_options():
    opts = MapOptions(specimens="Sh02-Sd020,Sh06-Sd015", mu="0.4,0.8", refine=1, tol=0.2)
    specs = opts.structures(ArchRequest())
    assert [s.id for s in specs] == ["Sh02-Sd020", "Sh06-Sd015"]
    spec = opts.map_spec(specs, "glued", "pybullet", {}, 0.9)
    assert spec.mus == [0.4, 0.8] and spec.refine == 1 and spec.protocol == {"kind": "hold", "tol": 0.2}
    assert spec.settings is None and spec.contact == {"Sh02-Sd020": 0.9, "Sh06-Sd015": 0.9}
    assert opts.map_spec(specs, "glued", "mujoco", {}, 1.0).settings == {"engine": "mujoco"}
