"""A fragility study's parts from what a user gives: grids of stripes, the groups of sines or records, the
perturbation in millimetres, the settings and the nominal block; each refusal one input error."""
import pytest

from dem.experiments.fragility.inputs import (
    BLOCK_WIDTH,
    block_nominal,
    deterministic_thresholds,
    motion_groups,
    nominal,
    perturbation_mm,
    stripe_grid,
    study_settings,
)
from dem.common.request import ArchRequest
from dem.experiments.fragility.run import DEFAULT_EDGE_LOSS_SD, DEFAULT_SIZE_SD, Perturbation
from foundation.errors import ArchdemInputError
from specimens.blocks import DEFAULT_DENSITY


def test_a_grid_is_sorted_rounded_and_refused_out_of_range_or_repeated():
    assert stripe_grid("0.4,0.1,0.345", "--amplitudes", 0.0, 5.0, "g") == [0.1, 0.345, 0.4]
    assert stripe_grid("0.1:0.3:0.1", "--amplitudes", 0.0, 5.0, "g") == [0.1, 0.2, 0.3]
    with pytest.raises(ArchdemInputError, match=r"--amplitudes values must be in \(0, 5\] g"):
        stripe_grid("6", "--amplitudes", 0.0, 5.0, "g")
    with pytest.raises(ArchdemInputError, match="--amplitudes repeats a value"):
        stripe_grid("0.3,0.3", "--amplitudes", 0.0, 5.0, "g")


def test_sine_groups_one_per_frequency_and_the_wrong_companions_refused():
    groups, info = motion_groups(sine="4,2", amplitudes="0.2,0.1")
    assert [(name, unit, [a for a, _ in items]) for name, unit, items in groups] == [
        ("2 Hz", "g", [0.1, 0.2]), ("4 Hz", "g", [0.1, 0.2])]
    assert groups[0][2][0][1] == {"kind": "sine", "freq": 2.0, "amplitude_g": 0.1}
    assert info == {"input": "sine", "freqs": [2.0, 4.0]}
    for kw, msg in (({}, "give --sine"), ({"sine": "2", "records": ["a"]}, "give --sine"),
                    ({"sine": "2"}, "--sine goes with --amplitudes"),
                    ({"sine": "2", "amplitudes": "0.1", "im": "pga"}, "--sine goes with --amplitudes"),
                    ({"records": ["a"], "im": "pga"}, "--records goes with --im"),
                    ({"records": ["a"], "im": "pga", "stripes": "0.1", "amplitudes": "0.1"}, "--records goes with")):
        with pytest.raises(ArchdemInputError, match=msg):
            motion_groups(**kw)


def test_the_perturbation_is_in_metres_with_the_defaults_by_kind():
    assert perturbation_mm("arch", 1.0, None, None, 0.1) == Perturbation(1e-3, DEFAULT_EDGE_LOSS_SD, 0.0, 0.1)
    assert perturbation_mm("block", None, None, 0.5, 0.0) == Perturbation(0.0, 0.0, 0.5e-3, 0.0)
    assert perturbation_mm("block", None, None, None, 0.0).size_sd == DEFAULT_SIZE_SD
    with pytest.raises(ArchdemInputError, match="a block takes --size-sd"):
        perturbation_mm("block", None, 0.2, None, 0.1)
    with pytest.raises(ArchdemInputError, match="an arch's joints take --edge-loss-sd"):
        perturbation_mm("drawing", None, None, 0.2, 0.1)
    with pytest.raises(ArchdemInputError, match="--edge-loss must be a length from 0 to 100 mm, got nan"):
        perturbation_mm("arch", float("nan"), None, None, 0.1)


def test_settings_carry_their_step_and_the_solver_iterations():
    s = study_settings({"mu_joint": 0.5, "mu_base": 1.0, "planar": True, "engine": "pybullet"}, 50)
    assert s["engine_options"] == {"solver_iterations": 50} and s["dt"] > 0
    assert "engine_options" not in study_settings({"engine": "pybullet"})


def test_a_block_takes_the_default_width_and_density_and_each_sine_a_threshold_function():
    structure, model = block_nominal(0.1, 0.4)
    assert structure == {"kind": "block", "b": 0.1, "h": 0.4, "width": BLOCK_WIDTH, "density": DEFAULT_DENSITY}
    groups, info = motion_groups(sine="2,3", amplitudes="0.3")
    found = deterministic_thresholds(model, {"engine": "pybullet"}, groups, info["freqs"])
    assert sorted(found) == ["2 Hz", "3 Hz"] and all(callable(f) for f in found.values())


def test_the_nominal_structure_of_a_request_a_block_or_an_arch_that_stands():
    label, structure, _ = nominal(ArchRequest(block=(0.05, 0.2)), "glued", width=0.2)
    assert label == "block-b0.05-h0.2" and (structure["b"], structure["h"], structure["width"]) == (0.1, 0.4, 0.2)
    label, structure, model = nominal(ArchRequest(Sh=0.6, Sd=0.25, Rc=0.2, voussoirs=2), "free")
    assert label == "Sh0.6-Sd0.25-Rc0.2" and structure["kind"] == "arch" and structure["config"] == "free"
    with pytest.raises(ArchdemInputError, match="cannot stand"):
        nominal(ArchRequest(Sh=0.2, Sd=0.03, Rc=1.0), "glued")
