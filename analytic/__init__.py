"""The cross-check: limit analysis (continuous, discrete enumeration, static LP with friction), the
rocking block, the four-bar and two-bar linkages with impact, failure domains, ground motions.

    >>> from analytic import continuous_collapse, solve_lp
    >>> from specimens import discretise, get_specimen
    >>> arch = get_specimen("Sh06-Sd015").arch
    >>> lam = solve_lp(discretise(arch), mu_joint=0.577, mu_base=1.0).lam   # static multiplier
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from specimens.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use)
_EXPORTS = {
    "FailureDomain": "analytic.domain", "failure_domain": "analytic.domain",
    "Response": "analytic.dynamics", "simulate": "analytic.dynamics",
    "GroundMotion": "analytic.inputs", "PulseA": "analytic.inputs", "PulseB": "analytic.inputs", "SampledMotion": "analytic.inputs", "SinePulse": "analytic.inputs",
    "continuous_collapse": "analytic.limit_continuous",
    "enumerate_mechanisms": "analytic.limit_discrete", "solve_lp": "analytic.limit_discrete",
    "arch_four_bar": "analytic.linkage", "arch_two_bar": "analytic.linkage", "minimised_four_bar": "analytic.linkage", "minimised_layout": "analytic.linkage",
    "ground_motion": "analytic.records", "read_record": "analytic.records",
    "RockingBlock": "analytic.rocking_block",
    "analyse": "analytic.summary",
    "lambda_slide": "analytic.two_bar", "lambda_two_bar": "analytic.two_bar", "mu_star": "analytic.two_bar",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from analytic.domain import FailureDomain, failure_domain
    from analytic.dynamics import Response, simulate
    from analytic.inputs import GroundMotion, PulseA, PulseB, SampledMotion, SinePulse
    from analytic.limit_continuous import continuous_collapse
    from analytic.limit_discrete import enumerate_mechanisms, solve_lp
    from analytic.linkage import (
        arch_four_bar,
        arch_two_bar,
        minimised_four_bar,
        minimised_layout,
    )
    from analytic.records import ground_motion, read_record
    from analytic.rocking_block import RockingBlock
    from analytic.summary import analyse
    from analytic.two_bar import lambda_slide, lambda_two_bar, mu_star


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
