"""The generic one-degree-of-freedom mechanism core (analytic/rocking/mechanism.py).

Closed-form derivatives (velocity and acceleration analysis) are checked against an
O(h^4) central-difference stencil applied to the positions (an independent route).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from analytic.rocking.linkage import arch_four_bar, arch_two_bar, oppenheim_hinges
from analytic.rocking.rocking_block import RockingBlock
from specimens.catalogue import get_specimen


def _fd(f, x, h):
    """Fourth-order central difference (truncation O(h^4))."""
    return (-f(x + 2 * h) + 8 * f(x + h) - 8 * f(x - h) + f(x - 2 * h)) / (12 * h)


MECHS = {
    "block": lambda: RockingBlock(0.15, 0.6),
    "four-bar": lambda: arch_four_bar(get_specimen("Sh06-Sd015").arch, oppenheim_hinges(get_specimen("Sh06-Sd015").arch)),
    "two-bar": lambda: arch_two_bar(get_specimen("Sh1-Sd025").arch),
}


@pytest.mark.parametrize("name", list(MECHS))
@pytest.mark.parametrize("phi", [0.0, 0.05, 0.2])
def test_closed_form_derivatives_match_positions(name, phi):
    mech = MECHS[name]()
    st = mech.body_states(phi)
    h = 1e-3
    for j, s in enumerate(st):
        x = lambda p: mech.body_states(p)[j].x  # noqa: E731
        y = lambda p: mech.body_states(p)[j].y  # noqa: E731
        th = lambda p: mech.body_states(p)[j].theta  # noqa: E731
        dx = lambda p: mech.body_states(p)[j].dx  # noqa: E731
        dy = lambda p: mech.body_states(p)[j].dy  # noqa: E731
        dth = lambda p: mech.body_states(p)[j].dtheta  # noqa: E731
        # O(h^4) = 1e-12 truncation x derivative scale; round-off ~ 1e-16 / h = 1e-13: 1e-9 is safe
        assert s.dx == pytest.approx(_fd(x, phi, h), abs=1e-9)
        assert s.dy == pytest.approx(_fd(y, phi, h), abs=1e-9)
        assert s.dtheta == pytest.approx(_fd(th, phi, h), abs=1e-9)
        assert s.ddx == pytest.approx(_fd(dx, phi, h), abs=1e-8)
        assert s.ddy == pytest.approx(_fd(dy, phi, h), abs=1e-8)
        assert s.ddtheta == pytest.approx(_fd(dth, phi, h), abs=1e-8)


@pytest.mark.parametrize("name", list(MECHS))
def test_generalised_terms_are_consistent(name):
    """M' and V' of the core equal the derivatives of M and V (O(h^4) stencil, 1e-8 relative)."""
    mech = MECHS[name]()
    for phi in (0.0, 0.03, 0.1):
        M, dM, dV, S = mech.terms(phi)
        assert dM == pytest.approx(_fd(mech.mass, phi, 1e-3), rel=1e-7, abs=1e-12 * M)
        assert dV == pytest.approx(_fd(mech.potential, phi, 1e-3), rel=1e-8)
        assert mech.d2potential(phi) == pytest.approx(_fd(mech.dpotential, phi, 1e-3), rel=1e-7, abs=1e-9 * abs(dV))


@pytest.mark.parametrize("name", list(MECHS))
def test_onset_phi_cr_and_frequency_definitions(name):
    mech = MECHS[name]()
    M, dM, dV, S = mech.terms(0.0)
    assert mech.onset == pytest.approx(dV / (-S), rel=1e-14)
    assert dV > 0  # gravity resists the opening
    assert mech.dpotential(mech.phi_cr) == pytest.approx(0.0, abs=1e-10 * dV)  # phi_cr is where V' vanishes
    assert mech.potential(mech.phi_cr) > mech.potential(0.5 * mech.phi_cr)
    assert mech.omega0 == pytest.approx(math.sqrt(abs(mech.d2potential(0.0)) / M), rel=1e-14)
    # velocity map and mass matrix reproduce M(0): Psi^T M Psi
    psi = mech.velocity_map(0.0).ravel()
    assert psi @ mech.mass_matrix() @ psi == pytest.approx(M, rel=1e-13)


@pytest.mark.parametrize("name", list(MECHS))
def test_energy_conserved_free_motion(name):
    """No input, no impact: T + V is constant along the solution of the Lagrange equation (checks
    M' in the equation of motion; DOP853 at rtol 1e-10 keeps the drift below 1e-8 of the energy)."""
    from analytic.rocking.dynamics import integrate

    mech = MECHS[name]()
    y0 = (0.3 * mech.phi_cr, 0.5 * mech.omega0 * mech.phi_cr)
    T = 1.0 / mech.omega0
    sol = integrate(mech, y0, (0.0, T))
    assert np.all(sol.y[0] > 0) and np.all(sol.y[0] < mech.phi_limit)
    E = np.array([mech.energy(p, v) for p, v in zip(sol.y[0], sol.y[1])])
    assert np.max(np.abs(E - E[0])) < 1e-8 * abs(E[0])
