"""Four-hinge limit analysis of the continuous ring (docs/physics/limit-analysis.md#4-continuous-ring, continuous profile).

Hinges may sit anywhere on the intrados or the extrados; the macro-blocks are bounded by the
cuts through the hinges. A cut is described by one **arch coordinate** ``u`` in ``[0, U]``,
``U = 2 psi_e``, increasing from the left springing to the right springing:

* ``0 <= u <= psi_i`` — the radial cut at ``psi = u`` of the left half;
* ``psi_i < u < U - psi_i`` — the **keystone fan**: the cut from the intrados apex to the
  extrados point at polar angle ``u`` (left arc, up to the extrados apex at ``u = psi_e``) or
  ``U - u`` (right arc). It turns continuously from the left apex cut to the right one, so the
  macro-block masses are continuous in ``u`` and extrados hinges can reach the extrados apex;
  an intrados hinge on a fan cut is the intrados apex itself (the cut direction then decides
  how the keystone material is shared). With ``e = 0`` the fan is empty;
* ``U - psi_i <= u <= U`` — the radial cut at ``psi = U - u`` of the right half.

Macro-block masses and first moments are exact closed forms (Green's theorem on arcs and
segments), vectorised over batches of layouts; the layout returned carries exact
:class:`~analytic.limit.layout.MacroBlock` properties (from :mod:`specimens.sections`).

Minimisation: exhaustive vectorised search over a grid of hinge positions for both alternating
face patterns, then a pattern search (the full 3^4 stencil, step halved when nothing improves) from the best
admissible grid layouts.
Options: ``min_spacing`` (least distance in ``u`` [rad] between consecutive hinges);
``contact`` (fraction c of each cut that touches: the hinges sit at the ends of the cut's
central fraction c, the self-weight stays that of the full ring); ``effective_thickness``
(fraction f of ``t``: the ring is replaced by the ring of thickness ``f t`` about the same mean
radius ``Rp`` and the same centres, its self-weight included — the thinner-ring rule of the
literature, docs/physics/limit-analysis.md#12-effective-contact).
"""
from __future__ import annotations

import itertools
import math
import warnings
from dataclasses import dataclass

import numpy as np

from analytic.limit.layout import FourHingeLayout, Hinge, MacroBlock, continuous_layout
from analytic.limit.limit_discrete import four_hinge_lambda
from specimens.blocks import band_points, central_band, check_contact
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from specimens.sections import Arc, Segment, region_properties

PATTERNS = (("extrados", "intrados", "extrados", "intrados"), ("intrados", "extrados", "intrados", "extrados"))
_FACE_INDEX = {"intrados": 0, "extrados": 1}


# ---------------------------------------------------------------------------------------------
# exact Green integrals (area, int x dA, int y dA) of arcs and segments, vectorised
# ---------------------------------------------------------------------------------------------
def _arc_green(cx: float, cy: float, R: float, a0: np.ndarray, a1: np.ndarray) -> np.ndarray:
    """Contributions (A, Sx, Sy) of the arc about (cx, cy) of radius R from angle a0 to a1."""
    def prim(a):
        s, c = np.sin(a), np.cos(a)
        A = 0.5 * (R * R * a + R * (cx * s - cy * c))
        # Sx = 1/2 int x^2 dy, x = cx + R cos a, dy = R cos a da
        Ix = cx * cx * R * s + 2 * cx * R * R * (a / 2 + np.sin(2 * a) / 4) + R**3 * (s - s**3 / 3)
        # Sy = -1/2 int y^2 dx, dx = -R sin a da
        Iy = cy * cy * R * (-c) + 2 * cy * R * R * (a / 2 - np.sin(2 * a) / 4) + R**3 * (-c + c**3 / 3)
        return np.stack([A, 0.5 * Ix, 0.5 * Iy], axis=-1)

    return prim(np.asarray(a1, float)) - prim(np.asarray(a0, float))


def _seg_green(p0: np.ndarray, p1: np.ndarray) -> np.ndarray:
    x0, y0 = p0[..., 0], p0[..., 1]
    x1, y1 = p1[..., 0], p1[..., 1]
    A = 0.5 * (x0 * y1 - x1 * y0)
    Sx = (y1 - y0) * (x0 * x0 + x0 * x1 + x1 * x1) / 6.0
    Sy = -(x1 - x0) * (y0 * y0 + y0 * y1 + y1 * y1) / 6.0
    return np.stack([A, Sx, Sy], axis=-1)


class RingCuts:
    """The cut family and the cumulative section function of one arch (see module doc)."""

    def __init__(self, arch: PointedArch, contact: float = 1.0):
        self.arch = arch
        self.contact = contact
        self.e, self.Ri, self.Re = arch.e, arch.Ri, arch.Re
        self.psi_i, self.psi_e = arch.psi_i, arch.psi_e
        self.U = 2 * self.psi_e
        # closing segment at the left springing, extrados -> intrados
        self._spring = _seg_green(arch.point(0.0, self.Re, -1), arch.point(0.0, self.Ri, -1))

    def ends(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Intrados and extrados end points (..., 2) of the cut at ``u``."""
        u = np.asarray(u, float)
        U, e = self.U, self.e
        left_i = u <= self.psi_i
        right_i = u >= U - self.psi_i
        pi_ = np.where(left_i, u, np.where(right_i, U - u, self.psi_i))
        si = np.where(u <= self.psi_e, -1.0, 1.0)
        si = np.where(left_i, -1.0, np.where(right_i, 1.0, si))
        I = np.stack([si * (-e + self.Ri * np.cos(pi_)), self.Ri * np.sin(pi_)], axis=-1)
        I = np.where((~left_i & ~right_i)[..., None], np.array([0.0, self.Ri * math.sin(self.psi_i)]), I)
        pe = np.where(u <= self.psi_e, u, U - u)
        se = np.where(u <= self.psi_e, -1.0, 1.0)
        E = np.stack([se * (-e + self.Re * np.cos(pe)), self.Re * np.sin(pe)], axis=-1)
        return I, E

    def contact_ends(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Ends (..., 2) of the central ``contact`` fraction of the cut at ``u``: the hinge points."""
        I, E = self.ends(u)
        return band_points(I, E, central_band(self.contact))

    def cumulative(self, u: np.ndarray) -> np.ndarray:
        """(A, Sx, Sy) per unit width of the ring from the left springing to the cut at ``u``."""
        u = np.asarray(u, float)
        e, U, pi_, pe = self.e, self.U, self.psi_i, self.psi_e
        I, E = self.ends(u)
        # intrados from the left springing (angle pi about C_L) to the cut
        g = _arc_green(e, 0.0, self.Ri, np.full_like(u, math.pi), math.pi - np.minimum(u, pi_))
        g = g + _arc_green(-e, 0.0, self.Ri, np.full_like(u, pi_), np.clip(U - u, 0.0, pi_))
        g = g + _seg_green(I, E)
        # extrados back from the cut to the left springing
        g = g + _arc_green(-e, 0.0, self.Re, np.clip(U - u, 0.0, pe), np.full_like(u, pe))
        g = g + _arc_green(e, 0.0, self.Re, math.pi - np.minimum(u, pe), np.full_like(u, math.pi))
        return g + self._spring

    def normal(self, u: np.ndarray) -> np.ndarray:
        I, E = self.ends(u)
        d = E - I
        n = np.stack([d[..., 1], -d[..., 0]], axis=-1)
        return n / np.linalg.norm(n, axis=-1, keepdims=True)

    def edges(self, u0: float, u1: float) -> list:
        """Exact boundary (arcs and segments) of the ring between cuts ``u0 < u1``."""
        e, U, pi_, pe = self.e, self.U, self.psi_i, self.psi_e
        I0, E0 = self.ends(u0)
        I1, E1 = self.ends(u1)
        out: list = []
        # intrados from cut 0 to cut 1: left arc part, then right arc part
        la0, la1 = min(u0, pi_), min(u1, pi_)
        if la1 > la0:
            out.append(Arc((e, 0.0), self.Ri, math.pi - la0, math.pi - la1))
        ra0, ra1 = min(max(U - u0, 0.0), pi_), min(max(U - u1, 0.0), pi_)
        if ra0 > ra1:
            out.append(Arc((-e, 0.0), self.Ri, ra0, ra1))
        out.append(Segment(tuple(I1), tuple(E1)))
        # extrados from cut 1 back to cut 0: right part then left part
        rb1, rb0 = min(max(U - u1, 0.0), pe), min(max(U - u0, 0.0), pe)
        if rb0 > rb1:
            out.append(Arc((-e, 0.0), self.Re, rb1, rb0))
        lb1, lb0 = min(u1, pe), min(u0, pe)
        if lb1 > lb0:
            out.append(Arc((e, 0.0), self.Re, math.pi - lb1, math.pi - lb0))
        out.append(Segment(tuple(E0), tuple(I0)))
        return out

    def hinge(self, u: float, face: str) -> Hinge:
        """The :class:`Hinge` at cut ``u`` (fan cuts: apex intrados / extrados arc angle)."""
        if face == "intrados":
            if u <= self.psi_i:
                return Hinge(-1, float(u), face, self.contact)
            if u >= self.U - self.psi_i:
                return Hinge(1, float(self.U - u), face, self.contact)
            return Hinge(1, float(self.psi_i), face, self.contact)
        if u <= self.psi_e:
            return Hinge(-1, float(u), face, self.contact)
        return Hinge(1, float(self.U - u), face, self.contact)

    def u_of_hinge(self, h: Hinge) -> float:
        """Arch coordinate of a hinge's cut (an intrados hinge at ``psi_i`` is on that half's apex cut)."""
        psi = float(h.psi)
        if h.face == "intrados":
            psi = min(psi, self.psi_i)
        return psi if h.side < 0 else self.U - psi


# ---------------------------------------------------------------------------------------------
# evaluation
# ---------------------------------------------------------------------------------------------
def _check_density(density: float) -> None:
    if not (isinstance(density, (int, float, np.floating)) and math.isfinite(density) and density > 0):
        raise ArchdemInputError(f"density must be a positive number [kg/m^3], got {density!r}")


def _lambda_u(ring: RingCuts, u: np.ndarray, faces: np.ndarray, load_sign: int = 1):
    """Vectorised multiplier of layouts ``u`` (..., 4) with face indices ``faces`` (..., 4)."""
    I, E = ring.contact_ends(u)
    pts = np.stack([I, E], axis=-2)  # (..., 4, 2 faces, 2)
    f = np.broadcast_to(faces, u.shape)
    H = np.take_along_axis(pts, f[..., None, None], axis=-2)[..., 0, :]
    Q = np.take_along_axis(pts, (1 - f)[..., None, None], axis=-2)[..., 0, :]
    n = ring.normal(u)
    F = ring.cumulative(u)  # (..., 4, 3)
    blocks = F[..., 1:, :] - F[..., :-1, :]
    return four_hinge_lambda(H, Q, n, blocks[..., 0], blocks[..., 1], blocks[..., 2], load_sign=load_sign)


def lambda_of_hinges(arch: PointedArch, hinges, density: float = 500.0, load_sign: int = 1,
                     cuts=None) -> float:
    """Multiplier of a given four-hinge layout on the continuous ring (``inf`` if inadmissible).

    ``hinges``: four :class:`~analytic.limit.layout.Hinge` left to right on radial cuts
    (``psi <= psi_i``; an extrados hinge may also have ``psi_i < psi <= psi_e``, a keystone-fan
    cut). An intrados hinge at the apex (``psi = psi_i``) is ambiguous: its cut is taken as the
    apex cut of its half unless ``cuts`` (the four arch coordinates, e.g.
    :attr:`ContinuousResult.u`) gives the keystone-fan cut found by the optimiser.
    ``density`` does not change the multiplier (kept for a uniform signature).
    """
    _check_density(density)
    contacts = {h.contact for h in hinges}
    if len(contacts) != 1:
        raise ArchdemInputError(f"the four hinges must share one effective contact, got {sorted(contacts)}")
    ring = RingCuts(arch, check_contact(contacts.pop()))
    u = np.array([ring.u_of_hinge(h) for h in hinges]) if cuts is None else np.asarray(cuts, float)
    if np.any(np.diff(u) <= 0):
        raise ArchdemInputError("hinges must be given left to right at distinct cuts")
    faces = np.array([_FACE_INDEX[h.face] for h in hinges])
    w = _lambda_u(ring, u, faces, load_sign)
    return float(w.lam) if bool(w.admissible) else math.inf


def layout_of(arch: PointedArch, u: np.ndarray, faces: tuple[str, ...], density: float,
              contact: float = 1.0) -> FourHingeLayout:
    """The :class:`FourHingeLayout` of cuts ``u`` (4,) with exact macro-block properties (hinges
    at the ends of each cut's central ``contact`` fraction)."""
    ring = RingCuts(arch, contact)
    hinges = tuple(ring.hinge(float(x), f) for x, f in zip(u, faces))
    radial = all(x <= ring.psi_i or x >= ring.U - ring.psi_i for x in u)
    if radial and np.all(np.diff(u) > 0) and all(
            not (abs(x - ring.psi_i) < 1e-15 and f == "intrados") for x, f in zip(u, faces)):
        try:
            return continuous_layout(arch, hinges, density)  # type: ignore[arg-type]
        except (ValueError, ZeroDivisionError):
            pass
    rho_w = density * arch.width
    blocks = []
    for k in range(3):
        sec = region_properties(ring.edges(float(u[k]), float(u[k + 1])))
        blocks.append(MacroBlock(rho_w * sec.area, sec.centroid, rho_w * sec.polar))
    return FourHingeLayout(hinges, tuple(blocks))  # type: ignore[arg-type]


# ---------------------------------------------------------------------------------------------
# minimisation
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ContinuousResult:
    """Minimum four-hinge multiplier of the continuous ring.

    ``lam``; ``hinges`` (4 :class:`Hinge`, left to right); ``u``: their arch coordinates [rad];
    ``faces``; ``layout`` (macro-block masses [kg], centroids [m], inertias [kg m^2] of the
    effective ring); ``converged`` (local refinement succeeded and did not end above the grid
    minimum); ``stands`` (``lam >= 0``); ``message``; ``effective_thickness``; ``min_spacing``;
    ``contact``.
    """

    lam: float
    hinges: tuple[Hinge, Hinge, Hinge, Hinge]
    u: np.ndarray
    faces: tuple[str, str, str, str]
    layout: FourHingeLayout | None
    converged: bool
    stands: bool
    message: str
    effective_thickness: float = 1.0
    min_spacing: float = 0.0
    load_sign: int = 1
    contact: float = 1.0

    def polar_angles(self, arch: PointedArch) -> np.ndarray:
        """Polar angles about O of the hinge points [rad] (0 = right springing); ``arch`` as analysed."""
        return hinge_polar_angles(arch, self.hinges)


def effective_arch(arch: PointedArch, effective_thickness: float) -> PointedArch:
    """The ring of thickness ``f t`` about the same mean radius and centres."""
    f = float(effective_thickness)
    if not (math.isfinite(f) and 0 < f <= 1):
        raise ArchdemInputError(f"effective thickness must be a fraction in (0, 1], got {effective_thickness!r}")
    return arch if f == 1.0 else arch.with_thickness(f * arch.t)


def _grid_search(ring: RingCuts, n: int, min_spacing: float, load_sign: int):
    """Best admissible layouts on a grid of ``n`` cut positions, for each face pattern.

    Cut end points, normals and cumulative sections are computed once per grid node and
    gathered for the ``C(n, 4)`` layouts.
    """
    grid = np.linspace(0.0, ring.U, n)
    I, E = ring.contact_ends(grid)
    pts = np.stack([I, E], axis=1)  # (n, 2 faces, 2)
    nrm = ring.normal(grid)
    F = ring.cumulative(grid)
    combos = np.array(list(itertools.combinations(range(n), 4)), dtype=np.int32)
    if min_spacing > 0:
        combos = combos[np.all(np.diff(grid[combos], axis=1) >= min_spacing - 1e-15, axis=1)]
    blocks = F[combos[:, 1:]] - F[combos[:, :-1]]
    nn = nrm[combos]
    out = []
    for pat in PATTERNS:
        faces = np.array([_FACE_INDEX[f] for f in pat])
        H = pts[combos, faces]
        Q = pts[combos, 1 - faces]
        w = four_hinge_lambda(H, Q, nn, blocks[..., 0], blocks[..., 1], blocks[..., 2], load_sign=load_sign)
        lam = np.where(w.admissible, w.lam, np.inf)
        order = np.argsort(lam)[:6]
        for k in order:
            if np.isfinite(lam[k]):
                out.append((float(lam[k]), grid[combos[k]].copy(), pat))
    out.sort(key=lambda r: r[0])
    return out


_STENCIL = np.array(list(itertools.product((-1, 0, 1), repeat=4)), dtype=float)


def _pattern_search(ring: RingCuts, u0: np.ndarray, faces: np.ndarray, step: float, min_spacing: float,
                    load_sign: int, tol: float = 1e-10, max_iter: int = 400) -> tuple[float, np.ndarray, bool]:
    """Derivative-free local minimisation: full 3^4 stencil, evaluated in one vectorised batch.

    Moves to the best admissible neighbour; halves the step when none improves. Robust to
    the kinks of the objective (apex, fan ends). Returns (lambda, u, converged).
    """
    spacing = max(min_spacing, 1e-9)

    def evaluate(U4: np.ndarray) -> np.ndarray:
        U4 = np.clip(U4, 0.0, ring.U)
        w = _lambda_u(ring, U4, faces, load_sign)
        good = w.admissible & np.all(np.diff(U4, axis=-1) >= spacing - 1e-15, axis=-1)
        return np.where(good, w.lam, np.inf)

    u = np.asarray(u0, float).copy()
    f = float(evaluate(u[None])[0])
    for _ in range(max_iter):
        if step < tol:
            return f, u, True
        cand = np.clip(u + step * _STENCIL, 0.0, ring.U)
        vals = evaluate(cand)
        k = int(np.argmin(vals))
        if vals[k] < f - 1e-15:
            f, u = float(vals[k]), cand[k]
        else:
            step *= 0.5
    return f, u, False


def continuous_collapse(
    arch: PointedArch,
    density: float = 500.0,
    min_spacing: float = 0.0,
    effective_thickness: float = 1.0,
    load_sign: int = 1,
    grid: int = 36,
    n_starts: int = 4,
    contact: float = 1.0,
) -> ContinuousResult:
    """Minimum collapse multiplier of the continuous ring over admissible four-hinge layouts.

    ``min_spacing`` [rad of arch coordinate]: least spacing between consecutive hinges;
    ``effective_thickness``: fraction of ``t`` kept (about ``Rp``); ``contact``: fraction of each
    cut that touches (hinges within it, full self-weight). A ring that cannot stand
    under self-weight gives ``lam < 0`` and ``stands = False``; a refinement that fails is
    reported with the best value found (``converged = False``) and a warning.
    """
    _check_density(density)
    if load_sign not in (1, -1):
        raise ArchdemInputError(f"load_sign must be +1 or -1, got {load_sign!r}")
    if not (math.isfinite(min_spacing) and min_spacing >= 0):
        raise ArchdemInputError(f"minimum hinge spacing must be >= 0 rad, got {min_spacing!r}")
    ar = effective_arch(arch, effective_thickness)
    contact = check_contact(contact)
    ring = RingCuts(ar, contact)
    if 3 * min_spacing >= ring.U:
        raise ArchdemInputError(f"minimum hinge spacing {min_spacing:g} rad leaves no room for four hinges "
                                f"(arch coordinate length {ring.U:.4g} rad)")
    cands = _grid_search(ring, grid, min_spacing, load_sign)
    if not cands:
        return ContinuousResult(math.inf, None, np.full(4, np.nan), PATTERNS[0], None, False, True,  # type: ignore[arg-type]
                                "no admissible four-hinge layout found", effective_thickness, min_spacing, load_sign,
                                contact)
    grid_best = cands[0][0]
    best = (grid_best, cands[0][1], cands[0][2])
    any_success = False
    seen = []
    for lam0, u0, pat in cands:
        if len(seen) >= n_starts:
            break
        if any(p == pat and np.allclose(u0, q, atol=2.5 * ring.U / grid) for q, p in seen):
            continue
        seen.append((u0, pat))
        faces = np.array([_FACE_INDEX[f] for f in pat])
        lam1, u1, ok = _pattern_search(ring, u0, faces, ring.U / (grid - 1), min_spacing, load_sign)
        any_success |= ok
        if lam1 < best[0]:
            best = (lam1, u1, pat)
    lam, u, pat = best
    converged = any_success and lam <= grid_best + 1e-12
    msg = "ok"
    if not converged:
        msg = f"optimiser did not converge; best value found lambda = {lam:.6g}"
        warnings.warn(f"continuous_collapse: {msg}", RuntimeWarning, stacklevel=2)
    if lam < 0:
        msg = f"the ring cannot stand under self-weight (lambda = {lam:.4g} < 0)" + ("" if converged else "; " + msg)
    layout = layout_of(ar, u, pat, density, contact)
    return ContinuousResult(lam, layout.hinges, u, pat, layout, converged, lam >= 0, msg,
                            float(effective_thickness), float(min_spacing), load_sign, contact)


def hinge_polar_angles(arch: PointedArch, hinges) -> np.ndarray:
    """Polar angles about O of the hinge points [rad] (0 at the right springing, pi at the left)."""
    return np.array([h.polar_about_origin(arch) for h in hinges])
