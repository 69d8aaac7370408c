"""Imperfect fit of hand-cut blocks: contact lost along the edges of the joints (docs/physics/geometry.md#13-imperfect-fit).

A joint of depth ``L`` touches over the band ``[d_i, L - d_e]``: the strips ``d_i`` (intrados
edge) and ``d_e`` (extrados edge) are lost to chipped or rounded edges, faces out of plane or out
of angle. The **nominal** model loses the same width ``edge_loss`` at both edges of every joint,
which is the effective contact ``c = 1 - 2 edge_loss / L`` of :func:`specimens.blocks.discretise`.
A **realisation** draws each edge's loss independently, normal about ``edge_loss`` with standard
deviation ``edge_loss_sd`` (truncated at 0), from a seeded generator: realisation ``k`` of seed
``S`` is the same on every machine.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from specimens.blocks import Assembly, check_contact, discretise
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch

#: Least contact a realised joint keeps (fraction of its depth); larger drawn losses are scaled down to it.
MIN_CONTACT = 0.1


@dataclass(frozen=True)
class Imperfection:
    """Edge losses of the joints [m]: mean ``edge_loss`` and scatter ``edge_loss_sd`` per edge."""

    edge_loss: float = 0.0
    edge_loss_sd: float = 0.0

    def __post_init__(self) -> None:
        for name in ("edge_loss", "edge_loss_sd"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                raise ArchdemInputError(f"{name.replace('_', ' ')} must be a length >= 0 [m], got {v!r}")

    @classmethod
    def from_contact(cls, arch: PointedArch, contact: float, edge_loss_sd: float = 0.0) -> "Imperfection":
        """The nominal edge loss that leaves ``arch``'s joints the contact fraction ``contact`` (the
        inverse of :meth:`contact`), with the scatter ``edge_loss_sd`` [m]."""
        return cls(edge_loss=(1.0 - check_contact(contact)) * arch.t / 2, edge_loss_sd=edge_loss_sd)

    def contact(self, arch: PointedArch) -> float:
        """The nominal effective contact of ``arch``'s joints (radial joints: depth ``t``)."""
        c = 1.0 - 2.0 * self.edge_loss / arch.t
        if c < MIN_CONTACT:
            raise ArchdemInputError(f"an edge loss of {self.edge_loss * 1e3:g} mm leaves less than "
                                    f"{MIN_CONTACT:g} of the {arch.t * 1e3:g} mm joints in contact")
        return check_contact(c)

    def bands(self, assembly: Assembly, seed: int, realisation: int = 0) -> dict[str, tuple[float, float]]:
        """Contact bands (fractions of each joint's depth from its intrados end) of one realisation."""
        rng = np.random.default_rng([int(seed), int(realisation)])
        out = {}
        for j in assembly.joints:
            L = j.length
            d = np.maximum(rng.normal(self.edge_loss, self.edge_loss_sd, 2), 0.0) / L
            if d.sum() > 1.0 - MIN_CONTACT:
                d *= (1.0 - MIN_CONTACT) / d.sum()
            out[j.name] = (float(d[0]), float(1.0 - d[1]))
        return out


def realise(arch: PointedArch, imperfection: Imperfection, seed: int | None, realisation: int = 0,
            **discretise_kw) -> Assembly:
    """The assembly of ``arch`` with ``imperfection``: nominal (``seed=None`` or no scatter) or
    realisation ``realisation`` of ``seed``; ``discretise_kw`` as :func:`specimens.blocks.discretise`
    (without ``contact``)."""
    if "contact" in discretise_kw:
        raise ArchdemInputError("give the contact through the imperfection's edge loss, not both")
    nominal = discretise(arch, contact=imperfection.contact(arch), **discretise_kw)
    if seed is None or imperfection.edge_loss_sd == 0.0:
        return nominal
    return discretise(arch, contact=nominal.contact, bands=imperfection.bands(nominal, seed, realisation), **discretise_kw)


def realise_drawn(assembly: Assembly, imperfection: Imperfection, seed: int | None, realisation: int = 0) -> Assembly:
    """A drawn assembly (:mod:`specimens.drawn`, full blocks) with ``imperfection``: every joint loses
    ``edge_loss`` at each edge (nominal: ``seed=None`` or no scatter), or realisation ``realisation``
    of ``seed``; its joints have their own depths, so the nominal contact is per joint."""
    if imperfection.edge_loss == 0.0 and (seed is None or imperfection.edge_loss_sd == 0.0):
        return assembly
    sd = 0.0 if seed is None else imperfection.edge_loss_sd
    bands = Imperfection(imperfection.edge_loss, sd).bands(assembly, 0 if seed is None else seed, realisation)
    for j in assembly.joints:
        if 2.0 * imperfection.edge_loss > (1.0 - MIN_CONTACT) * j.length:
            raise ArchdemInputError(f"an edge loss of {imperfection.edge_loss * 1e3:g} mm leaves less than "
                                    f"{MIN_CONTACT:g} of joint {j.name} ({j.length * 1e3:.4g} mm) in contact")
    return assembly.with_bands(bands)


__all__ = ["Imperfection", "realise", "realise_drawn", "MIN_CONTACT"]
