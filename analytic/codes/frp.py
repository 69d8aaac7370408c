"""Limit analysis of an arch strengthened with FRP strips (docs/physics/assessment.md#5-frp-strips).

Strips bonded along the ring's extrados (or intrados), from springing to springing, cross every
joint of the ring; at a joint whose hinge opens on the strips' side they carry their design force
``T = f_fd t_f w_f``. In the static LP that is a tension down to ``-T`` allowed at the joint's end on
that side; in the kinematic form it is the work ``T c |dtheta|`` of a hinge turning by
``dtheta`` with the strip a distance ``c`` (the joint's depth) from the hinge. The strips end at the
springing joints (no anchorage into the base or the piers). Sliding is not considered (mu = inf).

The design strength ``f_fd`` follows the guideline for FRP on masonry (docs/physics/assessment.md#5-frp-strips):
rupture ``eta_a f_fk / gamma_f``; with the masonry's strengths and the strip's modulus, end debonding
``f_fdd = sqrt(2 E_f Gamma_Fd / t_f) / gamma_fd`` (reduced within the optimal bond length of the
strip's ends) and intermediate debonding at a joint ``f_fdd2 = k_q sqrt(2 E_f Gamma_Fd2 / t_f) / gamma_fd``;
the least governs each joint. A design strength given by the user wins.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from analytic.limit import ties
from specimens.blocks import DEFAULT_DENSITY, discretise
from foundation.errors import ArchdemInputError

#: Partial factor on the strips' rupture strength, per application type (A: certified system, B: other).
GAMMA_F = {"A": 1.10, "B": 1.25}
#: Partial factor on debonding, per application type.
GAMMA_FD = {"A": 1.20, "B": 1.50}
#: Kept for callers: the rupture partial factor of application type A.
GAMMA_FRP = GAMMA_F["A"]
#: Environmental conversion factor eta_a per exposure and fibre.
ETA_A = {"internal": {"glass": 0.75, "carbon": 0.95, "aramid": 0.85},
         "external": {"glass": 0.65, "carbon": 0.85, "aramid": 0.75},
         "aggressive": {"glass": 0.50, "carbon": 0.85, "aramid": 0.70}}
#: Correction factors of the specific fracture energy on masonry [m]: end and intermediate debonding.
#: UNVERIFIED against CNR-DT 200 R1/2013 §5.3: the defaults of :class:`BondFactors` (overridable).
K_G_END, K_G_INTERMEDIATE = 0.031e-3, 0.093e-3
#: Load-distribution factor of intermediate debonding (1: no load distributed along the strip).
K_Q = 1.0
#: Ultimate slip of the bond law [m], the bond's model factor and the least optimal bond length [m].
#: UNVERIFIED against the guideline: the defaults of :class:`BondFactors` (overridable).
SLIP_U, GAMMA_RD, L_ED_MIN = 0.4e-3, 1.5, 0.150
#: Least ratio b_f / b in the width factor k_b.
BF_B_MIN = 0.25
#: Masonry types: compressive strength range [Pa] of the code's table for existing masonry; the
#: tensile strength is taken as a tenth of the compressive one.
MASONRY_TYPES = {"solid-brick-lime": (2.6e6, 4.3e6)}
#: UNVERIFIED: the default of :attr:`BondFactors.fmt_ratio` (overridable).
MASONRY_TENSILE_RATIO = 0.10
#: Accepted masonry strengths [Pa] (beyond them a typo, not a masonry).
FM_RANGE, FMT_MAX_RATIO = (0.5e6, 20e6), 1.0 / 3.0
#: Masonry's partial factor in the crushing check of the strengthened ring's hinges.
GAMMA_M = 2.0
#: Voussoirs per side of the fine ring on which the strengthened mechanism is sought.
N_RING = 96


def _positive(name: str, v, lo: float, hi: float, unit: str = "") -> float:
    if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and lo <= v <= hi):
        raise ArchdemInputError(f"{name} must be a number from {lo:g} to {hi:g}{unit}, got {v!r}")
    return float(v)


#: Words beside a bond factor in the records: the unverified default, or a value the user set.
UNVERIFIED_DEFAULT, USER_SET = "unverified default", "set by the user"


@dataclass(frozen=True)
class BondFactors:
    """The bond and debonding factors of CNR-DT 200 R1/2013 §5.3 (FRP on masonry), each overridable by
    an engineer holding the guideline. The defaults are the module constants and are UNVERIFIED
    against the guideline's text (docs/physics/assessment.md#5-frp-strips).

    ``k_G`` [m]: correction factor of the specific fracture energy, end debonding (default 0.031 mm);
    ``k_G2`` [m]: the same, intermediate debonding (default 0.093 mm);
    ``s_u`` [m]: ultimate slip of the bond law, in ``f_bd = 2 Gamma_Fd / s_u`` (default 0.4 mm);
    ``gamma_Rd`` [-]: model factor of the optimal bond length (default 1.5);
    ``l_ed_min`` [m]: least optimal bond length (default 150 mm);
    ``fmt_ratio`` [-]: the masonry's mean tensile strength ``f_mtm`` as a share of its compressive
    ``f_mm`` when not measured, for a named masonry type (default 0.10);
    ``user_set``: the names the user set (a value other than its default counts as set anyway)."""

    k_G: float = K_G_END
    k_G2: float = K_G_INTERMEDIATE
    s_u: float = SLIP_U
    gamma_Rd: float = GAMMA_RD
    l_ed_min: float = L_ED_MIN
    fmt_ratio: float = MASONRY_TENSILE_RATIO
    user_set: frozenset = frozenset()

    #: (field, symbol, unit of the records, scale from SI to it, accepted range in SI)
    FIELDS = (("k_G", "k_G", "mm", 1e3, (0.0, 1e-3)), ("k_G2", "k_G2", "mm", 1e3, (0.0, 1e-3)),
              ("s_u", "s_u", "mm", 1e3, (0.0, 5e-3)), ("gamma_Rd", "gamma_Rd", "-", 1.0, (1.0, 3.0)),
              ("l_ed_min", "l_ed_min", "mm", 1e3, (0.0, 1.0)), ("fmt_ratio", "f_mtm/f_mm", "-", 1.0, (0.0, FMT_MAX_RATIO)))

    def __post_init__(self) -> None:
        for name, sym, unit, k, (lo, hi) in self.FIELDS:
            v = getattr(self, name)
            # gamma_Rd may equal its least value 1; the others must be positive
            ok = (not isinstance(v, bool) and isinstance(v, (int, float)) and math.isfinite(v)
                  and (lo <= v if lo > 0 else lo < v) and v <= hi)
            if not ok:
                u = "" if unit == "-" else f" {unit}"
                num = isinstance(v, (int, float)) and not isinstance(v, bool)
                raise ArchdemInputError(f"FRP bond factor {sym} (CNR-DT 200 R1/2013) must be in "
                                        f"{'[' if lo > 0 else '('}{lo * k:g}, {hi * k:.4g}]{u}, "
                                        f"got {f'{v * k:g}{u}' if num else repr(v)}")
        unknown = set(self.user_set) - {f[0] for f in self.FIELDS}
        if unknown:
            raise ArchdemInputError(f"unknown FRP bond factor(s) {', '.join(sorted(unknown))}")
        changed = {f[0] for f in self.FIELDS if getattr(self, f[0]) != getattr(BondFactors, f[0])}
        object.__setattr__(self, "user_set", frozenset(self.user_set) | changed)

    @classmethod
    def given(cls, **values) -> "BondFactors":
        """The factors with those of ``values`` that are not None set by the user (SI units)."""
        kw = {k: v for k, v in values.items() if v is not None}
        return cls(**kw, user_set=frozenset(kw))

    def source(self, name: str) -> str:
        """"set by the user" or "unverified default"."""
        return USER_SET if name in self.user_set else UNVERIFIED_DEFAULT

    @property
    def all_default(self) -> bool:
        return not self.user_set

    def describe(self) -> dict:
        """Each factor: its value in the unit of the records, the unit, and whether it is the
        unverified default or was set by the user."""
        return {name: {"symbol": sym, "value": getattr(self, name) * k, "unit": unit, "source": self.source(name)}
                for name, sym, unit, k, _ in self.FIELDS}

    def text(self, fmt_ratio: bool = True) -> str:
        """One line: each factor with "(unverified default)" beside the defaults (``fmt_ratio`` False:
        without the tensile ratio, where the masonry's tensile strength is given)."""
        parts = []
        for name, sym, unit, k, _ in self.FIELDS:
            if name == "fmt_ratio" and not fmt_ratio:
                continue
            u = "" if unit == "-" else f" {unit}"
            tag = " (unverified default)" if name not in self.user_set else " (set by the user)"
            parts.append(f"{sym} {getattr(self, name) * k:g}{u}{tag}")
        return ", ".join(parts)


@dataclass(frozen=True)
class Masonry:
    """The substrate's mean compressive ``fm`` and tensile ``fmt`` strengths [Pa]; ``name``: where they come from."""

    fm: float
    fmt: float
    name: str = "given"

    def __post_init__(self) -> None:
        lo, hi = FM_RANGE
        if isinstance(self.fm, bool) or not (isinstance(self.fm, (int, float)) and math.isfinite(self.fm)
                                             and lo <= self.fm <= hi):
            raise ArchdemInputError(f"masonry compressive strength fm must be from {lo / 1e6:g} to {hi / 1e6:g} MPa, "
                                    f"got {self.fm!r} Pa")
        if isinstance(self.fmt, bool) or not (isinstance(self.fmt, (int, float)) and math.isfinite(self.fmt)
                                              and 0 < self.fmt <= FMT_MAX_RATIO * self.fm):
            raise ArchdemInputError(f"masonry tensile strength fmt must be in (0, fm / 3 = "
                                    f"{FMT_MAX_RATIO * self.fm / 1e6:.3g} MPa], got {self.fmt!r}")

    def describe(self) -> dict:
        return {"name": self.name, "fm_MPa": self.fm / 1e6, "fmt_MPa": self.fmt / 1e6}


def masonry_type(name: str, FC: float, bond: BondFactors | None = None) -> Masonry:
    """A named masonry of :data:`MASONRY_TYPES`: at knowledge level LC1 (``FC >= 1.35``) the least
    compressive strength of its range, else the middle of the range; tensile ``bond.fmt_ratio`` of it
    (default a tenth, unverified)."""
    if name not in MASONRY_TYPES:
        raise ArchdemInputError(f"unknown masonry type {name!r}; known: {', '.join(MASONRY_TYPES)} "
                                f"(or FM_MPA,FMT_MPA)")
    bond = BondFactors() if bond is None else bond
    lo, hi = MASONRY_TYPES[name]
    fm = lo if FC >= 1.35 else 0.5 * (lo + hi)
    level = "LC1: least of" if FC >= 1.35 else "middle of"
    ratio = bond.fmt_ratio
    return Masonry(fm, ratio * fm, f"{name} ({level} {lo / 1e6:g}-{hi / 1e6:g} MPa, fmt = {ratio:g} fm, "
                                   f"{bond.source('fmt_ratio')})")


@dataclass(frozen=True)
class Strips:
    """FRP strips on one ``face`` ("extrados"/"intrados") of the ring: characteristic tensile
    ``strength`` f_fk [Pa], ``thickness`` t_f [m] (equivalent dry-fibre thickness), total ``width``
    b_f [m] across the ring; ``design_strength`` [Pa] given by the designer (wins over the rules);
    ``modulus`` E_f [Pa], ``fibre`` (carbon/glass/aramid), ``exposure`` (internal/external/aggressive),
    ``application`` type (A/B), the substrate ``masonry`` and the confidence factor ``FC`` of its
    strengths: the guideline's design values (module doc); ``bond``: the guideline's bond and
    debonding factors (:class:`BondFactors`, unverified defaults unless set)."""

    strength: float
    thickness: float
    width: float
    face: str = "extrados"
    design_strength: float | None = None
    modulus: float | None = None
    fibre: str = "carbon"
    exposure: str = "external"
    application: str = "A"
    masonry: Masonry | None = None
    FC: float = 1.35
    bond: BondFactors = BondFactors()

    def __post_init__(self) -> None:
        if not isinstance(self.bond, BondFactors):
            raise ArchdemInputError(f"FRP bond factors must be a BondFactors, got {self.bond!r}")
        for name, v, hi in (("strength", self.strength, 1e11), ("thickness", self.thickness, 0.1),
                            ("width", self.width, 100.0)):
            if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and 0 < v <= hi):
                raise ArchdemInputError(f"FRP {name} must be a positive number up to {hi:g} (SI), got {v!r}")
        if self.face not in ("extrados", "intrados"):
            raise ArchdemInputError(f"FRP face must be extrados or intrados, got {self.face!r}")
        fd = self.design_strength
        if fd is not None and not (isinstance(fd, (int, float)) and math.isfinite(fd) and 0 < fd <= self.strength):
            raise ArchdemInputError(f"FRP design strength must be in (0, strength = {self.strength / 1e6:g} MPa], "
                                    f"got {fd!r}")
        if self.exposure not in ETA_A:
            raise ArchdemInputError(f"FRP exposure must be one of {', '.join(ETA_A)}, got {self.exposure!r}")
        if self.fibre not in ETA_A["internal"]:
            raise ArchdemInputError(f"FRP fibre must be one of {', '.join(ETA_A['internal'])}, got {self.fibre!r}")
        if self.application not in GAMMA_F:
            raise ArchdemInputError(f"FRP application type must be A or B, got {self.application!r}")
        if self.modulus is not None and (isinstance(self.modulus, bool) or not (
                isinstance(self.modulus, (int, float)) and 10e9 <= self.modulus <= 700e9)):
            raise ArchdemInputError(f"FRP modulus E_f must be from 10 to 700 GPa, got {self.modulus!r} Pa")
        if self.masonry is not None and self.modulus is None:
            raise ArchdemInputError("debonding from the masonry needs the strips' modulus E_f")
        _positive("confidence factor FC", self.FC, 1.0, 3.0)

    @property
    def design_rupture(self) -> float:
        """``f_fd = eta_a f_fk / gamma_f`` [Pa]."""
        return ETA_A[self.exposure][self.fibre] * self.strength / GAMMA_F[self.application]

    def design(self, substrate_width: float | None = None) -> "StripDesign":
        """The guideline's design values of the strips on a masonry element ``substrate_width`` b [m] wide."""
        return strip_design(self, substrate_width)

    @property
    def design_stress(self) -> float:
        """``f_fd`` [Pa] away from the strips' ends (the governing one; b = b_f when unknown)."""
        return self.design().governing_stress

    @property
    def force(self) -> float:
        """Design force ``T = f_fd t_f w_f`` [N] of the strips crossing one joint away from their ends."""
        return self.design_stress * self.thickness * self.width

    def describe(self, substrate_width: float | None = None) -> dict:
        d = self.design(substrate_width)
        return {"face": self.face, "strength_MPa": self.strength / 1e6, "thickness_mm": self.thickness * 1e3,
                "width_mm": self.width * 1e3, "modulus_GPa": None if self.modulus is None else self.modulus / 1e9,
                "fibre": self.fibre, "exposure": self.exposure, "application": self.application,
                "masonry": None if self.masonry is None else self.masonry.describe(),
                "design_strength_MPa": d.governing_stress / 1e6, "governing": d.governing, "force_N": d.force,
                "bond_factors": self.bond.describe(), "design": d.describe()}


@dataclass(frozen=True)
class StripDesign:
    """The guideline's steps (SI): ``eta_a``, ``gamma_f``, rupture ``f_rupture``; with masonry:
    ``k_b``, ``Gamma_Fd`` and ``Gamma_Fd2`` [N/m = J/m^2], ``gamma_fd``, end ``f_end`` and
    intermediate ``f_intermediate`` debonding, the optimal bond length ``l_ed`` [m]; ``given``: the
    user's design strength; ``governing``: the name of the least (or "given")."""

    strips: Strips
    eta_a: float
    gamma_f: float
    f_rupture: float
    k_b: float | None = None
    Gamma_Fd: float | None = None
    Gamma_Fd2: float | None = None
    gamma_fd: float | None = None
    f_end: float | None = None
    f_intermediate: float | None = None
    l_ed: float | None = None
    given: float | None = None

    @property
    def candidates(self) -> dict[str, float]:
        out = {"rupture": self.f_rupture}
        if self.f_intermediate is not None:
            out["intermediate debonding"] = self.f_intermediate
        return out

    @property
    def governing(self) -> str:
        if self.given is not None:
            return "given"
        c = self.candidates
        return min(c, key=c.get)

    @property
    def governing_stress(self) -> float:
        """``f_fd`` [Pa] at a joint away from the strips' ends."""
        return float(self.given if self.given is not None else min(self.candidates.values()))

    @property
    def force(self) -> float:
        return self.governing_stress * self.strips.thickness * self.strips.width

    def at(self, s: float) -> tuple[float, str]:
        """``(f_fd [Pa], governing mode)`` at a joint ``s`` [m] along the strip from its nearer end: within
        the optimal bond length the end's anchorage ``f_fdd (s / l_ed)(2 - s / l_ed)`` also bounds it."""
        if self.given is not None:
            return float(self.given), "given"
        c = dict(self.candidates)
        if self.f_end is not None and s < self.l_ed:
            r = max(s, 0.0) / self.l_ed
            c["end debonding"] = self.f_end * r * (2.0 - r)
        k = min(c, key=c.get)
        return float(c[k]), k

    def describe(self) -> dict:
        """Every step with its unit and formula."""
        st = self.strips
        out = {"eta_a": {"value": self.eta_a, "unit": "-", "formula": f"environmental factor ({st.exposure}, {st.fibre})"},
               "gamma_f": {"value": self.gamma_f, "unit": "-", "formula": f"rupture partial factor (application {st.application})"},
               "f_rupture": {"value": self.f_rupture / 1e6, "unit": "MPa", "formula": "eta_a f_fk / gamma_f"}}
        if self.Gamma_Fd is not None:
            m, bf = st.masonry, st.bond
            out.update({
                "f_mm": {"value": m.fm / 1e6, "unit": "MPa", "formula": m.name},
                "f_mtm": {"value": m.fmt / 1e6, "unit": "MPa", "formula": m.name},
                "k_b": {"value": self.k_b, "unit": "-", "formula": "sqrt((3 - b_f/b) / (1 + b_f/b)) >= 1, b_f/b >= 0.25"},
                "k_G": {"value": bf.k_G * 1e3, "unit": "mm", "formula": f"end debonding ({bf.source('k_G')})"},
                "k_G2": {"value": bf.k_G2 * 1e3, "unit": "mm",
                         "formula": f"intermediate debonding ({bf.source('k_G2')})"},
                "Gamma_Fd": {"value": self.Gamma_Fd / 1e3, "unit": "N/mm", "formula": "k_b k_G / FC sqrt(f_mm f_mtm)"},
                "Gamma_Fd2": {"value": self.Gamma_Fd2 / 1e3, "unit": "N/mm", "formula": "k_b k_G2 / FC sqrt(f_mm f_mtm)"},
                "gamma_fd": {"value": self.gamma_fd, "unit": "-", "formula": f"debonding partial factor (application {st.application})"},
                "f_end": {"value": self.f_end / 1e6, "unit": "MPa", "formula": "sqrt(2 E_f Gamma_Fd / t_f) / gamma_fd"},
                "f_intermediate": {"value": self.f_intermediate / 1e6, "unit": "MPa",
                                   "formula": "k_q sqrt(2 E_f Gamma_Fd2 / t_f) / gamma_fd"},
                "s_u": {"value": bf.s_u * 1e3, "unit": "mm", "formula": f"ultimate slip of the bond law ({bf.source('s_u')})"},
                "gamma_Rd": {"value": bf.gamma_Rd, "unit": "-", "formula": f"model factor ({bf.source('gamma_Rd')})"},
                "l_ed_min": {"value": bf.l_ed_min * 1e3, "unit": "mm",
                             "formula": f"least optimal bond length ({bf.source('l_ed_min')})"},
                "l_ed": {"value": self.l_ed * 1e3, "unit": "mm",
                         "formula": "max(sqrt(pi^2 E_f t_f Gamma_Fd / 2) / (gamma_Rd f_bd), l_ed_min), f_bd = 2 Gamma_Fd / s_u"}})
        if self.given is not None:
            out["f_given"] = {"value": self.given / 1e6, "unit": "MPa", "formula": "the designer's design strength"}
        out["f_fd"] = {"value": self.governing_stress / 1e6, "unit": "MPa", "formula": f"governing: {self.governing}"}
        out["T"] = {"value": self.force / 1e3, "unit": "kN", "formula": "f_fd t_f b_f"}
        return out


def strip_design(strips: Strips, substrate_width: float | None = None) -> StripDesign:
    """The guideline's design values of ``strips`` (module doc) on a masonry element ``substrate_width``
    b [m] wide (None: b = b_f, k_b = 1)."""
    eta, gf = ETA_A[strips.exposure][strips.fibre], GAMMA_F[strips.application]
    base = dict(strips=strips, eta_a=eta, gamma_f=gf, f_rupture=eta * strips.strength / gf,
                given=strips.design_strength)
    m = strips.masonry
    if m is None:
        return StripDesign(**base)
    b = strips.width if substrate_width is None else float(substrate_width)
    ratio = min(1.0, max(BF_B_MIN, strips.width / b))
    k_b = max(1.0, math.sqrt((3.0 - ratio) / (1.0 + ratio)))
    # the guideline's fracture energy is in N/mm with strengths in MPa and k_G in mm: in SI, N/m
    bf = strips.bond  # the guideline's bond factors: unverified defaults unless the user set them
    root = math.sqrt(m.fm * m.fmt)
    G1 = k_b * bf.k_G / strips.FC * root
    G2 = k_b * bf.k_G2 / strips.FC * root
    gfd = GAMMA_FD[strips.application]
    E, t = strips.modulus, strips.thickness
    f_end = math.sqrt(2 * E * G1 / t) / gfd
    f_int = K_Q * math.sqrt(2 * E * G2 / t) / gfd
    f_bd = 2 * G1 / bf.s_u
    l_ed = max(math.sqrt(math.pi ** 2 * E * t * G1 / 2) / (bf.gamma_Rd * f_bd), bf.l_ed_min)
    return StripDesign(**base, k_b=k_b, Gamma_Fd=G1, Gamma_Fd2=G2, gamma_fd=gfd, f_end=f_end, f_intermediate=f_int,
                       l_ed=l_ed)


def strip_joint(joint) -> bool:
    """Strips cross the ring's joints, not the springings nor the piers."""
    return not joint.in_pier and joint.name not in ("L0", "R0")


def strip_distances(assembly, face: str) -> dict[str, float]:
    """Distance [m] along the strip (the polyline of the ring joints' ends on ``face``) from each ring
    joint to the nearer end of the strips (the springing joints)."""
    k = 1 if face == "extrados" else 0
    ring = [j for j in assembly.joints if not j.in_pier]
    pts = np.array([j.contact_points[k] for j in ring])
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))])
    return {j.name: float(min(si, s[-1] - si)) for j, si in zip(ring, s)}


def joint_forces(assembly, strips: Strips) -> dict[str, dict]:
    """Per strip joint: its distance ``s`` [m] from the strips' nearer end, design stress ``f_fd`` [Pa],
    force ``T`` [N] and the governing ``mode``."""
    d = strips.design(float(assembly.arch.width))
    dist = strip_distances(assembly, strips.face)
    out = {}
    for j in assembly.joints:
        if strip_joint(j):
            f, criterion = d.at(dist[j.name])
            out[j.name] = {"s": dist[j.name], "f_fd": f, "T": f * strips.thickness * strips.width, "mode": criterion}
    return out


def tension_of(assembly, strips: Strips, forces: dict[str, dict] | None = None) -> np.ndarray:
    """(n_joints, 2) tension [N] each joint carries at its intrados / extrados end."""
    k = 1 if strips.face == "extrados" else 0
    forces = joint_forces(assembly, strips) if forces is None else forces
    T = np.zeros((len(assembly.joints), 2))
    for j in assembly.joints:
        if j.name in forces:
            T[j.index, k] = forces[j.name]["T"]
    return T


@dataclass(frozen=True)
class StrengthenedCollapse:
    """``lam``: multiplier of the strengthened arch (under the loads of ``strengthened_collapse``);
    ``hinges``: (joint, face) left to right; ``mechanism``: its four-bar; ``assembly``: the fine cut;
    ``strips``; ``forces``: per strip joint its design force (:func:`joint_forces`); ``lp_forces``:
    the LP's contact forces at collapse per joint [N]."""

    lam: float
    hinges: tuple[tuple[str, str], ...]
    mechanism: object  # a FourBar or a RigidRotation
    assembly: object
    strips: Strips | None
    forces: dict | None = None
    lp_forces: dict | None = None
    tie: object = None  # an analytic.limit.ties.Tie
    tie_link: object = None  # its analytic.limit.ties.TieLink on the fine cut
    tie_lp_force: float | None = None

    def tie_force(self, phi: float) -> float:
        """Generalised force ``W'(phi)`` [J/rad] of the tie resisting the mechanism (yielding where it lengthens)."""
        if self.tie_link is None:
            return 0.0
        return ties.tie_force(self.mechanism, self.assembly, self.hinges, self.tie_link, phi)

    def extra_force(self, phi: float) -> float:
        """``W'(phi)`` [J/rad] of the strips and the tie together."""
        return self.strip_force(phi) + self.tie_force(phi)

    def strip_force(self, phi: float) -> float:
        """Generalised force ``W'(phi)`` [J/rad] of the strips resisting the mechanism at rotation ``phi``:
        ``sum T_k c_k cos(dtheta_k / 2) d(dtheta_k)/dphi sign(dtheta_k)`` over the hinges opening on their side."""
        if self.strips is None:
            return 0.0
        st = self.mechanism.body_states(phi)
        th = [0.0] + [b.theta for b in st] + [0.0]  # hinge k joins body k-1 (or the ground) to body k
        w = [0.0] + [b.dtheta for b in st] + [0.0]
        forces = self.forces if self.forces is not None else joint_forces(self.assembly, self.strips)
        out = 0.0
        for k, (name, face) in enumerate(self.hinges):
            j = self.assembly.joint(name)
            if not strip_joint(j) or face == self.strips.face:
                continue
            c = float(np.linalg.norm(j.contact_points[1] - j.contact_points[0]))
            rel, drel = th[k + 1] - th[k], w[k + 1] - w[k]
            sign = math.copysign(1.0, drel if abs(rel) < 1e-12 else rel)  # the gap opens either way of turning
            out += forces[name]["T"] * c * math.cos(rel / 2) * sign * drel
        return out

    def strip_hinges(self) -> list[dict]:
        """The hinges the strips hold (opening on their side): joint, force and its governing mode."""
        if self.strips is None:
            return []
        return [{"joint": n, "face": f, **self.forces[n]} for n, f in self.hinges
                if n in self.forces and f != self.strips.face]

    def crushing(self, masonry: Masonry | None, FC: float) -> list[dict] | None:
        """The masonry's compression at each hinge of the collapse (LP forces): the resultant ``C`` [N]
        at the hinge's end, the depth ``y = C / (0.85 f_md w)`` of the stress block that carries it
        (``f_md = f_m / (FC gamma_M)``), against the joint's depth ``t``; None without masonry."""
        if masonry is None or self.lp_forces is None:
            return None
        f_md = masonry.fm / (FC * GAMMA_M)
        w = float(self.assembly.arch.width)
        out = []
        for name, face in self.hinges:
            j = self.assembly.joint(name)
            C = max(0.0, float(self.lp_forces[name]["N_" + face]))
            t = float(np.linalg.norm(j.contact_points[1] - j.contact_points[0]))
            y = C / (0.85 * f_md * w)
            out.append({"joint": name, "face": face, "C_kN": C / 1e3, "f_md_MPa": f_md / 1e6, "y_mm": y * 1e3,
                        "t_mm": t * 1e3, "ratio": y / t, "verified": bool(y <= t)})
        return out


def strengthened_collapse(arch, strips: Strips | None, density: float = DEFAULT_DENSITY, piers=None,
                          n_ring: int = N_RING, load_sign: int = -1, tie=None) -> StrengthenedCollapse:
    """The strengthened arch's (on ``piers`` or not; ``strips`` None: unreinforced) least multiplier
    and mechanism: the static LP with the strips' tension on the fine cut (``n_ring`` voussoirs per side; on piers the cut of
    :func:`analytic.limit.limit_piers.continuous_on_piers`), and the mechanism through its hinges (four, or
    one when the strips hold the ring whole and it turns on a springing); ``load_sign`` -1: loads along
    -x (those of a positive ground acceleration), +1 along +x; ``tie``: an :class:`analytic.limit.ties.Tie`
    across the structure."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import solve_lp
    from analytic.rocking.linkage import four_bar_through

    if getattr(arch, "arch", True) is None:  # a drawn assembly (specimens.drawn): no ring to cut finely
        raise ArchdemInputError("FRP strips are modelled on the fine cut of a two-centred ring; a drawing of blocks "
                                "has no ring to cut: assess it without --frp")
    if piers is None:
        asm = discretise(arch, n_voussoirs=n_ring, config="free", density=density)
    else:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.limit.limit_piers import fine_cut

        asm = fine_cut(arch, piers, n_ring, density, 1.0)
    forces = None if strips is None else joint_forces(asm, strips)
    link = None
    if tie is not None:
        link = ties.tie_link(asm, tie)
    lp = solve_lp(asm, math.inf, math.inf, load_sign=load_sign,
                  tension=None if strips is None else tension_of(asm, strips, forces), ties=() if link is None else (link,))
    if not lp.success:
        raise ArchdemInputError(f"strengthened arch: {lp.message}")
    if len(lp.hinges) not in (1, 4):
        why = ""
        if link is not None and lp.tie_forces[0] < (1 - 1e-6) * link.force:
            why = (f" (lambda = {lp.lam:.4g}: the tie holds without yielding, {lp.tie_forces[0] / 1e3:.4g} of "
                   f"{link.force / 1e3:.4g} kN, and keeps its length; a weaker tie yields)")
        raise ArchdemInputError(f"the strengthened arch's mechanism has {len(lp.hinges)} hinges, neither one nor "
                                f"four ({', '.join(f'{n}:{f}' for n, f in lp.hinges)}){why}; the kinematic "
                                f"assessment needs one of one or four hinges")
    what = " and ".join(w for w, x in (("FRP", strips), ("a tie", tie)) if x is not None)
    fb = four_bar_through(asm, lp.hinges, name=f"four-bar (with {what})" if what else "four-bar (fine cut)")
    return StrengthenedCollapse(float(lp.lam), lp.hinges, fb, asm, strips, forces, lp.forces, tie, link,
                                lp.tie_forces[0] if link is not None else None)
