"""The quick campaign run end to end on three specimens, its simulations replaced by stand-ins
with known answers: every step's table holds those answers beside the analytic columns, every
findings sentence agrees with the tables, ``campaign.h5`` holds the CSV tables, a second run
keeps every step and changes no file, and a run with other parameters is refused."""
from __future__ import annotations

import csv
import html
import json
import math
import re
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
from analytic.motions.inputs import SinePulse
from dem.campaign.runner import STEPS, default_steps, run_campaign
from dem.common.campaign import CampaignContext
from dem.core.settings import DYNAMICS_ENGINE
from dem.experiments.friction_map.step_map import map_plan
from dem.experiments.record.step_record import record_plan
from dem.experiments.shake.step_shake import shake_plan
from dem.experiments.tilt.check import reference_lp
from specimens.blocks import discretise
from specimens.catalogue import catalogue_rows, select_specimens
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT, G
from foundation.errors import ArchdemInputError

pytestmark = pytest.mark.slow  # every test here simulates, spawns processes or runs a campaign

SPECIMENS = "Sh02-Sd015,Sh02-Sd020,Sh1-Sd025"  # two of one sharpness, both quick-map ends, the shake specimen
# the stand-ins' truths
TILT_FACTOR = 1.02  # tilt lambda = 1.02 x the LP at the same frictions
TILT_SLIDING = ("Sh1-Sd025",)  # collapses sliding; the others rock
MAP_MU_STAR = {"Sh02-Sd015": 0.7, "Sh1-Sd025": 1.5}  # 1.5: above the quick grid, still sliding at its top
MAP_LAM_ROCK = 0.4  # map tilt lambda when rocking; lam_rock x mu / mu* when sliding
# shake: collapse from factor x four-bar threshold, except in a survival window (x that threshold)
SHAKE_TRUTH = {2.0: (1.1, (1.4, 2.0), "rocking", "after-first-rebound"),
               6.0: (0.7, None, "mixed", "before-first-rebound")}
RECORD_FACTOR = 1.5  # the record collapses the arch from 1.5 x its static lambda (PGA)
SHAKE_TOL, RECORD_TOL = 0.02, 0.02  # the quick campaign's bisection tolerances
SCAN_RATIO = 1.15  # largest ratio of neighbouring shake scan amplitudes (dem_failure_domain's default)


# ----------------------------------------------------------------------------- stand-ins
def _everywhere(mp: pytest.MonkeyPatch, module, name: str, value) -> None:
    """Patch ``module.name`` and every project module that imported that object by name."""
    old = getattr(module, name)
    for m in list(sys.modules.values()):
        if m is not module and getattr(m, "__name__", "").startswith(("dem.", "analytic.", "specimens.")) \
                and getattr(m, name, None) is old:
            mp.setattr(m, name, value)
    mp.setattr(module, name, value)


class StandIns:
    """Monkeypatches of the seams the steps simulate through, and what they were asked."""

    def __init__(self, mp: pytest.MonkeyPatch, specimens: list, ctx: CampaignContext):
        import analytic.limit.figures as figures_limit
        import dem.experiments.friction_map.run as friction_map
        import dem.experiments.shake.domain as domain
        import dem.experiments.shake.run as shake
        import dem.experiments.shake.thresholds as thresholds
        import dem.experiments.tilt.case as cases
        import specimens.catalogue as catalogue

        self.runs: list[tuple[str, str, float, float, object]] = []  # (id, kind, freq, pga [g], settings)
        # the catalogue-wide work (the catalogue table, the analytic step's series and figures) on
        # the selected specimens only, and no full-scale figures
        _everywhere(mp, catalogue, "CATALOGUE", tuple(specimens))
        real_figs = figures_limit.catalogue_figures
        _everywhere(mp, figures_limit, "catalogue_figures", lambda out, full_scale=True, rows=None: real_figs(out, False, rows))
        # tilt step: the closed-form case function, told each test's lambda and mode
        real_make = cases.make_case

        def tilt_make_case(label, arch, config, mu_joint, mu_base, *a, **kw):
            c = real_make(label, arch, config, mu_joint, mu_base, *a, **kw)
            lam = TILT_FACTOR * reference_lp(discretise(arch, config=config), mu_joint, mu_base).lam
            # synthetic_case slides below mu* with lambda = lam_rock x mu / mu*
            c["synthetic"] = ({"mu_star": 2 * mu_joint, "lam_rock": 2 * lam} if label in TILT_SLIDING
                              else {"mu_star": mu_joint / 2, "lam_rock": lam})
            return c

        _everywhere(mp, cases, "DEM_CASE", cases.SYNTHETIC_CASE)
        _everywhere(mp, cases, "make_case", tilt_make_case)
        # the collapse figures replay a short real simulation (0.05 s) at the stand-in's lambda
        real_replay = cases.replay_tilt

        def short_replay(case, results):
            lam = float(results["lambda"])
            proto = {**case["protocol"], "ramp_time": 0.02, "hold_time": 0.03, "rest_after": None}
            return real_replay({**case, "protocol": proto},
                               {**results, "bracket": [lam / 1.005, lam], "levels": [[lam / 1.005, 0.0], [lam, 1.0]]})

        _everywhere(mp, cases, "replay_tilt", short_replay)
        # map step: the same case function, each specimen with its own mu*
        real_map = friction_map.catalogue_map

        def map_make_case(label, arch, config, mu_joint, mu_base, *a, **kw):
            c = real_make(label, arch, config, mu_joint, mu_base, *a, **kw)
            c["synthetic"] = {"mu_star": MAP_MU_STAR[label], "lam_rock": MAP_LAM_ROCK}
            return c

        mp.setattr(friction_map, "make_case", map_make_case)  # the map's own, not the tilt step's
        _everywhere(mp, friction_map, "catalogue_map", lambda *a, **kw: real_map(*a, **{**kw, "func": cases.SYNTHETIC_CASE}))
        # shake step: the real four-bar domain, computed once here for the stand-in's truth
        (spec,), freqs = shake_plan(ctx)
        self.shake_id, self.freqs = spec.id, tuple(freqs)
        self.analytic = domain.analytic_domains(spec.arch, freqs, workers=1)
        pts = self.analytic["four-bar"].points()
        self.four_bar = {x: min(p["amplitude_g"] for p in pts if p["x"] == x) for x in {p["x"] for p in pts}}
        assert sorted(self.four_bar) == sorted(freqs) == sorted(SHAKE_TRUTH)

        def known_domains(arch, fs, **kw):
            assert arch == spec.arch and tuple(fs) == self.freqs
            return self.analytic

        _everywhere(mp, domain, "analytic_domains", known_domains)
        self.record_id = record_plan(ctx)[0].id
        self.lam_static = {s.id: solve_lp(discretise(s.arch, config="glued"), REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam
                           for s in specimens}

        def collapses(model, motion, settings, protocol):
            a = motion.pga / G
            if isinstance(motion, SinePulse):
                self.runs.append((model.name, "sine", motion.f, a, settings))
                factor, window, mode, phase = SHAKE_TRUTH[motion.f]
                t = factor * self.four_bar[motion.f]
                hit = a >= t and not (window and window[0] * t <= a < window[1] * t)
                return hit, (mode if hit else "none"), (phase if hit else None)
            self.runs.append((model.name, "record", math.nan, a, settings))
            hit = a >= RECORD_FACTOR * self.lam_static[model.name]
            return hit, ("rocking" if hit else "none"), ("after-first-rebound" if hit else None)

        mp.setattr(thresholds, "collapses", collapses)

        def checked(args):  # the thresholds' checks (settled or a range): the same truth, not counted in runs
            name, model, st, protocol, motion_fn, a, f = args
            factor, window, mode, _ = SHAKE_TRUTH[f]
            t = factor * self.four_bar[f]
            hit = a >= t and not (window and window[0] * t <= a < window[1] * t)
            return thresholds.Reading(name, st.engine, st.dt, a, hit, mode if hit else "none")

        mp.setattr(thresholds, "_read_one", checked)
        # the time histories beside the shake thresholds: short real runs (0.05 s)
        real_shake = shake.shake
        _everywhere(mp, shake, "shake", lambda model, motion, settings=None, protocol=None, **kw:
                   real_shake(model, motion, settings, shake.ShakeProtocol(duration=0.05), **kw))


# ----------------------------------------------------------------------------- the campaign
@pytest.fixture(scope="module")
def campaign(tmp_path_factory):
    specimens = select_specimens(SPECIMENS)
    out = tmp_path_factory.mktemp("campaign")
    log: list[str] = []
    ctx = CampaignContext(out=out, specimens=specimens, quick=True, workers=1, log=log.append)
    with pytest.MonkeyPatch.context() as mp:
        stand = StandIns(mp, specimens, ctx)
        manifest = run_campaign(ctx)
        yield {"out": out, "specimens": specimens, "manifest": manifest, "log": log, "stand": stand}


def _rows(out: Path, name: str, table: str | None = None) -> list[dict]:
    """The rows of step ``name``'s table ``table`` (default the step's own, ``name/name.csv``)."""
    with open(out / name / f"{table or name}.csv", newline="") as fh:
        return list(csv.DictReader(fh))


def _f(v: str) -> float:
    return float(v) if v != "" else math.nan


def _findings(campaign, step: str) -> list[str]:
    found = campaign["manifest"]["steps"][step]["outputs"]["findings"]
    assert found, f"step {step} wrote no findings"
    return found


def _quotes(text: str, value: float, decimals: int) -> bool:
    """``text`` is ``value`` written with ``decimals`` decimals (half a unit of the last digit)."""
    return abs(float(text) - value) <= 0.5 * 10 ** -decimals + 1e-12


def _match_all(sentences: list[str], patterns: dict[str, str]) -> dict[str, re.Match]:
    """Each sentence matched by exactly one pattern (by name); no sentence left unchecked."""
    got = {}
    for s in sentences:
        hits = [(k, m) for k, p in patterns.items() if (m := re.fullmatch(p, s))]
        assert len(hits) == 1 and hits[0][0] not in got, f"sentence not recognised, or twice: {s!r}"
        got[hits[0][0]] = hits[0][1]
    return got


def test_every_step_runs_once_in_order(campaign):
    log = campaign["log"]
    assert [ln.split("]")[0][1:] for ln in log if ln.endswith("...")] == default_steps()
    assert list(campaign["manifest"]["steps"]) == default_steps()
    for name in default_steps():
        assert (campaign["out"] / name).is_dir() and not (campaign["out"] / f".{name}.part").exists()


# ----------------------------------------------------------------------------- catalogue
def test_catalogue_table_and_heaviest_specimen(campaign):
    rows = _rows(campaign["out"], "catalogue")
    want = [r for r in catalogue_rows() if r["id"] in SPECIMENS.split(",")]
    assert [r["id"] for r in rows] == [r["id"] for r in want] == SPECIMENS.split(",")
    for got, w in zip(rows, want):
        assert float(got["mass"]) == w["mass"] and float(got["Sd"]) == w["Sd"]
    (m,) = _match_all(_findings(campaign, "catalogue"),
                      {"heaviest": r"The heaviest specimen is (\S+) \(([\d.]+) kg glued assembly\)\."}).values()
    heaviest = max(rows, key=lambda r: float(r["mass"]))
    assert m.group(1) == heaviest["id"] and _quotes(m.group(2), float(heaviest["mass"]), 2)


# ----------------------------------------------------------------------------- analytic
def test_analytic_table_matches_the_limit_analysis_called_directly(campaign):
    from analytic.limit.two_bar import lambda_two_bar

    from analytic.limit.non_associative import solve_non_associative

    rows = {r["id"]: r for r in _rows(campaign["out"], "analytic")}
    assert list(rows) == SPECIMENS.split(",")
    cols = list(next(iter(rows.values())))
    i = cols.index("lambda_lp_reference_friction")
    assert cols[i + 1:i + 3] == ["lambda_non_associative", "non_associative_below_lp_pct"]
    for s in campaign["specimens"]:
        r, glued = rows[s.id], discretise(s.arch, config="glued")
        assert float(r["lambda_lp_reference_friction"]) == pytest.approx(
            solve_lp(glued, REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam, rel=1e-9)
        assert float(r["lambda_discrete_glued"]) == pytest.approx(enumerate_mechanisms(glued).lam, rel=1e-9)
        assert float(r["lambda_discrete_free"]) == pytest.approx(
            enumerate_mechanisms(discretise(s.arch, config="free")).lam, rel=1e-9)
        assert float(r["lambda_two_bar"]) == pytest.approx(lambda_two_bar(s.arch), rel=1e-9)
        # without dilatancy: beside the LP, at most it, and the library's on the same blocks
        lp, na = float(r["lambda_lp_reference_friction"]), float(r["lambda_non_associative"])
        assert 0 < na <= lp * (1 + 1e-9)
        assert na == pytest.approx(solve_non_associative(glued, REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam, rel=1e-9)
        assert float(r["non_associative_below_lp_pct"]) == pytest.approx(100 * (1 - na / lp), rel=1e-9, abs=1e-9)
        # a thinner ring is weaker
        assert 0 < float(r["lambda_continuous_80pct"]) < float(r["lambda_continuous"])


def test_analytic_findings_agree_with_the_table(campaign):
    rows = _rows(campaign["out"], "analytic")
    lc = np.array([_f(r["lambda_continuous"]) for r in rows])
    ld = np.array([_f(r["lambda_discrete_glued"]) for r in rows])
    n = len(rows)
    m = _match_all(_findings(campaign, "analytic"), {
        "gap": r"Continuous-profile lambda is below the discrete one for (\d+) of (\d+) specimens; "
               r"the largest gap is ([-\d.]+) % \((\S+)\)\.",
        "sd": r"lambda grows with slenderness Sd at fixed sharpness for Sh = (.+) \(of (.+)\)\.",
        "base": r"The discrete mechanism has a hinge at a springing \(base joint\) in (\d+) of (\d+) specimens\.",
        "thin": r"An 80 % effective thickness lowers the continuous lambda by (\d+)-(\d+) %\.",
        "lp": r"At the reference friction \(([\d.]+)/([\d.]+)\) the associative LP has sliding joints in "
              r"(\d+) specimens(?:: (.+))?\.",
        "na": r"Without dilatancy \(Coulomb friction, non-associative\) the collapse multiplier (?:is ([\d.]+)–([\d.]+) % "
              r"below the associative LP \(largest: (\S+)\)|equals the associative LP \(to 0\.005 %\) for (\d+) of (\d+) "
              r"specimens); mixed-integer program proven optimal for (\d+) of (\d+) specimens, ([\d.]+) s per specimen "
              r"\(at most ([\d.]+) s\)\.",
    })
    assert set(m) == {"gap", "sd", "base", "thin", "lp", "na"}
    gap = 100 * (ld - lc) / ld
    assert (int(m["gap"][1]), int(m["gap"][2])) == (int(np.sum(lc <= ld)), n)
    assert _quotes(m["gap"][3], gap.max(), 1) and m["gap"][4] == rows[int(gap.argmax())]["id"]
    # lambda by Sd at each sharpness held by more than one specimen
    by_sh: dict[float, list] = {}
    for r in rows:
        by_sh.setdefault(float(r["Sh"]), []).append((float(r["Sd"]), float(r["lambda_continuous"])))
    grows = [sh for sh, v in by_sh.items() if len(v) > 1 and all(b[1] > a[1] for a, b in zip(sorted(v), sorted(v)[1:]))]
    assert m["sd"][1] == (", ".join(f"{x:g}" for x in sorted(grows)) or "none")
    assert m["sd"][2] == ", ".join(f"{x:g}" for x in sorted(by_sh))
    base = sum(any(h.split(":")[0] in ("L0", "R0") for h in r["hinges_discrete"].split()) for r in rows)
    assert (int(m["base"][1]), int(m["base"][2])) == (base, n)
    drop = 100 * (lc - np.array([_f(r["lambda_continuous_80pct"]) for r in rows])) / lc
    assert _quotes(m["thin"][1], drop.min(), 0)
    assert _quotes(m["thin"][2], drop.max(), 0)
    sliding = [r["id"] for r in rows if r["lp_sliding_joints"]]
    assert (float(m["lp"][1]), float(m["lp"][2])) == (REFERENCE_MU_JOINT, REFERENCE_MU_BASE)
    assert int(m["lp"][3]) == len(sliding) and (m["lp"][4] or "") == ", ".join(sliding)
    below = np.array([_f(r["non_associative_below_lp_pct"]) for r in rows])
    if m["na"][1] is not None:  # a range, its largest named
        assert _quotes(m["na"][1], below.min(), 2) and _quotes(m["na"][2], below.max(), 2)
        assert m["na"][3] == rows[int(below.argmax())]["id"]
    else:  # all equal to the LP to the digits quoted
        assert np.all(np.abs(below) < 0.005) and (int(m["na"][4]), int(m["na"][5])) == (n, n)
    assert (int(m["na"][6]), int(m["na"][7])) == (n, n)  # each of these three proven optimal
    assert 0 <= float(m["na"][8]) <= float(m["na"][9]) < 60  # the cost is stated, under the time limit


def test_analytic_non_associative_finding_names_the_range_the_largest_and_what_is_unproven():
    from dem.campaign.step_analytic import _non_associative_finding

    rows = [{"id": "A", "non_associative_below_lp_pct": -1e-12}, {"id": "B", "non_associative_below_lp_pct": 2.1349},
            {"id": "C", "non_associative_below_lp_pct": math.nan}]
    cost = {"A": (True, 1.0), "B": (False, 3.0), "C": (False, 0.2)}
    assert _non_associative_finding(rows, cost) == (
        "Without dilatancy (Coulomb friction, non-associative) the collapse multiplier is 0.00–2.13 % below the "
        "associative LP (largest: B), none for C; mixed-integer program proven optimal for 1 of 3 specimens "
        "(not proven, their multiplier an upper bound: B), 1.4 s per specimen (at most 3.0 s).")
    same = [{"id": k, "non_associative_below_lp_pct": v} for k, v in (("A", 0.0), ("B", 0.004))]
    assert "equals the associative LP (to 0.005 %) for 2 of 2 specimens; mixed-integer program proven optimal for 2 of 2" \
        in _non_associative_finding(same, {"A": (True, 1.0), "B": (True, 1.0)})


# ----------------------------------------------------------------------------- tilt
def test_tilt_table_holds_the_stand_in_lambdas_against_the_lp(campaign):
    rows = _rows(campaign["out"], "tilt")
    analytic = {r["id"]: r for r in _rows(campaign["out"], "analytic")}
    assert [r["id"] for r in rows] == SPECIMENS.split(",")
    assert "lambda_dem_no_sliding" not in rows[0]  # the no-sliding tilts belong to the full campaign
    for s, r in zip(campaign["specimens"], rows):
        asm = discretise(s.arch, config="glued")
        lp = solve_lp(asm, REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam
        assert float(r["lambda_lp_reference"]) == pytest.approx(lp, rel=1e-12)
        assert float(r["lambda_lp_reference"]) == float(analytic[s.id]["lambda_lp_reference_friction"])
        assert float(r["lambda_lp_no_sliding"]) == pytest.approx(solve_lp(asm, math.inf, math.inf).lam, rel=1e-12)
        assert float(r["lambda_dem_reference"]) == pytest.approx(TILT_FACTOR * lp, rel=1e-12)
        assert r["mode_reference"] == ("sliding" if s.id in TILT_SLIDING else "rocking")
        assert int(r["n_sims_reference"]) == 1 and r["joints_reference"] == ""
        lam, lam_lp = float(r["lambda_dem_reference"]), float(r["lambda_lp_reference"])
        assert float(r["err_reference_vs_lp_pct"]) == pytest.approx(100 * (lam - lam_lp) / lam_lp, rel=1e-12)
        assert float(r["err_reference_vs_lp_pct"]) == pytest.approx(100 * (TILT_FACTOR - 1), rel=1e-9)


def test_tilt_findings_agree_with_the_table(campaign):
    rows = _rows(campaign["out"], "tilt")
    m = _match_all(_findings(campaign, "tilt"), {
        "slide": r"At the reference friction \(([\d.]+)/([\d.]+)\) (\d+) of (\d+) specimens collapse with sliding "
                 r"joints(?:: (.+))?\.",
        "err": r"At the reference friction the DEM lambda is ([-+][\d.]+) % to ([-+][\d.]+) % from the associative LP "
               r"\(which is no bound for Coulomb friction\)\.",
        "check": r"(?:Every tilt is within 3 % of the LP of its own blocks\.|(\d+) of (\d+) tilts depart from the LP of "
                 r"their own blocks by more than 3 %: (.+))",
    })
    assert set(m) == {"slide", "err", "check"}
    # every tilt's own check (docs/physics/dem.md#76-every-tilt-beside-its-own-lp): the table's departures, named
    off = [r["id"] for r in rows if abs(float(r["err_reference_vs_lp_pct"])) > 3]
    if off:
        assert (int(m["check"][1]), int(m["check"][2])) == (len(off), len(rows))
        assert all(f"{i}: tilt lambda" in m["check"][3] and "likely cause" in m["check"][3] for i in off)
    else:
        assert m["check"][1] is None
    sliding = [r["id"] for r in rows if r["mode_reference"] in ("sliding", "mixed")]
    assert sliding == list(TILT_SLIDING)
    assert (int(m["slide"][3]), int(m["slide"][4]), m["slide"][5]) == (len(sliding), len(rows), ", ".join(sliding))
    err = [float(r["err_reference_vs_lp_pct"]) for r in rows]
    assert _quotes(m["err"][1], min(err), 1)
    assert _quotes(m["err"][2], max(err), 1)


def test_tilt_collapse_figures_of_the_first_rocking_and_first_sliding_specimen(campaign):
    figs = [f["path"] for f in campaign["manifest"]["steps"]["tilt"]["outputs"]["figures"]]
    assert figs[1:] == ["tilt/collapse_Sh02-Sd015.png", "tilt/collapse_Sh1-Sd025.png"]
    assert all((campaign["out"] / p).stat().st_size > 0 for p in figs)


# ----------------------------------------------------------------------------- map
# ----------------------------------------------------------------------------- lab
def test_lab_table_holds_the_laboratory_the_calibration_and_the_stand_in(campaign):
    from analytic.limit.calibration import LAB_TILT_TESTS, load_calibration, lp_lambda, read_experiments

    rows = {r["id"]: r for r in _rows(campaign["out"], "lab")}
    tilt = {r["id"]: r for r in _rows(campaign["out"], "tilt")}
    lab = {t.id: t for t in read_experiments(LAB_TILT_TESTS)}
    cal = load_calibration()
    # the tested specimens first (Sh02-Sd020, Sh1-Sd025), then the prediction
    assert list(rows) == ["Sh02-Sd020", "Sh1-Sd025", "Sh02-Sd015"]
    for s in campaign["specimens"]:
        r, t = rows[s.id], lab.get(s.id)
        assert r["kind"] == ("laboratory" if t else "prediction")
        c = 1 - 2 * cal.edge_loss / s.arch.t
        assert float(r["contact"]) == pytest.approx(c, rel=1e-12)
        assert float(r["lambda_lp_ideal"]) == pytest.approx(lp_lambda(s.arch, 1.0), rel=1e-12)
        assert float(r["lambda_lp_effective"]) == pytest.approx(lp_lambda(s.arch, c), rel=1e-12)
        assert float(r["lambda_dem_ideal"]) == float(tilt[s.id]["lambda_dem_reference"])
        # the stand-in tilt ignores the joints: every realisation gives its lambda
        want = TILT_FACTOR * reference_lp(discretise(s.arch, config="glued"), REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam
        assert float(r["lambda_dem_effective_mean"]) == pytest.approx(want, rel=1e-12)
        assert int(r["n_realisations"]) == (3 if t else 1)
        assert r["mode_dem"] == ("sliding" if s.id in TILT_SLIDING else "rocking")
        if t:
            assert (float(r["lambda_lab_mean"]), float(r["lambda_lab_sd"]), r["mode_lab"]) == (t.lambda_mean, t.lambda_sd, t.mode)
            # equal lambdas: their sample sd is 0 up to the rounding of their mean (one ulp of lambda)
            assert float(r["lambda_dem_effective_sd"]) == pytest.approx(0.0, abs=4 * math.ulp(want))
            assert r["within_2sd_or_15pct"] == str(abs(want - t.lambda_mean) <= max(2 * t.lambda_sd, 0.15 * t.lambda_mean))
            assert r["mode_agrees"] == str(r["mode_dem"] == t.mode)
            assert float(r["err_dem_vs_lab_pct"]) == pytest.approx(100 * (want / t.lambda_mean - 1), rel=1e-9)


def test_lab_findings_agree_with_the_table(campaign):
    from analytic.limit.calibration import load_calibration

    rows = [r for r in _rows(campaign["out"], "lab") if r["kind"] == "laboratory"]
    cal = load_calibration()
    m = _match_all(_findings(campaign, "lab"), {
        "cal": r"Calibrated imperfect fit: ([\d.]+) mm of contact lost at each joint edge \(scatter ([\d.]+) mm\); "
               r"leave-one-out RMS error of the LP ([\d.]+) % against ([\d.]+) % for one contact fraction for all specimens\.",
        "ideal": r"Ideal contact overestimates the laboratory lambda by ([-+\d]+) % to ([-+\d]+) % \(LP\)\.",
        "dem": r"With the calibrated joints the DEM tilt lambda lies within max\(2 sd, 15 %\) of the laboratory mean for "
               r"(\d+) of (\d+) specimens and reproduces the observed mode for (\d+) of (\d+)\.",
    })
    assert set(m) == {"cal", "ideal", "dem"}
    assert _quotes(m["cal"][1], cal.edge_loss * 1e3, 2) and _quotes(m["cal"][3], cal.loo_rms_pct, 1)
    e = [_f(r["err_ideal_lp_vs_lab_pct"]) for r in rows]
    assert _quotes(m["ideal"][1], min(e), 0) and _quotes(m["ideal"][2], max(e), 0)
    assert int(m["dem"][1]) == sum(r["within_2sd_or_15pct"] == "True" for r in rows) and int(m["dem"][2]) == len(rows)
    assert int(m["dem"][3]) == sum(r["mode_agrees"] == "True" for r in rows)


def test_map_tables_hold_the_stand_in_thresholds(campaign):
    out = campaign["out"]
    rows = {r["id"]: r for r in _rows(out, "map")}
    ctx = CampaignContext(out=out, specimens=campaign["specimens"], quick=True)
    specs, grid, rounds = map_plan(ctx)
    assert list(rows) == [s.id for s in specs] == list(MAP_MU_STAR)
    grid = [float(x) for x in grid.split(",")]
    with open(out / "map" / "map_points.csv", newline="") as fh:
        points = list(csv.DictReader(fh))
    analytic = {r["id"]: r for r in _rows(out, "analytic")}
    for s in specs:
        r, ms = rows[s.id], MAP_MU_STAR[s.id]
        pts = [p for p in points if p["id"] == s.id]
        assert pts and int(r["n_tilts"]) == len(pts) and int(r["n_failed"]) == 0
        for p in pts:  # each point is the stand-in's answer at its friction
            mu = float(p["mu"])
            assert p["mode"] == ("rocking" if mu >= ms else "sliding")
            assert float(p["lambda"]) == pytest.approx(MAP_LAM_ROCK * min(1.0, mu / ms), rel=1e-12)
        assert sorted(float(p["mu"]) for p in pts if p["kind"] == "grid") == grid
        # the analytic columns are those of the analytic step / the LP called directly
        asm = discretise(s.arch, config="glued")
        assert float(r["lambda_no_sliding"]) == pytest.approx(solve_lp(asm, math.inf, REFERENCE_MU_BASE).lam, rel=1e-9)
        assert float(r["lambda_kinematic"]) == float(analytic[s.id]["lambda_discrete_glued"])
        assert float(r["lambda_continuous"]) == pytest.approx(float(analytic[s.id]["lambda_continuous"]), rel=1e-9)
        if ms > max(grid):
            assert r["dem_status"] == "all_sliding" and r["mu_star_dem"] == "" and len(pts) == len(grid)
            continue
        lo, hi = float(r["mu_star_dem_lo"]), float(r["mu_star_dem_hi"])
        assert r["dem_status"] == "bracketed" and lo < ms <= hi
        assert float(r["mu_star_dem"]) == pytest.approx((lo + hi) / 2, rel=1e-12)
        # one bisection of the grid interval per refinement round
        assert hi - lo == pytest.approx((grid[1] - grid[0]) / 2 ** rounds, abs=1e-9)
        assert len(pts) == len(grid) + rounds


def test_map_findings_agree_with_the_table(campaign):
    rows = _rows(campaign["out"], "map")
    m = _match_all(_findings(campaign, "map"), {
        "bracketed": r"The DEM rocking/sliding threshold mu\* is bracketed for (\d+) of (\d+) specimens: (.+)\.",
        "two_bar": r"The two-bar model's mu\* is below the DEM mu\* for (\d+) of (\d+) bracketed specimens "
                   r"\(mean difference DEM - two-bar ([-+][\d.]+)\)\.",
        "sd": r"Sh = ([\d.]+): DEM mu\* (grows|does not grow monotonically) with Sd \((.+)\)\.",
        "all_rocking": r"Rocking already at the lowest friction of the grid: (.+)\.",
        "all_sliding": r"Still sliding at the highest friction of the grid: (.+)\.",
        "na_dem": r"The non-associative mu\* \(limit analysis without dilatancy\) is below the DEM mu\* for (\d+) of (\d+) "
                  r"specimens where both exist \(mean difference DEM - no dilatancy ([-+][\d.]+); DEM / no dilatancy: (.+)\)\.",
        "na_lp": r"Without dilatancy mu\* equals the associative LP's \(to the bisection tolerance ([\d.e-]+)\) for (\d+) of "
                 r"(\d+) specimens(?:; it is above it by up to ([\d.]+) for the others)?\.",
        "na_cost": r"The references without dilatancy \(mu\* and lambda on the grid\) took (\d+) s of the step's (\d+) s "
                   r"\((\d+)%; (\d+) s a specimen\)(: a large share of this quick run)?\.",
    })
    br = [r for r in rows if r["dem_status"] == "bracketed"]
    assert br and set(m) == {"bracketed", "two_bar", "all_sliding", "na_dem", "na_lp", "na_cost"}  # one bracketed: no Sd trend
    both = [r for r in rows if r["mu_star_dem"] != "" and r["mu_star_na"] != ""]
    d_na = [float(r["mu_star_dem"]) - float(r["mu_star_na"]) for r in both]
    assert (int(m["na_dem"][1]), int(m["na_dem"][2])) == (sum(d > 0 for d in d_na), len(both))
    assert _quotes(m["na_dem"][3], np.mean(d_na), 2)
    assert int(m["na_lp"][3]) == sum(r["mu_star_na"] != "" for r in rows) or int(m["na_lp"][3]) == len(rows)
    assert (int(m["bracketed"][1]), int(m["bracketed"][2])) == (len(br), len(rows))
    quoted = [v.rsplit(" ", 1) for v in m["bracketed"][3].split(", ")]
    assert [q[0] for q in quoted] == [r["id"] for r in br]
    for (_, v), r in zip(quoted, br):
        assert _quotes(v, float(r["mu_star_dem"]), 2)
    diffs = [float(r["mu_star_dem"]) - float(r["mu_star_two_bar"]) for r in br if r["mu_star_two_bar"] != ""]
    assert (int(m["two_bar"][1]), int(m["two_bar"][2])) == (sum(d > 0 for d in diffs), len(diffs))
    assert _quotes(m["two_bar"][3], np.mean(diffs), 2)
    assert m["all_sliding"][1] == ", ".join(r["id"] for r in rows if r["dem_status"] == "all_sliding")


# ----------------------------------------------------------------------------- shake
def test_shake_table_holds_the_stand_in_thresholds_against_the_four_bar(campaign):
    stand = campaign["stand"]
    rows = _rows(campaign["out"], "shake")
    assert [(r["id"], float(r["freq_Hz"])) for r in rows] == [(stand.shake_id, f) for f in stand.freqs]
    tb = stand.analytic["two-bar"].points()
    two_bar = {x: min(p["amplitude_g"] for p in tb if p["x"] == x) for x in {p["x"] for p in tb}}
    lam = stand.lam_static[stand.shake_id]
    for r in rows:
        f = float(r["freq_Hz"])
        factor, window, mode, phase = SHAKE_TRUTH[f]
        truth = factor * stand.four_bar[f]
        assert lam < truth < 4 * lam  # inside the quick scan, or the check below would not apply
        a, fb = float(r["a_dem_g"]), float(r["a_four_bar_g"])
        assert fb == stand.four_bar[f] and float(r["a_two_bar_g"]) == two_bar[f]
        assert float(r["lambda_static"]) == pytest.approx(lam, rel=1e-12)
        assert truth <= a <= truth * (1 + SHAKE_TOL)  # the bisection's upper end, within its tolerance
        assert float(r["ratio_dem_to_four_bar"]) == pytest.approx(a / fb, rel=1e-12)
        assert (r["dem_mode"], r["collapse_phase"]) == (mode, phase)
        assert int(r["n_sims"]) == sum(1 for run in stand.runs if run[1] == "sine" and run[2] == f)
        assert r["verdict"] in ("settled", "unchecked")  # every check reads the stand-in's bracket alike
        if window is None:
            assert r["survival_bands_above"] == ""
            continue
        # the window's edges are known to the scan's resolution
        (lo, hi), = [tuple(float(x) for x in b.split("-")) for b in r["survival_bands_above"].split()]
        assert window[0] * truth / SCAN_RATIO <= lo <= window[0] * truth * SCAN_RATIO
        assert window[1] * truth / SCAN_RATIO <= hi <= window[1] * truth * SCAN_RATIO
    for run in stand.runs:  # the runs used the reference friction and the campaign's engine of the shakes
        assert (run[4].mu_joint, run[4].mu_base, run[4].engine) == (REFERENCE_MU_JOINT, REFERENCE_MU_BASE, DYNAMICS_ENGINE)


def test_shake_findings_agree_with_the_table(campaign):
    rows = _rows(campaign["out"], "shake")
    m = _match_all(_findings(campaign, "shake"), {
        "ratio": r"DEM / four-bar collapse amplitude ratio: ([\d.]+)-([\d.]+) over (\d+) \(specimen, frequency\) "
                 r"pairs; the four-bar is conservative \(ratio > 1\) in (\d+) of them\.",
        "windows": r"Survival windows above the first collapse amplitude: (.+)\.",
        "verdicts": r"Thresholds settled: (\d+) of (\d+); a range: (\d+); unchecked: (\d+)(?: \((.+)\))?\. "
                    r"The checks ran (\d+) runs in \d+ s\.",
    })
    assert set(m) == {"ratio", "windows", "verdicts"}
    counts = [int(m["verdicts"][k]) for k in (1, 3, 4)]
    assert int(m["verdicts"][2]) == len(rows) == sum(counts)
    assert counts == [sum(r["verdict"] == k for r in rows) for k in ("settled", "range", "unchecked")]
    assert int(m["verdicts"][6]) == sum(int(r["check_runs"]) for r in rows)
    ratios = [float(r["ratio_dem_to_four_bar"]) for r in rows]
    assert _quotes(m["ratio"][1], min(ratios), 2)
    assert _quotes(m["ratio"][2], max(ratios), 2)
    assert (int(m["ratio"][3]), int(m["ratio"][4])) == (len(rows), sum(x > 1 for x in ratios))
    assert sum(x > 1 for x in ratios) == sum(v[0] > 1 for v in SHAKE_TRUTH.values())
    windows = [f"{r['id']} {float(r['freq_Hz']):g} Hz ({r['survival_bands_above']} g)" for r in rows
               if r["survival_bands_above"]]
    assert len(windows) == 1 and m["windows"][1] == windows[0]


# ----------------------------------------------------------------------------- record
def test_record_table_holds_the_stand_in_collapse_pga(campaign):
    from analytic.motions.records import read_record
    from dem.experiments.record.step_record import RECORD_FILE, _record_path

    stand = campaign["stand"]
    (r,) = _rows(campaign["out"], "record")
    lam = stand.lam_static[stand.record_id]
    assert (r["id"], r["record"]) == (stand.record_id, RECORD_FILE)
    assert float(r["lambda_static"]) == pytest.approx(lam, rel=1e-12)
    assert float(r["pga_record_g"]) == pytest.approx(read_record(_record_path()).pga / G, rel=1e-12)
    a = float(r["collapse_pga_g"])
    assert RECORD_FACTOR * lam <= a <= RECORD_FACTOR * lam * (1 + RECORD_TOL)
    assert float(r["ratio_to_static"]) == pytest.approx(a / lam, rel=1e-12)
    assert float(r["scale_factor"]) == pytest.approx(a / float(r["pga_record_g"]), rel=1e-12)
    assert r["mode"] == "rocking"
    assert int(r["n_sims"]) == sum(1 for run in stand.runs if run[1] == "record")


def test_record_findings_agree_with_the_table(campaign):
    (r,) = _rows(campaign["out"], "record")
    (m,) = _match_all(_findings(campaign, "record"), {
        "pga": r"(\S+): the El Centro 1940 window collapses the arch at PGA ([\d.]+) g "
               r"\(x([\d.]+) the record, ([\d.]+) x the static lambda\)\.",
    }).values()
    assert m[1] == r["id"]
    assert _quotes(m[2], float(r["collapse_pga_g"]), 3)
    assert _quotes(m[3], float(r["scale_factor"]), 2)
    assert _quotes(m[4], float(r["ratio_to_static"]), 2)


# ----------------------------------------------------------------------------- assessment checks
def _half_unit(text: str) -> float:
    """Half a unit in the last written place of the number ``text`` (``1.25e-3``: of its mantissa)."""
    mant, _, exp = text.lower().partition("e")
    places = len(mant.split(".")[1]) if "." in mant else 0
    return 0.5 * 10.0 ** (-places + (int(exp) if exp else 0))


def _assert_index_is_its_pair(rows: list[dict], demand: str, capacity: str, where: str) -> int:
    """Every row: the written safety index is capacity / demand of the two numbers written beside it
    (to their written precision, and at least to 1e-9 when they are written in full), and the
    verdict is index >= 1."""
    for r in rows:
        dem, cap, idx = float(r[demand]), float(r[capacity]), float(r["safety_index"])
        assert dem > 0 and cap >= 0 and math.isfinite(idx), (where, r)
        ratio = cap / dem
        tol = ratio * (_half_unit(r[capacity]) / cap + _half_unit(r[demand]) / dem) + _half_unit(r["safety_index"])
        assert abs(idx - ratio) <= max(tol, 1e-9 * abs(ratio)), (where, r)
        assert r["verdict"] in ("verified", "not verified"), (where, r)
        assert (r["verdict"] == "verified") == (idx >= 1), (where, r)
    return len(rows)


def test_every_index_of_the_assessment_step_is_its_written_pair(campaign):
    """``assess/checks.csv``: for every check of every configuration, with and without strips, the
    index recomputes as capacity / demand from the two values the table writes, and the verdict is
    index >= 1; the table holds every check the step's configurations ran."""
    rows = _rows(campaign["out"], "assess", "checks")
    n = _assert_index_is_its_pair(rows, "demand_value", "capacity_value", "assess/checks.csv")
    configs = {(r["configuration"], r["frp"]) for r in _rows(campaign["out"], "assess")}
    assert {(r["configuration"], r["frp"]) for r in rows} == configs and n >= 3 * len(configs)


def test_every_index_of_the_drawing_step_is_its_written_pair(tmp_path):
    """``drawing/drawing-assessment.csv`` (the optional step, not in the stand-in campaign: run here with
    its DEM tilt replaced by a stand-in, its code checks real): index = capacity / demand, verdict."""
    from types import SimpleNamespace

    from dem.experiments.assessment import step_drawing as sd

    ctx = CampaignContext(out=tmp_path, specimens=[], quick=True, workers=1, log=lambda *_: None)
    d = tmp_path / "drawing"
    d.mkdir()
    stand_in = SimpleNamespace(lam=0.5, mode="rocking", joints=[])
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(sd, "tilt", lambda *a, **kw: stand_in)
        sd.step_drawing(ctx, d)
    with open(d / "drawing-assessment.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert _assert_index_is_its_pair(rows, "demand", "capacity", "drawing/drawing-assessment.csv") == 3
    assert [r["kind"] for r in rows] == ["activation", "linear", "non-linear"]


# ----------------------------------------------------------------------------- report and HDF5
def test_report_lists_every_finding_of_every_step(campaign):
    text = (campaign["out"] / "report.html").read_text(encoding="utf-8")
    n = 0
    for name, rec in campaign["manifest"]["steps"].items():
        for f in rec["outputs"]["findings"]:
            assert f"<li>{html.escape(f'[{name}] {f}')}</li>" in text
            n += 1
    assert n >= len(default_steps())


def test_campaign_h5_holds_the_csv_tables_and_the_manifest(campaign):
    out, manifest = campaign["out"], campaign["manifest"]
    tables = {t["name"]: t["csv"] for rec in manifest["steps"].values() for t in rec["outputs"].get("tables", [])}
    assert set(tables) == {"catalogue", "analytic", "modes", "tilt", "lab", "map", "map_points", "shake", "record", "assess",
                           "assess_checks", "assess_calculation"}
    with h5py.File(out / "campaign.h5", "r") as f:
        assert json.loads(f.attrs["parameters"]) == manifest["parameters"]
        assert json.loads(f.attrs["manifest"])["steps"] == manifest["steps"]
        assert set(f["tables"]) == set(tables)
        for name, path in tables.items():
            with open(out / path, newline="") as fh:
                rows = list(csv.DictReader(fh))
            g = f["tables"][name]
            assert rows and list(g) == sorted(rows[0])  # h5py lists the columns by name
            for col in rows[0]:
                ds = g[col][()]
                if ds.dtype.kind == "f":
                    np.testing.assert_array_equal(ds, [_f(r[col]) for r in rows])
                elif ds.dtype.kind == "i":  # a column of whole numbers stays whole
                    assert ds.tolist() == [int(r[col]) for r in rows]
                elif ds.dtype.kind == "b":
                    assert ds.tolist() == [{"True": True, "False": False}[r[col]] for r in rows]
                else:
                    assert [v.decode() for v in ds] == [r[col] for r in rows]
        # typed, not text: the tables' counts and flags read back as numbers and booleans
        assert f["tables/tilt/n_sims_reference"].dtype.kind == "i" and f["tables/assess/frp"].dtype.kind == "b"
        # a number column stays a number: the tilt lambdas read back exactly
        lam = f["tables/tilt/lambda_dem_reference"][()]
        assert lam.dtype.kind == "f" and lam.tolist() == [float(r["lambda_dem_reference"]) for r in _rows(out, "tilt")]


# ----------------------------------------------------------------------------- resume and refusal
def _snapshot(out: Path) -> dict[str, tuple[bytes, int]]:
    return {str(p.relative_to(out)): (p.read_bytes(), p.stat().st_mtime_ns) for p in sorted(out.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def rerun(campaign):
    """The campaign run a second time on its folder: the files before and after, the log, the manifest."""
    out = campaign["out"]
    before = _snapshot(out)
    log: list[str] = []
    ctx = CampaignContext(out=out, specimens=campaign["specimens"], quick=True, workers=1, log=log.append)
    manifest = run_campaign(ctx)
    return {"before": before, "after": _snapshot(out), "log": log, "manifest": manifest}


def test_a_second_run_keeps_every_step(campaign, rerun):
    log = rerun["log"]
    assert [ln for ln in log if "already done" in ln] == [f"[{n}] already done ({STEPS[n][1]}); kept" for n in default_steps()]
    assert not [ln for ln in log if ln.endswith("...") or " done in " in ln]
    assert rerun["manifest"]["steps"] == campaign["manifest"]["steps"]


def test_a_second_run_changes_no_file_of_the_steps_or_the_report(rerun):
    before, after = rerun["before"], rerun["after"]
    assert sorted(after) == sorted(before)
    steps = [k for k in before if Path(k).parts[0] in STEPS or Path(k).parts[0] == "studies"]
    assert len(steps) > len(default_steps())
    # the steps' and studies' files are not even rewritten
    assert [k for k in steps if after[k] != before[k]] == []
    # the report and the manifest are rebuilt, to the same bytes
    assert [k for k in ("report.html", "campaign.json") if after[k][0] != before[k][0]] == []


def test_a_second_run_rewrites_campaign_h5_to_the_same_bytes(rerun):
    assert rerun["after"]["campaign.h5"][0] == rerun["before"]["campaign.h5"][0]


@pytest.mark.parametrize("change", [
    {"quick": False},
    {"specimens": "Sh02-Sd015,Sh02-Sd020"},
    {"config": "free"},
    {"contact": 0.8},
])
def test_a_run_with_other_parameters_is_refused_and_writes_nothing(campaign, change):
    out = campaign["out"]
    before = _snapshot(out)
    kw = {"quick": True, **change}
    kw["specimens"] = select_specimens(kw.get("specimens", SPECIMENS))
    log: list[str] = []
    with pytest.raises(ArchdemInputError, match="other parameters"):
        run_campaign(CampaignContext(out=out, workers=1, log=log.append, **kw))
    assert log == [] and _snapshot(out) == before


def test_a_campaign_step_on_a_local_dask_cluster(tmp_path):
    """``--scheduler``: the campaign's sweeps run on a real local cluster, with the local results."""
    distributed = pytest.importorskip("distributed")

    def tilt_rows(out, scheduler=None):
        ctx = CampaignContext(out=out, specimens=select_specimens("Sh02-Sd020"), quick=True, workers=2,
                              log=lambda s: None, scheduler=scheduler)
        run_campaign(ctx, ["tilt"])
        with open(out / "tilt" / "tilt.csv", newline="") as fh:
            return list(csv.DictReader(fh))

    local = tilt_rows(tmp_path / "local")
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None) as cl:
        remote = tilt_rows(tmp_path / "dask", cl.scheduler_address)
    keep = [k for k in local[0] if "wall" not in k]
    assert [{k: r[k] for k in keep} for r in remote] == [{k: r[k] for k in keep} for r in local]
