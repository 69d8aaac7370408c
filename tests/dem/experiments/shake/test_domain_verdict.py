"""Each threshold of the DEM failure domain carries its settled-or-range verdict: in
:func:`dem_failure_domain`'s answer, in ``archdem domain --engine dem``'s JSON and lines, and not at all
with ``--no-check`` (the runs replaced by a stand-in with known thresholds, but for the one slow test)."""
from __future__ import annotations

import json

import pytest

from analytic.motions.inputs import SinePulse
from dem.cli import main
from dem.core.settings import DYNAMICS_DT
from dem.experiments.shake import thresholds
from dem.experiments.shake.domain import dem_domain_lines, dem_failure_domain, verdict_phrase
from specimens.catalogue import get_specimen
from specimens.constants import G

SPEC = get_specimen("Sh02-Sd020")  # static onset about 0.35 g
EDGE = 0.50  # [g] the stand-in search's least collapsing amplitude at 2 Hz
HALF_STEP_EDGE = 0.60  # [g] ... and the half-step check's when it is made to disagree


@pytest.fixture
def stand_in(monkeypatch):
    """The search's runs collapse from EDGE; the checks' runs from ``edges[dt]`` (EDGE unless set). Returns
    ``(edges, checks)``: the check runs asked, as ``(check, dt, amplitude)``."""
    edges: dict[float, float] = {}
    checks: list[tuple] = []

    def collapses(model, motion, settings, protocol):
        assert isinstance(motion, SinePulse) and motion.f == 2.0
        return (True, "rocking", "before-first-rebound") if motion.pga / G >= EDGE else (False, "none", None)

    def read_one(args):
        check, model, settings, protocol, motion_fn, a_g, freq = args
        checks.append((check, settings.dt, a_g))
        c = a_g >= edges.get(settings.dt, EDGE)
        return thresholds.Reading(check, settings.engine, settings.dt, float(a_g), c, "rocking" if c else "none")

    monkeypatch.setattr(thresholds, "collapses", collapses)
    monkeypatch.setattr(thresholds, "_read_one", read_one)
    return edges, checks


def _domain(**kw):
    return dem_failure_domain(SPEC.id, SPEC.arch, (2.0,), a_max_ratio=3.0, tol=0.02, workers=1, **kw)


def test_the_domain_is_unchecked_unless_asked(stand_in):
    _, checks = stand_in
    (t,) = _domain()["thresholds"]
    assert t["verdict"]["status"] == "unchecked" and checks == []


def test_a_threshold_the_half_step_reads_alike_is_settled(stand_in):
    _, checks = stand_in
    (t,) = _domain(check=True)["thresholds"]
    v = t["verdict"]
    # 2 Hz: no LMGC90 asked; the bracket's two ends widened by 5 %, at half the step
    assert v["status"] == "settled" and v["checks"] == ["half step"]
    lo, hi = t["bracket_g"]
    assert checks == [("half step", DYNAMICS_DT / 2, pytest.approx(lo / thresholds.CHECK_MARGIN)),
                      ("half step", DYNAMICS_DT / 2, pytest.approx(hi * thresholds.CHECK_MARGIN))]
    assert verdict_phrase(v) == "settled"


def test_a_threshold_the_half_step_moves_is_a_range_holding_both(stand_in):
    edges, _ = stand_in
    edges[DYNAMICS_DT / 2] = HALF_STEP_EDGE
    (t,) = _domain(check="half-step")["thresholds"]
    v = t["verdict"]
    lo, hi = v["range_g"]
    # from the search's threshold to the half step's, found on the scan (one scan step above it at most)
    assert v["status"] == "range" and lo == t["amplitude_g"]
    assert HALF_STEP_EDGE <= hi <= HALF_STEP_EDGE * t["scan_ratio"]
    assert verdict_phrase(v) == f"range {lo:.3f}-{hi:.3f} g"


def _summary(v: thresholds.Verdict) -> dict:
    return {"freq": 6.0, "amplitude_g": 0.84, "bracket_g": [0.833, 0.84], "mode": "sliding", "collapse_phase": None,
            "survival_bands_above": [], "n_sims": 17, "verdict": v.to_dict()}


def _reading(check: str, a: float, collapsed: bool) -> thresholds.Reading:
    return thresholds.Reading(check, "lmgc90", 5e-4, a, collapsed, "none")


@pytest.mark.parametrize("verdict, phrase", [
    (thresholds.Verdict("range", "lmgc90 stands", 0.84, None, ("half step", "lmgc90"),
                        (_reading("search", 0.833, False), _reading("lmgc90", 1.245, False))),
     "range 0.840 g to above 1.245 g"),
    (thresholds.Verdict("range", "half step collapses", None, 0.84, ("half step",), (_reading("search", 0.6, True),)),
     "range below the scan to 0.840 g"),
    (thresholds.Verdict("unchecked", "LMGC90 not asked", checks=("half step",)), "unchecked (LMGC90 not asked)"),
])
def test_the_verdict_in_a_few_words(verdict, phrase):
    assert verdict_phrase(verdict.to_dict()) == phrase
    res = {"physics_engine": "mujoco", "dt": 1.25e-4, "config": "free", "mu_joint": 0.577, "mu_base": 0.577,
           "lambda": 0.5, "a_range_g": [0.5, 3.0], "thresholds": [_summary(verdict)]}
    assert dem_domain_lines("A", res)[1].endswith(f"collapse from 0.8400 g; {phrase}")


def test_the_lines_of_an_unchecked_search_carry_no_verdict():
    res = {"physics_engine": "mujoco", "dt": 1.25e-4, "config": "free", "mu_joint": 0.577, "mu_base": 0.577,
           "lambda": 0.5, "a_range_g": [0.5, 3.0], "thresholds": [_summary(thresholds.NOT_CHECKED)]}
    assert dem_domain_lines("A", res)[1:] == ["       6 Hz: collapse from 0.8400 g"]


def test_archdem_domain_checks_by_default_and_not_with_no_check(stand_in, capsys):
    _, checks = stand_in
    argv = ["domain", SPEC.id, "--engine", "dem", "--freq", "2", "--amax", "3", "--workers", "1"]
    assert main(argv + ["--json"]) == 0
    (t,) = json.loads(capsys.readouterr().out)["thresholds"]
    assert t["verdict"]["status"] == "settled" and t["verdict"]["checks"] == ["half step"] and len(checks) == 2
    assert main(argv) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[1].endswith("; settled") and out[2].startswith("  checks: 2 runs, ")
    checks.clear()
    assert main(argv + ["--no-check", "--json"]) == 0
    (t,) = json.loads(capsys.readouterr().out)["thresholds"]
    assert t["verdict"]["status"] == "unchecked" and checks == []
    assert main(["domain", SPEC.id, "--no-check"]) == 2  # the analytic linkage has nothing to check
    assert "--no-check does nothing here: it checks the DEM's thresholds" in capsys.readouterr().err


@pytest.mark.slow
def test_a_real_domain_threshold_is_checked_at_half_the_step():
    """One frequency, a coarse scan and bisection on the shakes' engine: the check's runs are the bracket's
    ends at half the step, and the verdict holds the threshold."""
    (t,) = dem_failure_domain(SPEC.id, SPEC.arch, (2.0,), a_max_ratio=3.0, scan_ratio=1.5, tol=0.1, workers=1,
                              check=True)["thresholds"]
    v = t["verdict"]
    assert t["amplitude_g"] is not None and v["status"] in ("settled", "range")
    runs = [r for r in v["readings"] if r["check"] != "search"]
    assert {r["dt"] for r in runs} == {DYNAMICS_DT / 2} and len(runs) >= 2
    if v["status"] == "range":
        lo, hi = v["range_g"]
        assert (lo is None or lo <= t["amplitude_g"]) and (hi is None or hi >= t["amplitude_g"])
