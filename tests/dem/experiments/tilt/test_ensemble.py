"""Tilt ensembles: the summary statistics, the cases a study runs, and refused input (the DEM
runs themselves are tested through ``archdem tilt --ensemble`` in tests/dem/experiments/tilt/test_tilt_cmd.py)."""
import math

import numpy as np
import pytest

from dem.experiments.tilt import ensemble
from dem.experiments.tilt.ensemble import EnsembleResult, tilt_ensemble
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError
from specimens.imperfection import Imperfection

ARCH = get_specimen("Sh06-Sd020").arch


def test_summary_is_the_sample_statistics_of_the_runs():
    lams = np.array([0.30, 0.33, 0.36])
    r = EnsembleResult("x", 0.84, 0.0012, lams, ("rocking", "rocking", "mixed"), ((1, 0), (1, 1), (1, 2)),
                       ("realisation 3: boom",))
    s = r.summary()
    assert s["lambda_mean"] == pytest.approx(0.33, rel=1e-12)
    assert s["lambda_sd"] == pytest.approx(0.03, rel=1e-12)  # sample sd (n - 1)
    assert s["lambda_cov"] == pytest.approx(0.03 / 0.33, rel=1e-12)
    assert s["modes"] == {"rocking": 2, "mixed": 1} and s["edge_loss_sd_mm"] == pytest.approx(1.2)
    assert s["failed"] == ["realisation 3: boom"] and s["n"] == 3
    one = EnsembleResult("x", 1.0, 0.0, np.array([0.3]), ("rocking",), ((1, 0),))
    assert math.isnan(one.lambda_sd) and one.lambda_mean == 0.3


def test_the_ensemble_prints_itself():
    r = EnsembleResult("x", 0.84, 0.0012, np.array([0.30, 0.33, 0.36]), ("rocking", "rocking", "mixed"),
                       ((1, 0), (1, 1), (1, 2)), ("realisation 3: boom",), "e.h5", 12.3, config="glued", seed=1)
    assert r.lines() == ["x (glued, contact 0.840, edge-loss scatter 1.2 mm, seed 1): lambda 0.3300 +- 0.0300 over 3 "
                         "realisations (rocking 2, mixed 1); 12 s -> e.h5", "  failed: realisation 3: boom"]


def test_the_ensemble_describes_what_it_ran_with():
    r = EnsembleResult("x", 0.84, 0.0012, np.array([0.30, 0.33]), ("rocking", "rocking"), ((1, 0), (1, 1)),
                       config="free", seed=1, mu_joint=0.6, mu_base=1.0, engine="compliant")
    d = r.describe()
    assert list(d)[-5:] == ["config", "mu_joint", "mu_base", "engine", "seed"]
    assert (d["config"], d["mu_joint"], d["engine"], d["seed"]) == ("free", 0.6, "compliant", 1)
    assert d["lambda_mean"] == r.summary()["lambda_mean"]


def band_case(case: dict) -> dict:
    """Stand-in case function (imported by name in the workers): its lambda is the intrados end of
    joint L0's band plus the realisation, so the test sees which bands each case carried."""
    return {"lambda": float(case["bands"]["L0"][0]) + case["realisation"], "mode": "rocking"}


def test_every_realisation_is_a_case_with_its_seed_and_bands(tmp_path, monkeypatch):
    from specimens.blocks import discretise

    monkeypatch.setattr(ensemble, "DEM_CASE", band_case)
    imp = Imperfection(0.005, 0.001)
    r = tilt_ensemble("Sh06-Sd020", ARCH, imp, 3, 42, tmp_path / "e.h5", workers=1, progress=False)
    nominal = discretise(ARCH, config="glued", contact=imp.contact(ARCH))
    want = [imp.bands(nominal, 42, k)["L0"][0] + k for k in range(3)]
    assert list(r.lambdas) == want and r.seeds == ((42, 0), (42, 1), (42, 2)) and r.failed == ()
    assert r.contact == nominal.contact and len(set(want)) == 3


@pytest.mark.parametrize("n, seed, match", [(0, 1, "1 to 10000"), (2.5, 1, "1 to 10000"), (2, -1, "seed")])
def test_bad_ensemble_is_refused(tmp_path, n, seed, match):
    with pytest.raises(ArchdemInputError, match=match):
        tilt_ensemble("x", ARCH, Imperfection(0.005, 0.001), n, seed, tmp_path / "e.h5", progress=False)
    assert not (tmp_path / "e.h5").exists()
