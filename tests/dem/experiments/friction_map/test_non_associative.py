"""The friction map's mu* without dilatancy (non-associative limit analysis): its search, its place in the
map's JSON, rows, command table, figures and the campaign's findings."""
from __future__ import annotations

import functools
import math
import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from dem.experiments.friction_map import map_cmd
from dem.experiments.friction_map import run as fm
from dem.experiments.friction_map.figure import plot_lambda_mu, save_map_figures
from dem.experiments.friction_map.step_map import non_associative_findings
from specimens.catalogue import get_specimen

SID = "Sh02-Sd015"  # the cheapest mixed-integer programs of the catalogue (about 1 s each)


def _result(mu_star_na=0.42) -> fm.MapResult:
    """A map of one specimen made by hand: nothing simulated or solved."""
    mu = np.array([0.3, 0.4, 0.5, 0.6])
    a = fm.AnalyticCurves(mu, np.array([0.2, 0.25, 0.3, 0.3]), np.full(4, np.nan), 0.3, 0.3, 0.31, 0.1, 0.38, 0.5,
                          0.55, mu_star_na=mu_star_na, mu_na=mu[:2], lam_na=np.array([0.19, 0.24]), seconds_na=3.0)
    points = [fm.MapPoint(0.3, 0.2, "sliding", "grid", 7, 1.0, "k1"),
              fm.MapPoint(0.6, 0.3, "rocking", "grid", 7, 1.0, "k2")]
    th = fm.threshold_bracket([p.mu for p in points], [p.mode for p in points])
    s = fm.SpecimenMap("Sh06-Sd015", get_specimen("Sh06-Sd015").arch, "glued", 1.0, points, th, a)
    return fm.MapResult(Path("m.h5"), "glued", 1.0, [0.3, 0.6], [s], 2, 0, 20.0, [1.0, 1.0], 0)


def test_one_search_parameterised_by_the_solver(monkeypatch):
    # a stand-in solver without dilatancy that reaches lam_ns at mu = 0.7: the search must use it
    # (the LP's own mu* of this arch is about 0.36) and start no lower than the LP's bracket
    import analytic.limit.non_associative as na

    from analytic.limit.limit_discrete import solve_lp
    from specimens.blocks import discretise

    asm = discretise(get_specimen("Sh06-Sd015").arch, config="glued")
    lam_ns = solve_lp(asm, math.inf, 1.0).lam
    calls = []

    def fake(assembly, mu_joint, mu_base):
        calls.append(mu_joint)
        return SimpleNamespace(lam=lam_ns * min(1.0, mu_joint / 0.7))

    monkeypatch.setattr(na, "solve_non_associative", fake)
    ms_lp = fm.lp_mu_star(asm, 1.0, lam_ns)
    assert not calls and 0.3 < ms_lp < 0.4
    ms = fm.lp_mu_star(asm, 1.0, lam_ns, associative=False)
    assert 0.7 - 1e-9 <= ms <= 0.7 + fm.LP_MU_TOL and calls and min(calls) >= ms_lp - fm.LP_MU_TOL
    # short at mu_max: none
    monkeypatch.setattr(na, "solve_non_associative", lambda a, m, b: SimpleNamespace(lam=0.5 * lam_ns))
    assert fm.lp_mu_star(asm, 1.0, lam_ns, associative=False) is None


@pytest.mark.slow  # mu* without dilatancy and four more mixed-integer programs: about 5 s
def test_non_associative_mu_star_on_a_specimen():
    from analytic.limit.limit_discrete import solve_lp
    from analytic.limit.non_associative import solve_non_associative
    from specimens.blocks import discretise

    arch = get_specimen(SID).arch
    a = fm.analytic_curves(arch, "glued", 1.0, [0.3, 0.6], mus_na=[0.3, 0.6])
    asm = discretise(arch, config="glued")
    lam_ns, ms, thr = a.lam_no_sliding, a.mu_star_na, (1 - fm.LP_REL_TOL) * a.lam_no_sliding
    # its multiplier is at most the associative LP's: its mu* is not below the LP's
    assert ms is not None and ms >= a.mu_star_lp - fm.LP_MU_TOL
    # at mu* (and a margin) the multiplier without dilatancy is the no-sliding one; below it, it is short
    above = solve_non_associative(asm, ms + 2 * fm.LP_MU_TOL, 1.0).lam
    below = solve_non_associative(asm, ms - 2 * fm.LP_MU_TOL, 1.0).lam
    assert abs(above - lam_ns) <= fm.LP_REL_TOL * lam_ns and below < thr
    # the curve on its own grid, at most the LP's
    assert list(a.mu_na) == [0.3, 0.6] and np.all(a.lam_na <= a.lam_lp * (1 + 1e-9))
    assert a.lam_na[0] < thr <= a.lam_na[1] and a.seconds_na > 0
    assert solve_lp(asm, ms - 2 * fm.LP_MU_TOL, 1.0).lam >= below * (1 - 1e-9)


def test_json_rows_and_table_carry_mu_star_na(tmp_path, capsys, monkeypatch):
    r = _result()
    assert r.to_json()[0]["mu_star_na"] == 0.42 and r.to_rows("summary")[0]["mu_star_na"] == 0.42
    assert _result(None).to_json()[0]["mu_star_na"] is None
    assert "mu_star_na" in fm.definitions()
    from dem.cli import main

    @functools.wraps(fm.catalogue_map)  # the command reads its defaults from the signature
    def fake(*a, **kw):
        return r

    monkeypatch.setattr(fm, "catalogue_map", fake)  # the command runs its spec through it
    monkeypatch.setattr(map_cmd, "catalogue_map", fake)
    assert main(["map", "--specimens", "Sh06-Sd015", "--mu", "0.3,0.6", "--out", str(tmp_path / "m.h5")]) == 0
    head, row = capsys.readouterr().out.splitlines()[1:3]
    assert head.split()[5:7] == ["mu*LP", "mu*NA"]
    # after the DEM's bracket: mu*LP, then mu*NA
    assert re.search(r"\]\s+0\.380\s+0\.420\s+0\.500\s", row), row


def test_figures_show_the_threshold_without_dilatancy(tmp_path):
    from matplotlib.figure import Figure

    r = _result()
    ax = plot_lambda_mu(r.specimens[0], ax=Figure().subplots())
    labels = ax.get_legend_handles_labels()[1]
    assert "mu* LP, no dilatancy" in labels and "LP, no dilatancy" in labels
    (line,) = [ln for ln in ax.get_lines() if ln.get_label() == "mu* LP, no dilatancy"]
    assert line.get_xdata()[0] == 0.42
    # none computed: no curve, no line
    labels = plot_lambda_mu(_result(None).specimens[0], ax=Figure().subplots()).get_legend_handles_labels()[1]
    assert "mu* LP, no dilatancy" not in labels
    assert len(save_map_figures(r, tmp_path)) == 3


def test_findings_compare_the_dem_with_the_threshold_without_dilatancy():
    rows = [{"id": "a", "mu_star_dem": 0.5, "mu_star_lp": 0.36, "mu_star_na": 0.36, "seconds_na": 10.0},
            {"id": "b", "mu_star_dem": 0.25, "mu_star_lp": 0.40, "mu_star_na": 0.45, "seconds_na": 10.0},
            {"id": "c", "mu_star_dem": None, "mu_star_lp": 0.30, "mu_star_na": None, "seconds_na": 0.0}]
    dem, lp, cost = non_associative_findings(rows, 40.0, quick=True)
    assert "below the DEM mu* for 1 of 2 specimens" in dem and "no dilatancy -0.03" in dem and "b 0.25 / 0.45" in dem
    assert "for 1 of 2 specimens; it is above it by up to 0.050 for the others." in lp
    assert cost.endswith("took 20 s of the step's 40 s (50%; 7 s a specimen): a large share of this quick run.")
    assert non_associative_findings(rows, 400.0)[-1].endswith("(5%; 7 s a specimen).")
    assert non_associative_findings([{**rows[2]}], 40.0) == []
