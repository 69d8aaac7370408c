"""``archdem analytic`` command line."""
import json
import math
import re

import pytest

from analytic.limit.limit_discrete import enumerate_mechanisms
from dem.cli import main
from specimens.blocks import discretise
from specimens.catalogue import get_specimen


def test_json_keys_and_values(capsys):
    assert main(["analytic", "Sh06-Sd015", "--config", "free", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    for key in ("lambda_continuous", "hinges_continuous", "lambda_discrete", "hinges_discrete", "lambda_lp",
                "joints_lp", "lambda_two_bar"):
        assert key in out
    assert len(out["hinges_continuous"]) == 4
    assert set(out["hinges_continuous"][0]) >= {"half", "angle_rad", "face"}
    assert [set(h) for h in out["hinges_discrete"]] == [{"joint", "face"}] * 4
    # the CLI reports the library's number (independent call)
    kin = enumerate_mechanisms(discretise(get_specimen("Sh06-Sd015").arch, config="free"))
    assert out["lambda_discrete"] == pytest.approx(kin.lam, rel=1e-12)
    assert out["lambda_lp"] <= out["lambda_discrete"] + 1e-9  # friction can only lower it
    assert "non_associative" not in out  # only with --friction non-associative


def test_params_and_unstable_arch(capsys):
    assert main(["analytic", "--Sh", "0.2", "--Sd", "0.03", "--Rc", "1", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["stands"] is False and out["lambda_continuous"] < 0


def test_bad_input_exit_2(capsys):
    assert main(["analytic", "Sh06-Sd015", "--effective-thickness", "1.5"]) == 2
    assert "effective-thickness" in capsys.readouterr().err
    assert main(["analytic", "nope"]) == 2


def test_an_arch_that_cannot_stand_says_so_without_multipliers(capsys):
    """No negative multiplier printed before "cannot stand", and no None formatted (very tall thin piers)."""
    for argv in (["analytic", "--Sh", "0", "--Sd", "0.03", "--Rc", "0.2"],
                 ["analytic", "--Sh", "0.6", "--Sd", "0.15", "--Rc", "0.2", "--pier-height", "50", "--pier-width", "0.05"]):
        assert main(argv) == 1
        out = capsys.readouterr().out
        assert "cannot stand under self-weight" in out and "lambda =" not in out


NA_LINES = (r"  LP \(associative\) +lambda = ([\d.]+)   \(upper bound: sliding joints dilate\)\n"
            r"  non-associative +lambda = ([\d.]+)   ([-\d.]+) % below; hinges: (.+)   "
            r"\[optimal \(proven to a relative gap of (\S+)\); ([\d.]+) s, (\d+) nodes\]\n")


@pytest.mark.slow
def test_non_associative_prints_both_multipliers_its_mechanism_and_gap(capsys):
    """Sh02-Sd025 free at 0.577/1: the LP slides at L8 and dilates; without dilatancy the collapse lies
    about 2 % lower (docs/physics/limit-analysis.md#14-coulomb-friction-without-dilatancy)."""
    from analytic.limit.non_associative import solve_non_associative

    argv = ["analytic", "Sh02-Sd025", "--config", "free", "--friction", "non-associative"]
    assert main(argv) == 0
    text = capsys.readouterr().out
    m = re.search(NA_LINES, text)
    assert m, text
    lp, na = float(m[1]), float(m[2])
    assert f"LP (friction) lambda = {m[1]}" in text  # the same LP
    assert na <= lp * (1 + 1e-9) and 0 < 1 - na / lp < 0.05
    assert float(m[5]) <= 1e-6 and float(m[6]) > 0 and int(m[7]) >= 0
    assert main([*argv, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    d = out["non_associative"]
    assert d["lambda_associative"] == pytest.approx(out["lambda_lp"], rel=1e-9)
    assert d["lambda_non_associative"] <= out["lambda_lp"] * (1 + 1e-9)
    assert d["optimal"] is True and d["gap"] <= 1e-6 and isinstance(d["hinges"], list)
    assert m[3] == f"{100 * (1 - d['lambda_non_associative'] / d['lambda_associative']):.2f}"
    # the library's number (independent call on the same blocks)
    lib = solve_non_associative(discretise(get_specimen("Sh02-Sd025").arch, config="free"), 0.577, 1.0)
    assert d["lambda_non_associative"] == pytest.approx(lib.lam, rel=1e-9)
    assert f"{lib.lam:.4f}" == m[2]


@pytest.mark.slow
def test_non_associative_without_friction_limits_is_the_lp_and_on_piers_stays_below_it(capsys):
    assert main(["analytic", "Sh02-Sd025", "--friction", "non-associative", "--mu-joint", "inf", "--mu-base", "inf"]) == 0
    m = re.search(NA_LINES, capsys.readouterr().out)
    assert m and m[1] == m[2] and float(m[3]) == 0  # no sliding: nothing to dilate, still printed
    argv = ["analytic", "Sh06-Sd015", "--pier-height", "1", "--pier-width", "0.3", "--mu-joint", "0.3", "--mu-base",
            "0.4", "--friction", "non-associative", "--json"]
    assert main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    d = out["non_associative"]
    assert d["lambda_associative"] == pytest.approx(out["lambda_lp"], rel=1e-9)
    assert 0 < d["lambda_non_associative"] <= out["lambda_lp"] * (1 + 1e-9) and d["optimal"] is True
    assert d["sliding"] and all(j in out["joints_lp"] for j in d["sliding"])  # it slides, at joints of the LP's blocks
    assert all(v is None or not (isinstance(v, float) and math.isnan(v)) for v in d.values())


def test_a_bad_friction_law_exits_2_in_one_line(capsys):
    assert main(["analytic", "Sh02-Sd025", "--friction", "dilatant"]) == 2
    err = capsys.readouterr().err
    assert "--friction" in err and "invalid choice: 'dilatant'" in err and err.count("\n") == 1


def test_printed_hinge_angles_have_their_unit_and_mu_star_says_what_it_is(capsys):
    assert main(["analytic", "Sh06-Sd015"]) == 0
    text = capsys.readouterr().out
    line = next(ln for ln in text.splitlines() if ln.strip().startswith("continuous"))
    hinges = re.findall(r"([LR]) ([\d.]+) (\S+) (int|ext)", line)
    assert len(hinges) == 4 and all(unit == "rad" for _, _, unit, _ in hinges), line
    assert all(0 <= float(a) <= math.pi / 2 for _, a, _, _ in hinges)  # polar angles of a half, not lengths
    m = re.search(r"two-bar +lambda = ([\d.]+) \(frictionless crown slider\) +mu\* = ([\d.]+) "
                  r"\(friction above which the crown stops sliding and the arch rocks\)", text)
    assert m, text


def test_help_explains_the_terms(capsys):
    assert main(["analytic", "--help"]) == 0
    text = capsys.readouterr().out
    for term in ("continuous", "discrete", "LP (friction)", "two-bar", "mu*", "[rad]", "int = intrados"):
        assert term in text.split("terms")[-1], term
