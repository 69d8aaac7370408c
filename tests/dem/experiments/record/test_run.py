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


def test_a_record_files_summary_is_its_schema_row():
    """``run(RecordSpec)`` on the shipped record: its row (the JSON of ``archdem record``) in the schema's
    columns, the PGA in g and m/s^2 alike, and the text's lines."""
    from analytic.motions.records import example_record, read_record
    from dem.experiments.record.run import RecordSpec, RecordSummary, run
    from specimens.constants import G

    path = example_record()
    s = run(RecordSpec(str(path)))
    m = read_record(path)
    (row,) = s.to_json()
    assert list(row) == RecordSummary.SCHEMA.names and row["npts"] == len(m.values) and row["format"] == "at2"
    assert row["pga_g"] == pytest.approx(row["pga_ms2"] / G) and row["pga_ms2"] == pytest.approx(m.pga)
    assert row["t_pga"] == pytest.approx(np.argmax(np.abs(m.values)) * m.dt)
    lines = s.lines()
    assert lines[0] == f"file      {path}" and lines[-1].startswith(f"PGA       {row['pga_g']:.4f} g = ")


def test_a_record_threshold_row_scales_the_record_and_the_lambda():
    from dem.experiments.record.run import RecordThreshold
    from specimens.constants import G

    (row,) = RecordThreshold.of("A", "r.AT2", (1.0, 4.5), 0.2 * G, 0.3, 0.6, "rocking", 9).rows()
    assert list(row) == RecordThreshold.SCHEMA.names and row["window_s"] == "1.00-4.50"
    assert (row["pga_record_g"], row["scale_factor"], row["ratio_to_static"]) == pytest.approx((0.2, 3.0, 2.0))
    (none,) = RecordThreshold.of("A", "r.AT2", (1.0, 4.5), 0.2 * G, 0.3, None, None, 9).rows()
    assert all(np.isnan(none[k]) for k in ("collapse_pga_g", "scale_factor", "ratio_to_static")) and none["mode"] == ""


def test_a_record_runs_description_is_its_row():
    (row,) = _run(0.02, collapsed=True).rows()
    assert _run(0.02, collapsed=True).describe() == row == {
        "record": "r", "scale": 1.0, "pga": 1.0, "collapsed": True, "mode": "", "peak_d_star": 0.02, "wall_s": 0.0}
