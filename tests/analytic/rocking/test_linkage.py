"""Four-bar and two-bar linkages (analytic/rocking/linkage.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from analytic.limit.layout import continuous_layout
from analytic.rocking.linkage import (
    arch_four_bar,
    arch_two_bar,
    mirror_layout,
    oppenheim_hinges,
    parse_hinge_angles,
)
from specimens.catalogue import get_specimen
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch

IDS = ["Sh02-Sd015", "Sh06-Sd020", "Sh1-Sd025"]


def _lambda_instantaneous_centres(points, blocks):
    """Virtual work with instantaneous centres (docs/physics/limit-analysis.md#2-the-four-hinge-mechanism),
    written independently of the linkage: block 1 about H1, block 2 about C2 = H1H2 x H4H3, block 3
    about H4."""
    H1, H2, H3, H4 = (np.asarray(p, float) for p in points)
    d1, d2 = H2 - H1, H3 - H4
    # C2 = H1 + s d1 = H4 + t d2
    s, _ = np.linalg.solve(np.column_stack([d1, -d2]), H4 - H1)
    C2 = H1 + s * d1
    w1 = 1.0
    w2 = w1 * np.dot(H2 - H1, H2 - C2) / np.dot(H2 - C2, H2 - C2)
    w3 = w2 * np.dot(H3 - C2, H3 - H4) / np.dot(H3 - H4, H3 - H4)
    J = lambda r: np.array([-r[1], r[0]])  # noqa: E731
    dx = dy = 0.0
    for b, w, c in zip(blocks, (w1, w2, w3), (H1, C2, H4)):
        v = w * J(np.asarray(b.centroid) - c)
        dx += b.mass * v[0]
        dy += b.mass * v[1]
    return abs(dy / dx)


@pytest.mark.parametrize("sid", IDS)
def test_four_bar_onset_equals_virtual_work_lambda(sid):
    arch = get_specimen(sid).arch
    lay = continuous_layout(arch, oppenheim_hinges(arch), 500.0)
    fb = arch_four_bar(arch, lay)
    lam_vw = _lambda_instantaneous_centres([h.point(arch) for h in lay.hinges], lay.blocks)
    assert fb.lam == pytest.approx(lam_vw, rel=1e-6)  # issue tolerance (both exact: agree to ~1e-14)
    assert fb.onset / 9.81 == pytest.approx(fb.lam, rel=1e-14) and fb.direction == 1


@pytest.mark.parametrize("sid", IDS)
def test_four_bar_onset_equals_limit_analysis_of_minimised_layout(sid):
    import analytic.limit.limit_continuous as lc
    arch = get_specimen(sid).arch
    res = lc.continuous_collapse(arch, density=500.0)
    for d in (1, -1):  # either direction (mirrored through the cuts u)
        fb = arch_four_bar(arch, res.layout, direction=d, cuts=list(res.u))
        assert fb.lam == pytest.approx(res.lam, rel=1e-6)  # issue tolerance


def test_e_zero_reproduces_round_arch():
    """e = 0: macro-blocks are annular sectors with closed-form properties; the four-bar built on
    them directly matches the one built through the pointed-arch geometry (1e-10)."""
    Rc, t = 0.2, 0.04
    arch = PointedArch(e=0.0, t=t, Rp=Rc, width=0.1)
    rnd = PointedArch.round(Rc, t, width=0.1)
    hinges = oppenheim_hinges(arch)
    fb = arch_four_bar(arch, hinges, direction=None)
    fr = arch_four_bar(rnd, hinges, direction=None)
    # closed-form annular sectors between the hinge cuts (polar angles about O = psi for e = 0)
    Ri, Re, rho = Rc - t / 2, Rc + t / 2, 500.0 * 0.1
    ang = [math.pi - h.psi if h.side < 0 else h.psi for h in hinges]
    from analytic.limit.layout import MacroBlock
    from analytic.rocking.linkage import four_bar
    blocks = []
    for a, b in zip(ang[:-1], ang[1:]):
        lo, hi = min(a, b), max(a, b)
        th = hi - lo
        m = rho * 0.5 * (Re ** 2 - Ri ** 2) * th
        rbar = (2 / 3) * (Re ** 3 - Ri ** 3) / (Re ** 2 - Ri ** 2) * math.sin(th / 2) / (th / 2)
        mid = 0.5 * (lo + hi)
        c = np.array([rbar * math.cos(mid), rbar * math.sin(mid)])
        J_O = rho * 0.25 * (Re ** 4 - Ri ** 4) * th
        blocks.append(MacroBlock(m, c, J_O - m * float(c @ c)))
    pts = [h.point(arch) for h in hinges]
    fc = four_bar(pts, blocks)
    for f in (fb, fr):
        assert f.lam == pytest.approx(fc.lam, rel=1e-10)
        assert f.M0 == pytest.approx(fc.M0, rel=1e-10)
        assert f.phi_cr == pytest.approx(fc.phi_cr, rel=1e-8)
        assert f.omega0 == pytest.approx(fc.omega0, rel=1e-10)


def test_symmetric_rest_state_zero_generalised_force():
    """At rest with no ground motion the generalised force is zero (Q = -a_g S); a mechanism and its
    mirror image have opposite onsets (the symmetric arch has no preferred direction at rest). The
    mirror's coordinate is the rotation of the mirror of block 3, so S and V' scale by w1/w3 (and M
    by its square)."""
    arch = get_specimen("Sh06-Sd015").arch
    lay = continuous_layout(arch, oppenheim_hinges(arch), 500.0)
    fb = arch_four_bar(arch, lay, direction=None)
    fm = arch_four_bar(arch, mirror_layout(lay), direction=None)
    assert fb.generalised_force(0.0, 0.0) == 0.0
    M, dM, dV, S = fb.terms(0.0)
    Mm, dMm, dVm, Sm = fm.terms(0.0)
    k = 1.0 / abs(fb.rotation_rates()[2])
    assert fm.onset == pytest.approx(-fb.onset, rel=1e-12)
    assert abs(Sm) == pytest.approx(abs(S) * k, rel=1e-12) and dVm == pytest.approx(dV * k, rel=1e-12)
    assert Mm == pytest.approx(M * k * k, rel=1e-12)


def test_assembly_branch_continuous_from_rest():
    arch = get_specimen("Sh06-Sd015").arch
    fb = arch_four_bar(arch, oppenheim_hinges(arch))
    st0 = fb.body_states(0.0)
    for s, b in zip(st0, [fb.centroids[0], fb.centroids[1], fb.centroids[2]]):
        assert (s.x, s.y) == pytest.approx(b, abs=1e-14)  # rest pose reproduced
    phis = np.linspace(0, fb.phi_limit, 200)
    xs = np.array([[s.x for s in fb.body_states(p)] for p in phis])
    assert np.max(np.abs(np.diff(xs, axis=0))) < 0.05 * arch.Rp  # no jump to the other branch


def test_two_bar_onset_matches_virtual_work():
    import analytic.limit.two_bar as tb_mod
    for sid in IDS:
        arch = get_specimen(sid).arch
        tb = arch_two_bar(arch)
        assert tb.lam == pytest.approx(tb_mod.lambda_two_bar(arch), rel=1e-10)
        assert tb.direction == 1 and tb.impact_candidates()[0].direction == -1


def test_layout_parsing():
    arch = get_specimen("Sh02-Sd015").arch
    h = parse_hinge_angles(arch, "0.196,1.374,2.159,2.945")
    assert h == oppenheim_hinges(arch)
    for bad in ("1,2,3", "a,b,c,d", "0.1,0.2,0.3,5"):
        with pytest.raises(ArchdemInputError):
            parse_hinge_angles(arch, bad)
    for hh, beta in zip(h, (2.945, 2.159, 1.374, 0.196)):
        assert hh.polar_about_origin(arch) == pytest.approx(beta, abs=1e-12)  # the profile point seen at beta


@pytest.mark.slow
def test_minimised_layout_keeps_its_cuts():
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.rocking.linkage import minimised_four_bar, minimised_layout

    arch = get_specimen("Sh06-Sd020").arch
    lam = continuous_collapse(arch).lam
    for d in (1, -1):
        assert arch_four_bar(arch, minimised_layout(arch), direction=d).lam == pytest.approx(lam, rel=1e-6)
    assert minimised_four_bar(arch).lam == pytest.approx(lam, rel=1e-6)
