"""The virtual check of an assessment: matched records on the DEM, and the codes' rule over them."""
import numpy as np
import pytest

from analytic.motions.inputs import SampledMotion
from dem.experiments.record.run import RecordRun, dem_verdict, run_records
from specimens import get_specimen
from specimens.blocks import discretise


def _run(peak, collapsed=False):
    return RecordRun("r", 1.0, 1.0, collapsed, "", peak, 0.0)


def test_the_rule_over_the_records():
    """Verified when no record reaches d0* (or collapses) and the mean peak is at most d_u*."""
    assert dem_verdict([_run(0.01), _run(0.03)], d0_star=0.1, du_star=0.04)["verified"]
    assert not dem_verdict([_run(0.01), _run(0.09)], d0_star=0.1, du_star=0.04)["verified"]  # mean 0.05 > du
    assert dem_verdict([_run(0.001), _run(0.1)], d0_star=0.1, du_star=0.2)["n_reach_d0"] == 1
    v = dem_verdict([_run(0.001), _run(0.002, collapsed=True)], d0_star=0.1, du_star=0.04)
    assert v["n_collapsed"] == 1 and not v["verified"]


@pytest.mark.slow
def test_a_strong_pulse_moves_the_mass_centroid_and_a_weak_one_does_not():
    """A 0.6 s full-sine pulse of 1.2 g (far above lambda = 0.29) opens the arch: its mass centroid moves
    millimetres; at 0.05 g (below the onset) it moves microns at most."""
    asm = discretise(get_specimen("Sh06-Sd015").arch, config="free")
    dt = 0.002
    t = np.arange(0, 0.5, dt)
    pulse = np.sin(2 * np.pi * 2.0 * t)
    runs = run_records(asm, [SampledMotion(pulse * 9.81 * a, dt, name=f"{a} g") for a in (0.05, 1.2)], e_star=0.93)
    weak, strong = runs
    assert weak.peak_d_star < 1e-4 and not weak.collapsed
    assert strong.collapsed or strong.peak_d_star > 2e-3
