"""The cross-check: limit analysis (continuous, discrete enumeration, static LP with friction), the
rocking block, the four-bar and two-bar linkages with impact, failure domains, ground motions.

    >>> from analytic import continuous_collapse, solve_lp
    >>> from specimens import discretise, get_specimen
    >>> arch = get_specimen("Sh06-Sd015").arch
    >>> lam = solve_lp(discretise(arch), mu_joint=0.577, mu_base=1.0).lam   # static multiplier
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from foundation.lazy import lazy_exports

# ruff: noqa: F401 (the names below are re-exported lazily)

# public name -> its module (imported on first use)
_EXPORTS = {
    "FailureDomain": "analytic.rocking.domain", "failure_domain": "analytic.rocking.domain",
    "Response": "analytic.rocking.dynamics", "simulate": "analytic.rocking.dynamics",
    "GroundMotion": "analytic.motions.inputs", "PulseA": "analytic.motions.inputs", "PulseB": "analytic.motions.inputs", "SampledMotion": "analytic.motions.inputs", "SinePulse": "analytic.motions.inputs",
    "continuous_collapse": "analytic.limit.limit_continuous",
    "enumerate_mechanisms": "analytic.limit.limit_discrete", "solve_lp": "analytic.limit.limit_discrete",
    "solve_non_associative": "analytic.limit.non_associative",
    "arch_four_bar": "analytic.rocking.linkage", "arch_two_bar": "analytic.rocking.linkage", "minimised_four_bar": "analytic.rocking.linkage", "minimised_layout": "analytic.rocking.linkage",
    "ground_motion": "analytic.motions.records", "read_record": "analytic.motions.records",
    "RockingBlock": "analytic.rocking.rocking_block",
    "analyse": "analytic.limit.summary",
    "lambda_slide": "analytic.limit.two_bar", "lambda_two_bar": "analytic.limit.two_bar", "mu_star": "analytic.limit.two_bar",
}
__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # the same names for type checkers and editors
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.limit.limit_discrete import enumerate_mechanisms, solve_lp
    from analytic.limit.non_associative import solve_non_associative
    from analytic.limit.summary import analyse
    from analytic.limit.two_bar import lambda_slide, lambda_two_bar, mu_star
    from analytic.motions.inputs import GroundMotion, PulseA, PulseB, SampledMotion, SinePulse
    from analytic.motions.records import ground_motion, read_record
    from analytic.rocking.domain import FailureDomain, failure_domain
    from analytic.rocking.dynamics import Response, simulate
    from analytic.rocking.linkage import (
        arch_four_bar,
        arch_two_bar,
        minimised_four_bar,
        minimised_layout,
    )
    from analytic.rocking.rocking_block import RockingBlock


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
