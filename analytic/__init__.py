"""The cross-check: limit analysis (continuous, discrete enumeration, static LP with friction), the
rocking block, the four-bar and two-bar linkages with impact, failure domains, ground motions.

    >>> from analytic import continuous_collapse, solve_lp
    >>> from specimens import discretise, get_specimen
    >>> arch = get_specimen("Sh06-Sd015").arch
    >>> lam = solve_lp(discretise(arch), mu_joint=0.577, mu_base=1.0).lam   # static multiplier
"""
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

__all__ = [
    "FailureDomain", "failure_domain", "Response", "simulate", "GroundMotion", "PulseA", "PulseB", "SampledMotion",
    "SinePulse", "continuous_collapse", "enumerate_mechanisms", "solve_lp", "arch_four_bar", "arch_two_bar",
    "minimised_four_bar", "minimised_layout", "ground_motion", "read_record", "RockingBlock", "analyse",
    "lambda_slide", "lambda_two_bar", "mu_star",
]
