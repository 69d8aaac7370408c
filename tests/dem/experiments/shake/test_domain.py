"""The DEM failure domain over sine frequencies (:func:`dem_failure_domain`, its simulations replaced
by a stand-in with known thresholds) and the four-bar / two-bar domains set beside it
(:func:`analytic_domains`, against the linkages' own multipliers and dynamics)."""
from __future__ import annotations

import math

import pytest

from analytic.limit.limit_discrete import solve_lp
from analytic.motions.inputs import SinePulse
from dem.experiments.shake import thresholds
from dem.experiments.shake.domain import analytic_domains, dem_failure_domain
from specimens.blocks import discretise
from specimens.catalogue import get_specimen
from specimens.constants import NO_SLIDING_MU, REFERENCE_MU_BASE, REFERENCE_MU_JOINT, G
from foundation.errors import ArchdemInputError

SPEC = get_specimen("Sh02-Sd020")  # static onset about 0.35 g
A_MAX_RATIO, SCAN_RATIO, TOL = 4.0, 1.15, 0.01
# stand-in truths per frequency [Hz]: the collapsing amplitudes [g], and the mode and phase of a collapse
TRUTHS = {
    2.0: (lambda a: a >= 0.50, "rocking", "before-first-rebound"),
    4.0: (lambda a: 0.45 <= a < 0.60 or a >= 0.80, "mixed", "after-first-rebound"),  # a survival window
    8.0: (lambda a: False, "", None),  # nothing collapses inside the scan
}
EDGES = {2.0: 0.50, 4.0: 0.45}  # the least collapsing amplitude [g]


@pytest.fixture
def stand_in(monkeypatch):
    """Replace the shake run by :data:`TRUTHS`; return the list of runs it was asked for."""
    runs = []

    def collapses(model, motion, settings, protocol):
        assert isinstance(motion, SinePulse) and motion.phase == 0.0  # the plain one-cycle sine
        a = motion.pga / G
        runs.append((model.name, motion.f, a, settings.mu_joint, settings.mu_base))
        truth, mode, phase = TRUTHS[motion.f]
        return (True, mode, phase) if truth(a) else (False, "none", None)

    monkeypatch.setattr(thresholds, "collapses", collapses)
    return runs


def _domain(freqs=(4.0, 2.0, 8.0), spec=SPEC, **kw):
    return dem_failure_domain(spec.id, spec.arch, freqs, a_max_ratio=A_MAX_RATIO, scan_ratio=SCAN_RATIO, tol=TOL,
                              workers=kw.pop("workers", 1), **kw)


# ----------------------------------------------------------------------------- DEM domain
def test_dem_domain_reproduces_the_stand_in_thresholds_point_by_point(stand_in):
    dom = _domain()
    # one threshold per frequency, in the order asked, the one without collapse kept
    assert [t["freq"] for t in dom["thresholds"]] == [4.0, 2.0, 8.0]
    by_f = {t["freq"]: t for t in dom["thresholds"]}
    for f, edge in EDGES.items():
        t = by_f[f]
        lo, hi = t["bracket_g"]
        assert lo < edge <= hi == t["amplitude_g"] and hi / lo - 1 <= TOL
        assert (t["mode"], t["collapse_phase"]) == TRUTHS[f][1:]
        assert t["n_sims"] == sum(1 for r in stand_in if r[1] == f)
    assert by_f[8.0]["amplitude_g"] is None and by_f[8.0]["bracket_g"] is None
    assert {b["outcome"] for b in dom["bands"] if b["x"] == 8.0} == {"survival"}
    # points: the thresholds (phase in the analytic names) and the edge above the 4 Hz survival window
    names = {"before-first-rebound": "first-half-cycle", "after-first-rebound": "after-impact"}
    firsts = [p for p in dom["points"] if p["mode"] != "collapse"]
    assert [(p["x"], p["amplitude_g"], p["mode"], p["dem_mode"]) for p in firsts] == [
        (f, by_f[f]["amplitude_g"], names[TRUTHS[f][2]], TRUTHS[f][1]) for f in (4.0, 2.0)]
    (again,) = [p for p in dom["points"] if p["mode"] == "collapse"]
    assert again["x"] == 4.0 and 0.80 / SCAN_RATIO <= again["amplitude_g"] <= 0.80 * SCAN_RATIO
    (window,) = by_f[4.0]["survival_bands_above"]
    assert window["edge_bracket_g"][0] < 0.60 <= window["edge_bracket_g"][1]


def test_dem_domain_scans_from_the_static_lp_onset(stand_in):
    asm = discretise(SPEC.arch, config="glued")
    lam = solve_lp(asm, REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam
    dom = _domain(freqs=(8.0,))
    assert dom["lambda"] == pytest.approx(lam, rel=1e-12)
    assert dom["a_range_g"] == [dom["lambda"], A_MAX_RATIO * dom["lambda"]]
    assert (dom["id"], dom["config"], dom["mu_joint"], dom["mu_base"]) == (SPEC.id, "glued", REFERENCE_MU_JOINT,
                                                                          REFERENCE_MU_BASE)
    amps = [r[2] for r in stand_in]
    # nothing collapses at 8 Hz: the whole scan is run, from the onset to its top
    assert min(amps) == pytest.approx(lam, rel=1e-12) and max(amps) == pytest.approx(A_MAX_RATIO * lam, rel=1e-12)
    assert {r[0] for r in stand_in} == {SPEC.id}
    assert {(r[3], r[4]) for r in stand_in} == {(REFERENCE_MU_JOINT, REFERENCE_MU_BASE)}


def test_dem_domain_onset_and_runs_follow_the_friction_given(stand_in):
    """With no sliding the onset is the no-sliding LP, and the runs get those frictions too (on an
    arch whose LP slides at the reference friction, so that the friction changes the onset)."""
    spec = get_specimen("Sh1-Sd025")
    dom = _domain(freqs=(8.0,), spec=spec, mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU)
    asm = discretise(spec.arch, config="glued")
    assert dom["lambda"] == pytest.approx(solve_lp(asm, NO_SLIDING_MU, NO_SLIDING_MU).lam, rel=1e-12)
    assert dom["lambda"] > solve_lp(asm, REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam  # friction matters here
    assert stand_in and {(r[3], r[4]) for r in stand_in} == {(NO_SLIDING_MU, NO_SLIDING_MU)}


def test_dem_domain_same_with_one_and_two_processes(stand_in):
    one, two = _domain(), _domain(workers=2)
    strip = lambda d: [{k: v for k, v in t.items() if k != "wall_s"} for t in d["thresholds"]]  # noqa: E731
    assert strip(two) == strip(one)
    assert (two["points"], two["bands"]) == (one["points"], one["bands"])


def test_dem_domain_refuses_an_arch_without_a_static_onset(monkeypatch, stand_in):
    monkeypatch.setattr(thresholds, "static_onset", lambda model, settings: 0.0)
    with pytest.raises(ArchdemInputError, match="no positive static collapse multiplier"):
        _domain()
    assert stand_in == []


@pytest.mark.parametrize("freqs", [(), (2.0, -1.0), (math.nan,)])
def test_dem_domain_refuses_a_bad_frequency_grid(stand_in, freqs):
    with pytest.raises(ArchdemInputError, match="frequency grid"):
        _domain(freqs=freqs)
    assert stand_in == []


# ----------------------------------------------------------------------------- analytic domains
FREQS = (6.0, 2.0)  # unordered on purpose


@pytest.fixture(scope="module")
def analytic():
    return analytic_domains(SPEC.arch, FREQS, workers=1)


@pytest.mark.slow
def test_analytic_domains_are_the_four_bar_and_two_bar_of_the_arch(analytic):
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.limit.two_bar import lambda_two_bar

    assert set(analytic) == {"four-bar", "two-bar"}
    # the minimised four-bar is the continuous ring's collapse mechanism: same multiplier
    assert analytic["four-bar"].lam == pytest.approx(continuous_collapse(SPEC.arch).lam, rel=1e-9)
    assert analytic["two-bar"].lam == pytest.approx(lambda_two_bar(SPEC.arch), rel=1e-9)
    for dom in analytic.values():
        assert dom.input_kind == "sine0" and [c.x for c in dom.columns] == list(FREQS)
        lo, hi = dom.a_range
        assert lo == pytest.approx(dom.lam * G, rel=1e-6) and hi == pytest.approx(10 * dom.lam * G, rel=1e-6)
        # one threshold at least per frequency, each above the static onset
        assert sorted({p["x"] for p in dom.points()}) == sorted(FREQS)
        assert all(p["amplitude_g"] > dom.lam for p in dom.points())


@pytest.mark.slow
def test_analytic_domains_agree_with_failure_domain_called_directly(analytic):
    from analytic.rocking import linkage
    from analytic.rocking.domain import failure_domain

    fb = failure_domain(linkage.minimised_four_bar(SPEC.arch, 500.0), "sine0", FREQS, workers=1)
    got, want = analytic["four-bar"].points(), fb.points()
    assert [(p["x"], p["mode"]) for p in got] == [(p["x"], p["mode"]) for p in want]
    assert [p["amplitude_g"] for p in got] == pytest.approx([p["amplitude_g"] for p in want], rel=1e-9)


@pytest.mark.parametrize("freq", FREQS)
@pytest.mark.slow
def test_four_bar_threshold_separates_survival_from_collapse(analytic, freq):
    """The four-bar's own dynamics just below and just above its least collapsing amplitude."""
    from analytic.rocking import linkage
    from analytic.rocking.dynamics import simulate

    mech = linkage.minimised_four_bar(SPEC.arch, 500.0)
    a = min(p["amplitude_g"] for p in analytic["four-bar"].points() if p["x"] == freq) * G
    assert not simulate(mech, SinePulse(a * 0.995, freq), record=False).collapsed
    assert simulate(mech, SinePulse(a * 1.005, freq), record=False).collapsed


def _threshold_summary(a, status="settled", lo=None, hi=None):
    """A threshold's summary as the domain holds it, collapsing from ``a`` [g] (None: not up to the top)."""
    readings = [{"check": c} for c in ("search", "search", "half step", "half step", "lmgc90")]
    return {"freq": 4.0, "amplitude_g": a, "bracket_g": None if a is None else [0.9 * a, a], "mode": "rocking" if a else "",
            "collapse_phase": None, "survival_bands_above": [{"from_g": 0.6, "to_g": 0.8}] if a else [], "n_sims": 12,
            "verdict": {"status": status, "text": status, "range_g": [lo, hi], "readings": readings, "wall_s": 5.0}}


def test_a_domain_threshold_row_sets_the_dem_beside_the_linkages(tmp_path):
    """The shake step's row: NaN where a threshold is missing, the DEM / four-bar ratio, the checks' runs
    (the search's own not counted), and a CSV read back typed through the declared schema."""
    from dem.common.tables import read_csv
    from dem.experiments.shake.domain import DomainThreshold

    (row,) = DomainThreshold.of("A", 0.3, _threshold_summary(0.5, "range", 0.45, None), 0.4, None).rows()
    assert list(row) == DomainThreshold.SCHEMA.names
    assert row["ratio_dem_to_four_bar"] == pytest.approx(1.25) and math.isnan(row["a_two_bar_g"])
    assert row["survival_bands_above"] == "0.600-0.800" and row["check_runs"] == 3
    assert (row["range_low_g"], math.isnan(row["range_high_g"])) == (0.45, True)
    (none,) = DomainThreshold.of("A", 0.3, _threshold_summary(None), None, 0.2).rows()
    assert math.isnan(none["a_dem_g"]) and math.isnan(none["ratio_dem_to_four_bar"]) and none["dem_mode"] == ""
    DomainThreshold(row).write_csv(tmp_path / "shake.csv")
    _, (back,) = read_csv(tmp_path / "shake.csv")
    assert back["n_sims"] == 12 and back["a_dem_g"] == 0.5 and back["verdict"] == "range"


def test_the_dem_domain_text_and_json():
    from dem.experiments.shake.domain import dem_domain_json, dem_domain_lines

    t = _threshold_summary(0.5)
    res = {"physics_engine": "mujoco", "dt": 1.25e-4, "config": "glued", "mu_joint": 0.577, "mu_base": 1.0,
           "lambda": 0.3, "a_range_g": [0.3, 1.8], "thresholds": [t, {**t, "freq": 8.0, "amplitude_g": None,
                                                                      "survival_bands_above": []}]}
    # each frequency's verdict in a few words, then the checks' runs (the search's own not counted) and cost
    assert dem_domain_lines("A", res) == ["A  DEM (mujoco, dt 0.000125 s, glued, mu 0.577/1)  static lambda 0.3000",
                                          "       4 Hz: collapse from 0.5000 g; survives again 0.600-0.800 g; settled",
                                          "       8 Hz: collapse from none up to 1.800 g; settled",
                                          "  checks: 6 runs, 10.0 s"]
    assert dem_domain_lines("A", {**res, "plot": "d.png"})[-1] == "figure: d.png"
    js = dem_domain_json(res)
    assert js["thresholds"][0] == {k: t[k] for k in ("freq", "amplitude_g", "bracket_g", "mode", "collapse_phase", "n_sims",
                                                     "verdict")}
    assert {k: v for k, v in js.items() if k != "thresholds"} == {k: v for k, v in res.items() if k != "thresholds"}
