"""Fragility ensembles on the DEM: the deterministic run reproduced, seeded realisations, the rigid
block's median against its closed form, and a real Dask cluster against the local pool."""
import math

import pytest

from analytic.rocking.domain import failure_domain
from analytic.rocking.rocking_block import RockingBlock
from dem.core.settings import Settings
from dem.experiments.fragility.run import (
    Perturbation,
    arch_structure,
    block_structure,
    fragility,
    shake_case,
    sine_spec,
)
from dem.experiments.shake.run import ShakeProtocol, shake
from specimens import get_specimen
from specimens.constants import NO_SLIDING_MU
from foundation.errors import ArchdemInputError

BLOCK = block_structure(0.1, 0.4)  # b/h = 0.25, the validation's block
RIGID = {"engine": "pybullet", "mu_joint": NO_SLIDING_MU, "mu_base": NO_SLIDING_MU, "planar": True}


def _case(structure, settings, pert, k, amp, freq=2.0):
    return {"label": "t", "structure": structure, "settings": settings, "perturbation": pert.describe(), "seed": 5,
            "realisation": k, "group": "g", "intensity": amp, "motion": sine_spec(freq, amp)}


@pytest.mark.slow
def test_no_perturbation_is_the_deterministic_run_bit_for_bit():
    from analytic.motions.inputs import SinePulse
    from specimens.constants import G

    arch = get_specimen("Sh06-Sd015").arch
    st = arch_structure(arch)
    out = shake_case(_case(st, {"engine": "pybullet"}, Perturbation(), 3, 0.36))
    ref = shake(arch, SinePulse(0.36 * G, 2.0), Settings(), ShakeProtocol(), friction_work=False)
    assert out["collapsed"] == ref.collapsed
    assert out["peak_displacement"] == float(ref.sim.history.dmax.max())  # the same engine steps


@pytest.mark.slow
def test_realisations_are_seeded():
    st = arch_structure(get_specimen("Sh06-Sd015").arch)
    pert = Perturbation(edge_loss_sd=0.25e-3, friction_cov=0.1)
    a = shake_case(_case(st, {"engine": "pybullet"}, pert, 1, 0.2))
    b = shake_case(_case(st, {"engine": "pybullet"}, pert, 1, 0.2))
    c = shake_case(_case(st, {"engine": "pybullet"}, pert, 2, 0.2))
    assert (a["mu_joint"], a["peak_displacement"]) == (b["mu_joint"], b["peak_displacement"])
    assert a["mu_joint"] != c["mu_joint"] and a["peak_displacement"] != c["peak_displacement"]


@pytest.mark.parametrize("freq, amps", [(2.0, (0.29, 0.30, 0.305, 0.31, 0.315, 0.32, 0.33)),
                                        (3.0, (0.34, 0.35, 0.355, 0.36, 0.365, 0.37, 0.38))])
@pytest.mark.slow
def test_the_block_median_meets_the_rocking_block_model(tmp_path, freq, amps):
    """An independent truth: a planar block (0.1 x 0.4 m, no sliding) with its dimensions scattered by
    0.25 mm has its fitted median within 2 % of the closed-form overturning amplitude of a one-cycle
    sine (Housner's restitution), at two frequencies (measured 0.4 % and 0.8 %; the stripes are 1.6 % apart)."""
    from specimens.constants import G

    dom = failure_domain(RockingBlock(0.05, 0.2), "sine0", [freq], a_max_ratio=8.0, n_scan=16, workers=1)
    a_an = dom.columns[0].thresholds[0][0] / G
    groups = [(f"{freq:g} Hz", "g", [(a, sine_spec(freq, a)) for a in amps])]
    res = fragility("block", BLOCK, RIGID, Perturbation(size_sd=0.25e-3), groups, 6, 11, tmp_path / "b.h5",
                    workers=2, progress=False)
    fit = res.curves[0].fit
    assert fit is not None and abs(fit.median / a_an - 1) <= 0.02, (fit.median, a_an)
    assert fit.beta < 0.05 and not res.failed  # measured 0.002 and 0.015


@pytest.mark.slow
def test_a_local_dask_cluster_gives_the_local_pool_results(tmp_path):
    """A real scheduler and two worker processes on localhost against the local pool."""
    distributed = pytest.importorskip("distributed")
    groups = [("2 Hz", "g", [(a, sine_spec(2.0, a)) for a in (0.29, 0.33)])]
    pert = Perturbation(size_sd=0.25e-3)
    local = fragility("block", BLOCK, RIGID, pert, groups, 3, 4, tmp_path / "l.h5", workers=2, progress=False)
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None) as cl:
        remote = fragility("block", BLOCK, RIGID, pert, groups, 3, 4, tmp_path / "d.h5", scheduler=cl.scheduler_address,
                           progress=False)
    assert [s.describe() for s in remote.curves[0].stripes] == [s.describe() for s in local.curves[0].stripes]


def test_bad_ensembles_are_refused():
    groups = [("2 Hz", "g", [(0.3, sine_spec(2.0, 0.3))])]
    with pytest.raises(ArchdemInputError, match="realisations must be a whole number from 1"):
        fragility("b", BLOCK, RIGID, Perturbation(), groups, 0, 1, "x.h5")
    with pytest.raises(ArchdemInputError, match="friction coefficient of variation"):
        Perturbation(friction_cov=math.nan)


def test_a_spec_holds_the_study_and_its_cases():
    """The spec's cases are the study's; a case's perturbation is the spec's, field for field."""
    from dataclasses import asdict

    from dem.experiments.fragility.run import FragilitySpec, make_cases

    pert = Perturbation(edge_loss=1e-3, friction_cov=0.1)
    groups = [("2 Hz", "g", [(0.3, sine_spec(2.0, 0.3)), (0.4, sine_spec(2.0, 0.4))])]
    spec = FragilitySpec("b", BLOCK, RIGID, pert, groups, 3, 7, "x.h5")
    cases = spec.cases()
    assert cases == make_cases("b", BLOCK, RIGID, pert, groups, 3, 7) and len(cases) == 6
    assert cases[0]["perturbation"] == asdict(pert) and cases[-1]["realisation"] == 2
    with pytest.raises(ArchdemInputError, match="the seed must be a whole number"):
        FragilitySpec("b", BLOCK, RIGID, pert, groups, 3, -1, "x.h5").cases()


def test_the_json_answer_is_the_summary_then_what_the_study_was_asked_and_its_table():
    from dataclasses import replace

    from dem.experiments.fragility.run import FragilityResult, FragilitySpec, stripes_csv

    assert FragilitySpec("b", BLOCK, RIGID, Perturbation(), [], 3, 7, "x.h5").motions == {}
    res = replace(FragilityResult("b", [], 0, (), "runs/s.h5", 1.0),
                  inputs={"input": "sine", "freqs": [2.0], "perturbation": {"size_sd": 0.0}, "settings": RIGID})
    d = res.describe()
    assert list(d)[:len(res.summary())] == list(res.summary())
    assert list(d)[len(res.summary()):] == ["input", "freqs", "perturbation", "settings", "csv"]
    assert d["csv"] == str(stripes_csv("runs/s.h5")) == "runs/s-stripes.csv"
