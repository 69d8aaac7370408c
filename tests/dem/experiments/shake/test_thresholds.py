"""Shake thresholds: scan + bisection, bands of a non-monotonic outcome, the block threshold,
and the arch threshold against its static onset and the four-bar model."""
import math

import pytest

from analytic.motions.inputs import SinePulse
from dem.core.model import single_block
from dem.core.settings import Settings, dynamics_settings
from dem.experiments.shake import thresholds
from dem.experiments.shake.run import ShakeProtocol
from dem.experiments.shake.thresholds import CHECK_MARGIN, Outcome, _bands, scan_grid, threshold
from specimens.constants import NO_SLIDING_MU, G


def test_scan_grid_spacing():
    g = scan_grid(0.3, 1.2, 1.15)
    assert g[0] == pytest.approx(0.3) and g[-1] == pytest.approx(1.2)
    assert max(g[1:] / g[:-1]) <= 1.15 + 1e-12  # never coarser than the ratio asked for


def test_bands_keep_survival_windows():
    # collapse at 0.5, survival again at 0.8-0.9, collapse from 1.0 (the Sh02-Sd020 pattern,
    # docs/physics/dem.md#10-shake-thresholds-and-dem-failure-domains)
    runs = [Outcome(a, c, "rocking", None) for a, c in
            [(0.3, False), (0.4, False), (0.5, True), (0.6, True), (0.8, False), (0.9, False), (1.0, True)]]
    b = _bands(runs, 0.45)
    assert [x["outcome"] for x in b] == ["survival", "collapse", "survival", "collapse"]
    assert b[1]["from_g"] == pytest.approx(0.45)  # the bisected first threshold
    assert b[2]["from_g"] == pytest.approx(math.sqrt(0.6 * 0.8))  # later edges: middle of the scan bracket
    assert b[3]["from_g"] == pytest.approx(math.sqrt(0.9 * 1.0))


def _fake_motion(a, f):
    return SinePulse(a, f)


@pytest.mark.parametrize("max_sims", [60, 30, 27])
def test_stepping_below_the_scan_reports_only_simulated_ends(monkeypatch, max_sims):
    # every scanned amplitude collapses (truth 0.25 g below a_min 0.3 g): the search steps down below the
    # scan, even with the budget spent on a 25-point scan, and the bracket it reports was simulated at both ends
    ran = []

    def fake(args):
        ran.append(args[4])
        return Outcome(float(args[4]), args[4] >= 0.25, "rocking", None)

    monkeypatch.setattr(thresholds, "_run_one", fake)
    r = threshold(single_block(0.1, 0.4), 4.0, a_min_g=0.3, a_max_g=0.3 * 1.05 ** 24, scan_ratio=1.05, tol=0.01,
                  workers=1, max_sims=max_sims)
    lo, hi = r.bracket_g
    assert lo in ran and hi in ran and lo < 0.25 <= hi
    if max_sims == 60:
        assert hi / lo - 1 <= 0.01


def test_threshold_finds_lowest_edge_of_non_monotonic_outcome(monkeypatch):
    """Scan first, then bisect the lowest bracket: with collapse on [0.45, 0.78) and [0.9, inf) the
    answer is 0.45 (to 1 %), and the survival window above it is reported (a stand-in for the
    simulator, so that the search logic is checked against a known truth)."""
    truth = lambda a: (0.45 <= a < 0.78) or a >= 0.9  # noqa: E731

    def fake(args):
        a = args[4]
        return Outcome(float(a), truth(a), "rocking" if truth(a) else "none", None)

    monkeypatch.setattr(thresholds, "_run_one", fake)
    r = threshold(single_block(0.1, 0.4), 4.0, a_min_g=0.3, a_max_g=1.5, scan_ratio=1.1, tol=0.01, workers=1)
    lo, hi = r.bracket_g
    assert lo < 0.45 <= hi and hi / lo - 1 <= 0.01
    assert r.amplitude_g == hi
    above = r.survival_bands_above
    assert len(above) == 1
    # the window's edges are known to the scan resolution: each true edge lies in its scan bracket
    lo_w, hi_w = above[0]["edge_bracket_g"]
    assert lo_w < 0.78 <= hi_w and hi_w / lo_w <= 1.1 + 1e-9
    nxt = r.bands[r.bands.index(above[0]) + 1]
    assert nxt["edge_bracket_g"][0] < 0.9 <= nxt["edge_bracket_g"][1]


# stand-ins for the simulator that worker processes can import: the pulse "frequency" picks the truth
_TRUTHS = {
    1.0: lambda a: (0.45 <= a < 0.78) or a >= 0.9,  # threshold inside the scan, a survival window above
    2.0: lambda a: a >= 1.37,  # threshold near the top of the scan
    3.0: lambda a: a >= 0.26,  # the lowest amplitude collapses: step down below the scan
    4.0: lambda a: False,  # nothing collapses
}


def _fake_run(args):
    import time

    a, f = args[4], args[5]
    c = _TRUTHS[f](a)
    time.sleep(0.01 if c else 0.03)  # survivals run longer than collapses, as in the simulator
    return Outcome(float(a), c, "rocking" if c else "none", None)


@pytest.mark.parametrize("freq", sorted(_TRUTHS))
def test_threshold_same_runs_with_one_and_two_processes(monkeypatch, freq):
    """With two processes the bisection overlaps the rest of the scan; it must make exactly the
    runs of the serial search (same amplitudes, same order in the result) and give its answer."""
    monkeypatch.setattr(thresholds, "_run_one", _fake_run)
    kw = dict(a_min_g=0.3, a_max_g=1.5, scan_ratio=1.1, tol=0.01)
    one = threshold(single_block(0.1, 0.4), freq, **kw, workers=1)
    two = threshold(single_block(0.1, 0.4), freq, **kw, workers=2)
    assert two.runs == one.runs
    assert (two.amplitude_g, two.bracket_g, two.bands) == (one.amplitude_g, one.bracket_g, one.bands)
    if freq == 1.0:
        lo, hi = two.bracket_g
        assert lo < 0.45 <= hi and hi / lo - 1 <= 0.01


@pytest.mark.slow
def test_block_threshold_scan_and_bisection():
    """Full search on the single block at 3 Hz (planar, no sliding, two processes): the answer lies
    within 10 % of the analytic rocking-block threshold 0.3602 g (see test_shake for the tolerance),
    the bracket is 1 % wide and its ends were simulated with the stated outcomes."""
    from analytic.rocking.domain import failure_domain
    from analytic.rocking.rocking_block import RockingBlock

    a_an = failure_domain(RockingBlock(0.05, 0.2), "sine0", [3.0], a_max_ratio=8.0, n_scan=16,
                          workers=1).columns[0].thresholds[0][0] / G
    st = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, planar=True)
    r = threshold(single_block(0.1, 0.4), 3.0, st, ShakeProtocol(tail=2.0), a_min_g=0.25, a_max_g=0.6,
                  scan_ratio=1.2, tol=0.01, workers=2)
    assert r.amplitude_g == pytest.approx(a_an, rel=0.10)
    lo, hi = r.bracket_g
    assert hi / lo - 1 <= 0.01
    outcome = {round(x.amplitude_g, 12): x.collapsed for x in r.runs}
    assert outcome[round(hi, 12)] and not outcome[round(lo, 12)]
    assert r.amplitude_g >= 0.25  # never below the static onset b/h


@pytest.mark.slow
def test_arch_threshold_no_sliding_2hz_above_static_onset():
    """Sh02-Sd020, glued, friction high enough to prevent sliding, 2 Hz: the DEM least collapsing
    amplitude is at least the static onset lambda g of the LP (below it nothing moves), and within
    the scatter of impact modelling of the four-bar threshold (minimised layout, plain sine). The
    reference study found the four-bar conservative (DEM / four-bar >= 1); here it is not (0.935)."""
    from analytic.limit.limit_discrete import solve_lp
    from analytic.rocking import linkage
    from analytic.rocking.domain import failure_domain
    from dem.core.model import from_assembly
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    arch = get_specimen("Sh02-Sd020").arch
    asm = discretise(arch, config="glued")
    lam = solve_lp(asm, math.inf, math.inf).lam
    st = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU)
    # 2 % bisection and a 1.25 scan keep this to ~12 simulations
    r = threshold(from_assembly(asm, name="Sh02-Sd020"), 2.0, st, ShakeProtocol(tail=1.0), a_min_g=lam,
                  a_max_g=3 * lam, scan_ratio=1.25, tol=0.02, workers=2)
    assert r.amplitude_g is not None
    # 1 % below: hold tilt thresholds lie at most 2.8 % below the LP (docs/validation.md#4-no-sliding-tilt-against-the-lp), not more
    assert r.amplitude_g >= lam * (1 - 0.01)
    fb = linkage.arch_four_bar(arch, linkage.minimised_layout(arch), direction=1)
    a_fb, mode = failure_domain(fb, "sine0", [2.0], a_max_ratio=10, n_scan=24, workers=1).columns[0].thresholds[0]
    # the four-bar collapses after its first impact, where the DEM's impact (contact points, error
    # reduction) and the momentum balance differ: the single block's 10 % applies (test_shake.py,
    # docs/validation.md#3-single-block). Measured: DEM 0.3973 g, four-bar 0.4251 g (-6.5 %)
    assert mode == "after-impact"
    assert r.amplitude_g == pytest.approx(a_fb / G, rel=0.10)


@pytest.mark.slow
def test_a_threshold_on_a_local_dask_cluster_is_the_local_one():
    """A real scheduler and two worker processes run the scan and the bisection: the same runs."""
    distributed = pytest.importorskip("distributed")
    block = single_block(0.1, 0.4)
    st = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, planar=True)
    local = threshold(block, 2.0, st, a_min_g=0.27, a_max_g=0.4, workers=2)
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None) as cl:
        remote = threshold(block, 2.0, st, a_min_g=0.27, a_max_g=0.4, scheduler=cl.scheduler_address)
    assert remote.amplitude_g == local.amplitude_g and remote.bracket_g == local.bracket_g
    assert [(r.amplitude_g, r.collapsed) for r in remote.runs] == [(r.amplitude_g, r.collapsed) for r in local.runs]


@pytest.mark.parametrize("workers", [1, 2])
@pytest.mark.parametrize("freq", sorted(_TRUTHS))
def test_progress_counts_every_run_and_ends_on_the_total(monkeypatch, freq, workers):
    # one report as each run ends: runs done 1..n, a total never below them that ends on n; each note
    # the amplitude and its outcome, and the bracket once it is known (here, a scan of 18 and 4 bisections)
    monkeypatch.setattr(thresholds, "_run_one", _fake_run)
    calls = []
    r = threshold(single_block(0.1, 0.4), freq, a_min_g=0.3, a_max_g=1.5, scan_ratio=1.1, tol=0.01, workers=workers,
                  progress=lambda done, total, note: calls.append((done, total, note)))
    assert calls[0] == (0, 18 + 4, "scan 0.3000-1.5000 g")
    assert [c[0] for c in calls[1:]] == list(range(1, r.n_sims + 1))
    assert all(total >= done for done, total, _ in calls) and calls[-1][1] == r.n_sims
    assert sorted(c[2].split(" g ")[0] for c in calls[1:]) == sorted(f"{o.amplitude_g:.4f}" for o in r.runs)
    if r.bracket_g is not None:
        assert calls[-1][2].endswith(f"bracket [{r.bracket_g[0]:.4f}, {r.bracket_g[1]:.4f}] g") or freq == 3.0


def test_failure_domain_reports_each_frequency(monkeypatch):
    monkeypatch.setattr(thresholds, "_run_one", _fake_run)
    calls = []
    thresholds.failure_domain(single_block(0.1, 0.4), [1.0, 4.0], workers=1, a_min_g=0.3, a_max_g=1.5, scan_ratio=1.1,
                              progress=lambda done, total, note: calls.append((done, total, note)))
    assert calls[0] == (0, 2, "2 frequencies")
    assert calls[1][:2] == (1, 2) and calls[1][2].startswith("1 Hz: 0.45")
    assert calls[2] == (2, 2, "4 Hz: no collapse")


# ------------------------------------------------------------------- settled or a range
def _checked(monkeypatch, freq: float, truths: dict, mu: float = 0.577, unavailable: str = "", check=True):
    """A search whose runs collapse from ``truths["search"]`` [g] (None: never), and its check, whose
    half-step and LMGC90 runs collapse from their own truths: stand-ins for the simulator."""
    from dem.experiments.shake.thresholds import Reading

    def hit(name, a):
        t = truths[name]
        return t is not None and a >= t

    monkeypatch.setattr(thresholds, "_run_one", lambda args: Outcome(float(args[4]), hit("search", args[4]),
                                                                     "sliding", None))
    monkeypatch.setattr(thresholds, "_read_one", lambda args: Reading(args[0], args[2].engine, args[2].dt, float(args[5]),
                                                                      hit(args[0], args[5]), "sliding", ("R8",)))
    monkeypatch.setattr(thresholds, "reference_unavailable", lambda model, st: unavailable)
    st = Settings(engine="mujoco", dt=1.25e-4, mu_joint=mu, mu_base=mu)
    return threshold(single_block(0.1, 0.4), freq, st, a_min_g=0.3, a_max_g=1.5, scan_ratio=1.1, tol=0.01, workers=1,
                     check=check)


def test_a_bracket_every_check_reads_alike_is_settled(monkeypatch):
    r = _checked(monkeypatch, 6.0, {"search": 0.5, "half step": 0.5, "lmgc90": 0.5})
    v = r.verdict
    assert v.status == "settled" and v.checks == ("half step", "lmgc90")
    # the bracket's two ends, once per check, and nothing else: no new search
    lo, hi = r.bracket_g
    assert sorted((x.check, x.amplitude_g) for x in v.readings if x.check != "search") == sorted(
        (c, a) for c in ("half step", "lmgc90") for a in (lo / CHECK_MARGIN, hi * CHECK_MARGIN))
    lm = [x for x in v.readings if x.check == "lmgc90"]
    assert {(x.engine, x.dt) for x in lm} == {("lmgc90", Settings().dt)}  # the reference at its own step
    assert {x.dt for x in v.readings if x.check == "half step"} == {0.5 * 1.25e-4}
    assert r.summary()["verdict"]["status"] == "settled"


def test_readings_within_the_margin_settle_and_beyond_it_do_not(monkeypatch):
    # the engines' scatter where they agree (a few %) is not a range; a difference of 8 % is
    assert _checked(monkeypatch, 6.0, {"search": 0.5, "half step": 0.49, "lmgc90": 0.515}).verdict.status == "settled"
    assert _checked(monkeypatch, 6.0, {"search": 0.5, "half step": 0.5, "lmgc90": 0.54}).verdict.status == "range"


def test_outside_the_split_band_only_the_half_step_checks(monkeypatch):
    for freq, mu in ((4.0, 0.577), (10.0, 0.577), (6.0, NO_SLIDING_MU)):
        v = _checked(monkeypatch, freq, {"search": 0.5, "half step": 0.5, "lmgc90": None}, mu=mu).verdict
        assert v.status == "settled" and v.checks == ("half step",), (freq, mu)


def test_the_reference_standing_at_the_first_collapse_makes_a_range_that_holds_its_threshold(monkeypatch):
    r = _checked(monkeypatch, 6.0, {"search": 0.5, "half step": 0.5, "lmgc90": 0.8})
    v = r.verdict
    assert v.status == "range" and "lmgc90 stands" in v.why
    assert v.low_g == r.amplitude_g and 0.8 <= v.high_g <= 0.8 * 1.1  # LMGC90's own, to one scan step
    assert all(x.amplitude_g <= v.high_g for x in v.readings if x.check == "lmgc90")  # the walk stopped there
    assert v.text().startswith("range 0.5")


def test_a_reference_that_stands_to_the_top_leaves_the_range_open(monkeypatch):
    v = _checked(monkeypatch, 6.0, {"search": 0.5, "half step": 0.5, "lmgc90": None}).verdict
    assert v.status == "range" and v.high_g is None and "none up to 1.500" in v.text()


def test_a_half_step_collapsing_below_the_bracket_lowers_the_range(monkeypatch):
    r = _checked(monkeypatch, 2.0, {"search": 0.5, "half step": 0.4, "lmgc90": None})
    v = r.verdict
    assert v.status == "range" and v.high_g == r.amplitude_g and 0.4 <= v.low_g <= 0.4 * 1.1
    assert "half step collapses" in v.why


def test_without_the_reference_never_settled(monkeypatch):
    v = _checked(monkeypatch, 6.0, {"search": 0.5, "half step": 0.5, "lmgc90": 0.5},
                 unavailable="LMGC90 is not installed").verdict
    assert v.status == "unchecked" and v.text() == "unchecked (LMGC90 is not installed)"
    assert v.checks == ("half step",)


def test_a_reference_that_fails_leaves_the_threshold_unchecked(monkeypatch):
    r = _checked(monkeypatch, 6.0, {"search": 0.5, "half step": 0.5, "lmgc90": 0.5})
    read = thresholds._read_one

    def dies(args):
        if args[0] == "lmgc90":
            raise RuntimeError("the LMGC90 worker process ended (exit code -9); its messages are above")
        return read(args)

    monkeypatch.setattr(thresholds, "_read_one", dies)
    v = thresholds.check_threshold(r, single_block(0.1, 0.4), Settings(engine="mujoco", dt=1.25e-4), workers=1)
    assert v.status == "unchecked" and v.why.startswith("LMGC90 failed: the LMGC90 worker") and v.checks == ("half step",)


def test_the_half_step_check_alone_leaves_the_split_band_unchecked(monkeypatch):
    truths = {"search": 0.5, "half step": 0.5, "lmgc90": None}
    v = _checked(monkeypatch, 6.0, truths, check="half-step").verdict
    assert v.status == "unchecked" and v.why == "LMGC90 not asked" and v.checks == ("half step",)
    assert _checked(monkeypatch, 2.0, truths, check="half-step").verdict.status == "settled"


def test_a_search_without_collapse_is_checked_at_the_top(monkeypatch):
    v = _checked(monkeypatch, 6.0, {"search": None, "half step": None, "lmgc90": 1.2}).verdict
    assert v.status == "range" and v.high_g is None and 1.2 <= v.low_g <= 1.2 * 1.1


def test_unchecked_by_default(monkeypatch):
    monkeypatch.setattr(thresholds, "_run_one", lambda args: Outcome(float(args[4]), args[4] >= 0.5, "rocking", None))
    r = threshold(single_block(0.1, 0.4), 6.0, a_min_g=0.3, a_max_g=1.5, scan_ratio=1.1, workers=1)
    assert r.verdict is None and r.summary()["verdict"]["text"] == "unchecked (not checked)"


def test_the_reference_says_what_it_cannot_run():
    from dem.core.engines import engine_installed

    why = thresholds.reference_unavailable(single_block(0.1, 0.4), Settings(planar=True))
    assert why and "settled" not in why
    if engine_installed("lmgc90"):
        assert "planar" in why
        assert thresholds.reference_unavailable(single_block(0.1, 0.4), Settings()) == ""


@pytest.mark.slow
def test_lmgc90_arbitrates_the_sliding_collapse_of_sh06_sd015_at_6_hz():
    """The case where the engines split (free crown, friction 0.577 on every joint and the base, 6 Hz):
    MuJoCo's search collapses from 0.840 g by sliding at the crown and the base, LMGC90 stands there
    (its crown moves some 40 mm, then rests). The check of that bracket is a range, never settled,
    whose top is open: LMGC90 stands at the bracket's upper end. The scan's top is put at that end so
    that no walk follows (about a minute)."""
    from dem.core.engines import engine_installed
    from dem.core.model import as_model
    from dem.experiments.shake.thresholds import ThresholdResult, check_threshold

    if not engine_installed("lmgc90"):
        pytest.skip("LMGC90 is not installed")
    model = as_model("Sh06-Sd015", config="free")
    st = dynamics_settings(mu_joint=0.577, mu_base=0.577)
    res = ThresholdResult(6.0, 0.8399, (0.8329, 0.8399), (), (), 1.15, 0.01, 0.0, "sliding",
                          a_range_g=(0.6, 0.8399 * CHECK_MARGIN))
    v = check_threshold(res, model, st, workers=2)
    lm = [r for r in v.readings if r.check == "lmgc90"]
    assert [r.collapsed for r in lm] == [False, False] and all("R8" in r.joints for r in lm)  # slides, stands
    assert v.status == "range" and v.low_g == pytest.approx(0.8399) and v.high_g is None
    assert "lmgc90 stands" in v.why


def test_the_spec_runs_as_threshold_and_its_summary_is_its_schema_row(monkeypatch, tmp_path):
    """``run(ThresholdSpec)`` is ``threshold`` with the spec's fields (a stand-in collapsing from 0.45 g); its
    summary (the JSON of ``archdem threshold`` after the arch's fields) is its one row plus ``extra``, and the
    CSV of that row reads back typed."""
    from dem.common.tables import read_csv
    from dem.experiments.shake.thresholds import ThresholdResult, ThresholdSpec, run

    monkeypatch.setattr(thresholds, "_run_one", lambda args: Outcome(float(args[4]), args[4] >= 0.45, "rocking", None))
    kw = dict(a_min_g=0.3, a_max_g=0.6, scan_ratio=1.15, tol=0.01)
    a = run(ThresholdSpec(single_block(0.1, 0.4), 4.0, **kw), workers=1)
    b = threshold(single_block(0.1, 0.4), 4.0, workers=1, **kw)
    assert (a.amplitude_g, a.bracket_g, a.runs) == (b.amplitude_g, b.bracket_g, b.runs)
    s = a.summary()
    assert list(s) == ThresholdResult.SCHEMA.names and s["verdict"]["status"] == "unchecked"
    assert s["n_sims"] == a.n_sims and s["bracket_g"] == list(a.bracket_g)
    a.write_csv(tmp_path / "t.csv")
    _, (row,) = read_csv(tmp_path / "t.csv")
    assert row["amplitude_g"] == a.amplitude_g and row["runs"] == s["runs"] and row["mode"] == "rocking"


def test_the_text_of_a_threshold_names_it_its_bracket_and_the_bands_above():
    from dem.experiments.shake.thresholds import Reading, ThresholdResult, Verdict

    bands = ({"from_g": 0.3, "to_g": 0.4, "collapse": False}, {"from_g": 0.45, "to_g": 0.6, "collapse": True},
             {"from_g": 0.7, "to_g": 0.8, "collapse": False}, {"from_g": 0.9, "to_g": 1.0, "collapse": True})
    v = Verdict("settled", checks=("half step",), wall_s=2.0, readings=(
        Reading("search", "mujoco", 1.25e-4, 0.44, False, "none"),
        Reading("half step", "mujoco", 6.25e-5, 0.47, True, "rocking", ("L1", "R1"))))
    r = ThresholdResult(4.0, 0.45, (0.44, 0.45), bands, (), 1.15, 0.01, 3.0, "rocking", "before-first-rebound",
                        a_range_g=(0.3, 1.0), verdict=v)
    first, verdict, search, half = r.text("A", 0.31).splitlines()
    assert first == ("A 4 Hz: least collapsing amplitude 0.4500 g (bracket 0.4400-0.4500, rocking, before-first-rebound); "
                     "static lambda 0.3100; survives again 0.700-0.800 g; 0 runs, 3.0 s")
    assert verdict == "  settled (half step; within 5%); 1 check runs, 2.0 s"
    assert search.split() == ["search", "mujoco", "dt", "0.125", "ms", "0.4400", "g", "stands", "none"]
    assert half.endswith("collapsed rocking (slid: L1 R1)")
    none = ThresholdResult(4.0, None, None, bands[:1], (), 1.15, 0.01, 1.0, a_range_g=(0.3, 1.0))
    assert none.text("A", 0.31) == "A 4 Hz: no collapse up to 1.000 g (0 runs, 1.0 s)"
