"""The campaign's estimate counts the shake step's settled-or-range checks: their runs and their cost
beside the searches' (no simulation here)."""
from pathlib import Path

import pytest

from dem.campaign import estimate as est_mod
from dem.campaign.estimate import ENGINE_COST, UNIT_CORE_S, estimate, shake_search_runs
from dem.common.campaign import CampaignContext
from dem.core.settings import DYNAMICS_ENGINE
from specimens.catalogue import select_specimens
from specimens.constants import NO_SLIDING_MU


def _ctx(tmp_path, quick: bool, **kw) -> CampaignContext:
    return CampaignContext(out=Path(tmp_path), specimens=select_specimens("all"), quick=quick, workers=2, **kw)


def test_a_search_is_its_scan_and_bisection():
    # quick: 4 x lambda by 1.15 is 11 amplitudes, 3 bisections to 2 %; full: 6 x by 1.15, 14, and 4 to 1 %
    assert (shake_search_runs(True), shake_search_runs(False)) == (14, 18)


def test_the_quick_campaign_counts_the_half_step_check_alone(tmp_path, monkeypatch):
    # LMGC90 would be asked at 6 Hz (friction below the no-sliding 10), but the quick campaign never asks it
    monkeypatch.setattr(est_mod, "reference_unavailable", lambda model, settings: "")
    (s,) = estimate(_ctx(tmp_path, True), ["shake"]).values()
    assert s["units"] == 2 and s["check_runs"] == 2 * 2
    assert s["what"] == "sine-pulse thresholds and 4 check runs"
    # two runs at half the step cost four of the search's 14: the check adds 4/14 to the searches
    search = s["wall_s"] - s["check_wall_s"]
    assert s["check_wall_s"] == pytest.approx(search * 4 / 14)


@pytest.mark.parametrize("lmgc90", ["", "LMGC90 is not installed"])
def test_the_full_campaign_counts_lmgc90_where_the_rule_asks_it(tmp_path, monkeypatch, lmgc90):
    monkeypatch.setattr(est_mod, "reference_unavailable", lambda model, settings: lmgc90)
    (s,) = estimate(_ctx(tmp_path, False), ["shake"]).values()
    # 6 specimens x 5 frequencies, each 2 half-step runs; LMGC90 at 6 and 8 Hz (strictly inside 4-10 Hz)
    ref = 0 if lmgc90 else 6 * 2 * 2
    assert s["units"] == 30 and s["check_runs"] == 30 * 2 + ref
    run = UNIT_CORE_S[("shake", False)] / 18  # one search run on PyBullet at 0.5 ms, core-seconds
    mine = run * ENGINE_COST[DYNAMICS_ENGINE] * est_mod.DYNAMICS_DT_COST  # ... on the shakes' engine and step
    assert s["check_wall_s"] == pytest.approx((30 * 2 * 2 * mine + ref * run * ENGINE_COST["lmgc90"]) / 2)


def test_no_lmgc90_check_when_the_joints_cannot_slide(tmp_path, monkeypatch):
    monkeypatch.setattr(est_mod, "reference_unavailable", lambda model, settings: "")
    no_sliding = est_mod.Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU)
    monkeypatch.setattr(CampaignContext, "dynamics_of", lambda self, spec: no_sliding)
    (s,) = estimate(_ctx(tmp_path, False), ["shake"]).values()
    assert s["check_runs"] == 30 * 2


def test_the_checks_scale_with_the_machine_like_the_searches(tmp_path):
    ctx = _ctx(tmp_path, False)
    base = estimate(ctx, ["shake"])["shake"]
    slow = estimate(ctx, ["shake"], speed=2 * est_mod.REFERENCE_SPEED[ctx.engine])["shake"]
    assert slow["check_wall_s"] == pytest.approx(2 * base["check_wall_s"]) and base["check_wall_s"] > 0
