"""The spec of ``archdem modes``: its refusals in the library, and its result printed and as JSON."""
import pytest

from dem.common.request import ArchRequest
from dem.experiments.modes.spec import MAX_COUNT, ModesSpec, modes_structure
from foundation.errors import ArchdemInputError


@pytest.mark.parametrize("count", [0, MAX_COUNT + 1, 2.5])
def test_a_count_outside_its_range_is_refused_when_built(count):
    with pytest.raises(ArchdemInputError, match="--count must be a whole number from 1 to"):
        ModesSpec(count=count, kn=1e8)


@pytest.mark.parametrize("kw, msg", [
    ({}, "give the joints' stiffness as --kn"),
    ({"kn": 1e8, "youngs": 1e9}, "give the joints' stiffness as --kn"),
    ({"kn": 1e8, "given": frozenset({"poisson"})}, "--poisson does nothing here"),
    ({"youngs": -1.0}, "--youngs must be a positive modulus"),
    ({"youngs": 1e9, "poisson": 0.5}, r"--poisson must be in \[0, 0.5\)"),
])
def test_the_stiffness_refusals(kw, msg):
    label, block = modes_structure(ArchRequest(block=(0.05, 0.2)), "glued")
    with pytest.raises(ArchdemInputError, match=msg):
        ModesSpec(**kw).stiffness(block)


def test_a_block_s_modes_print_and_describe_the_same_frequencies():
    res = ModesSpec(kn=4.34e8, count=2).run(*modes_structure(ArchRequest(block=(0.05, 0.2)), "glued"))
    out = res.to_json()
    assert out["id"] == "block-b0.05-h0.2" and out["n_modes"] == 3 and len(out["frequencies_hz"]) == 2
    assert "plot" not in out
    head, freqs = res.lines()
    assert head.startswith("block-b0.05-h0.2: 3 modes on joints kn 4.34e+08 Pa/m")
    assert freqs == "  " + "  ".join(f"{f:.4g}" for f in out["frequencies_hz"]) + " Hz"
