"""The one bracket-and-bisect search (analytic.search) against stand-in outcomes with known thresholds."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from analytic.search import Bracket, midpoint, search, wide

RULES = ("width/hi", "width/lo", "ratio", "width")


def _recorder(truth: float):
    """An outcome ``x >= truth`` that records every x it is asked about."""
    seen: list[float] = []

    def f(x: float) -> bool:
        seen.append(x)
        return x >= truth

    return f, seen


@settings(max_examples=200, deadline=None)
@given(truth=st.floats(0.05, 20.0), lo_f=st.floats(0.2, 0.999), hi_f=st.floats(1.001, 5.0),
       rule=st.sampled_from(RULES), geometric=st.booleans(), ends=st.sampled_from(("first", "last")))
def test_converges_on_a_monotone_threshold(truth, lo_f, hi_f, rule, geometric, ends):
    # the first bracket is a guess around the truth: the answer brackets it, both ends were run, narrow by the rule
    tol = 1e-3 if rule != "width" else 1e-3 * truth
    f, seen = _recorder(truth)
    res = search(f, lo_f * truth, hi_f * truth, tol, rule=rule, geometric=geometric, ends=ends,
                 up=lambda x: x * 1.1, down=lambda x: x * 0.9)
    assert res.status == "converged"
    assert res.lo < truth <= res.hi
    assert res.lo in seen and res.hi in seen and res.lo_run is False and res.hi_run is True
    assert not wide(res.lo, res.hi, tol, rule)
    assert res.runs == len(seen)


@settings(max_examples=200, deadline=None)
@given(truth_f=st.floats(0.05, 30.0), ends=st.sampled_from(("first", "last")), max_runs=st.integers(1, 12))
def test_never_reports_an_end_it_did_not_run(truth_f, ends, max_runs):
    # whatever the budget, a reported bracket has both ends run; otherwise the status says it is none
    f, seen = _recorder(truth_f)
    res = search(f, 0.972, 1.01, 0.005, ends=ends, up=lambda x: x * 1.05, down=lambda x: x * 0.95, max_runs=max_runs,
                 limit=100.0)
    assert res.runs == len(seen) <= max_runs
    if res.bracketed:
        assert res.lo in seen and res.hi in seen and res.lo < truth_f <= res.hi
    else:
        assert res.status in ("unbracketed", "no_upper")


def test_budget_out_while_stepping_down_is_no_bracket():
    # truth far below the first bracket (0.3 x the guess): 5 runs cannot step down to it; the search
    # must not return a bracket whose lower end it never ran
    f, seen = _recorder(0.3)
    res = search(f, 0.972, 1.01, 0.005, up=lambda x: x * 1.05, down=lambda x: x * 0.95, max_runs=5)
    assert res.status == "unbracketed" and res.lo_run is None and res.lo not in seen
    assert not res.bracketed


def test_wrong_ends_move_outward_and_limit_stops_the_way_up():
    f, seen = _recorder(1.3)
    res = search(f, 0.972, 1.01, 0.005, up=lambda x: x * 1.05, down=lambda x: x * 0.95)
    assert res.status == "converged" and res.lo < 1.3 <= res.hi
    assert any(x > 1.01 for x in seen)  # the upper end was moved up
    f, seen = _recorder(10.0)
    res = search(f, 0.972, 1.01, 0.005, up=lambda x: x * 1.05, down=lambda x: x * 0.95, limit=3.0)
    assert res.status == "no_upper" and res.hi > 3.0 and max(seen) <= 3.0


def test_max_down_stops_the_way_down():
    # every run below is upper: after max_down steps down the search gives up with no_lower
    f, seen = _recorder(-1.0)
    res = search(f, 0.5, 1.0, 0.01, hi_run=True, down=lambda x: x / 2, ends="first", max_down=3)
    assert res.status == "no_lower" and seen == [0.5, 0.25, 0.125] and res.hi == 0.125


def test_first_runs_the_guessed_ends_before_bisecting():
    f, seen = _recorder(1.0)
    search(f, 0.9, 1.1, 0.01, ends="first", up=lambda x: x * 1.1, down=lambda x: x * 0.9)
    assert seen[:2] == [1.1, 0.9]
    f, seen = _recorder(1.0)
    search(f, 0.9, 1.1, 0.01, ends="last", up=lambda x: x * 1.1, down=lambda x: x * 0.9)
    assert seen[0] == pytest.approx(1.0) and 1.1 not in seen and 0.9 not in seen


def test_hook_sees_every_run_in_order():
    calls = []
    f, seen = _recorder(0.7)
    search(f, 0.5, 1.0, 1e-3, lo_run=False, hi_run=True, on_run=lambda x, r: calls.append((x, r)))
    assert [x for x, _ in calls] == seen and [r for _, r in calls] == [x >= 0.7 for x in seen]


def test_midpoints_and_rules():
    assert midpoint(1.0, 4.0) == 2.5 and midpoint(1.0, 4.0, geometric=True) == 2.0
    assert wide(1.0, 1.02, 0.01, "ratio") and not wide(1.0, 1.01, 0.011, "ratio")
    assert wide(1.0, 1.02, 0.015, "width/hi") and not wide(1.0, 1.02, 0.02, "width/hi")
    assert wide(1.0, 1.02, 0.015, "width/lo") and not wide(1.0, 1.02, 0.021, "width/lo")
    assert wide(1.0, 1.5, 0.4, "width") and not wide(1.0, 1.5, 0.5, "width")
    with pytest.raises(ValueError):
        wide(1.0, 2.0, 0.1, "nope")


def test_a_third_class_inside_keeps_the_lowest_change():
    # survival below 1, collapse mode A in [1, 1.5), mode B above: bisecting survival -> B finds the change at 1
    cls = lambda x: "survival" if x < 1.0 else ("A" if x < 1.5 else "B")  # noqa: E731
    res = search(cls, 0.5, 3.0, 1e-6, rule="width/lo", geometric=True, is_upper=lambda c: c != "survival",
                 lo_run="survival", hi_run="B")
    assert res.lo < 1.0 <= res.hi and res.hi_run == "A" and res.hi / res.lo - 1 < 2e-6


def test_bracket_steps_as_a_caller_would():
    b = Bracket(1.0, 2.0, 0.01, "ratio", geometric=True)
    n = 0
    while b.wide():
        x = b.mid()
        b.take(x, x >= math.sqrt(2), x)
        n += 1
    assert b.lo < math.sqrt(2) <= b.hi and n == math.ceil(math.log2(math.log(2) / math.log(1.01)))


def test_a_guessed_end_needs_a_way_out():
    with pytest.raises(ValueError, match="up for hi"):
        search(bool, 0.5, 1.0, 0.01, lo_run=False)
    with pytest.raises(ValueError, match="down for lo"):
        search(bool, 0.5, 1.0, 0.01, hi_run=True)
