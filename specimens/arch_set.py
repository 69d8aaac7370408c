"""Arches outside the catalogue: the set on which the tilt test is validated beyond the 11 specimens
(docs/validation.md#20-arches-outside-the-catalogue).

Round and pointed arches by parameters (spans 0.5-10 m, thickness from near the least that stands
to thick, 5-15 voussoirs, glued and free) and arches as a user draws them (DXF in mm, CSV, OBJ,
curved and straight-sided voussoirs, an irregular pointed arch, the shipped arch on piers). Every
member builds the blocks a tilt test runs and its limit analyses check; a drawn member writes its
drawing into a folder first and reads it back, the way a user's file is read.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from specimens.blocks import Assembly, discretise
from foundation.errors import ArchdemInputError
from specimens.geometry import PointedArch
from specimens.sections import signed_area

#: Out-of-plane depth of every member [m] (the tilt's lambda does not depend on it).
DEPTH = 0.1


@dataclass(frozen=True)
class SetArch:
    """One member: a two-centred arch (``Ri``, ``Re``, ``e`` [m], ``n`` voussoirs per side, ``config``)
    cut by :func:`specimens.blocks.discretise`, or drawn: ``drawing`` names the builder below and
    ``fmt`` the file written (``dxf``, ``csv``, ``obj``)."""

    name: str
    Ri: float = 0.0
    Re: float = 0.0
    e: float = 0.0
    n: int = 0
    config: str = "free"
    drawing: str = ""
    fmt: str = ""

    @property
    def drawn(self) -> bool:
        return bool(self.drawing)

    @property
    def arch(self) -> PointedArch | None:
        """The continuous ring of a member by parameters or of a regular drawn ring (its continuous LP applies)."""
        if self.drawing in ("", "ring", "ring-convex"):
            return PointedArch.from_radii(self.Ri, self.Re, self.e, width=DEPTH)
        return None

    @property
    def span(self) -> float:
        """Clear span [m] (intrados springings), NaN for the drawings without parameters."""
        return 2.0 * (self.Ri - self.e) if self.Ri else float("nan")

    @property
    def thickness_ratio(self) -> float:
        """Ring thickness over mean radius, t / Rp (a semicircle's least is about 0.107)."""
        return (self.Re - self.Ri) / (0.5 * (self.Ri + self.Re)) if self.Ri else float("nan")

    def assembly(self, folder: str | Path | None = None) -> Assembly:
        """The blocks; a drawn member is written into ``folder`` and read back from there."""
        if not self.drawn:
            return discretise(self.arch, n_voussoirs=self.n, config=self.config)
        if folder is None:
            raise ArchdemInputError(f"{self.name}: a drawn member needs a folder to write its drawing into")
        # deferred: the readers and writers import ezdxf
        from specimens.exchange import EXAMPLE_DRAWING, read_assembly

        if self.drawing == "survey":
            return read_assembly(EXAMPLE_DRAWING)
        path = Path(folder) / f"{self.name}.{self.fmt}"
        if not path.exists():
            _DRAW[self.drawing](self, path)
        return read_assembly(path)


def _ring_outlines(m: SetArch, shape: str) -> list[tuple[str, np.ndarray]]:
    asm = discretise(m.arch, n_voussoirs=m.n, config="free", shape=shape)
    return [(b.name, np.asarray(b.outline, float)) for b in asm.bodies]


def off_radial_joint(side: int, psi_deg: float, turn_deg: float, Ri: float, Re: float, e: float
                     ) -> tuple[np.ndarray, np.ndarray]:
    """Intrados and extrados ends of a surveyed joint of half ``side`` (-1 left, +1 right) of a two-centred
    ring (``Ri``, ``Re``, centres ``e`` off the axis): through the intrados point at polar angle ``psi``
    about its centre, along the radial turned by ``turn`` [deg], up to the extrados circle."""
    c = np.array([-side * e, 0.0])
    psi = math.radians(psi_deg)
    p_i = c + Ri * np.array([side * math.cos(psi), math.sin(psi)])
    ang = psi + math.radians(turn_deg) * side
    d = np.array([side * math.cos(ang), math.sin(ang)])
    # |p_i + s d - c| = Re
    b = float(d @ (p_i - c))
    s = -b + math.sqrt(b * b - float((p_i - c) @ (p_i - c)) + Re * Re)
    return p_i, p_i + s * d


def _irregular_outlines() -> list[tuple[str, np.ndarray]]:
    """A pointed arch as surveyed: 7 voussoirs on the left and 5 on the right, of unequal sizes, their
    joints turned a few degrees off the radial (Ri 1.6 m, Re 1.9 m, centres 0.4 m off the axis)."""
    Ri, Re, e = 1.6, 1.9, 0.4
    apex = math.degrees(math.acos(e / Ri))  # the intrados apex's polar angle about either centre
    left = [(0.0, 0.0), (11.0, 3.0), (19.0, -2.0), (31.0, 4.0), (40.0, -3.0), (49.0, 2.0), (62.0, -3.0), (apex, None)]
    right = [(0.0, 0.0), (16.0, -3.0), (28.0, 2.0), (45.0, -4.0), (57.0, 3.0), (apex, None)]

    def joint(side: int, psi_deg: float, turn: float | None) -> tuple[np.ndarray, np.ndarray]:
        if turn is None:  # the crown joint: vertical, from the intrados apex up to the extrados
            return off_radial_joint(side, psi_deg, 0.0, Ri, Re, e)[0], np.array([0.0, math.sqrt(Re * Re - e * e)])
        return off_radial_joint(side, psi_deg, turn, Ri, Re, e)

    out = []
    for side, tag, js in ((-1, "L", left), (1, "R", right)):
        ends = [joint(side, *j) for j in js]
        for k in range(1, len(ends)):
            (a_i, a_e), (b_i, b_e) = ends[k - 1], ends[k]
            out.append((f"{tag}{k}", np.array([a_i, b_i, b_e, a_e])))
    return out


def _write_dxf(outlines: list[tuple[str, np.ndarray]], path: Path, unit: str) -> None:
    """A drawing as a user makes one: closed polylines on a layer stating the depth, a name inside each
    block, the units in the header, no pieces and no ground (the ground is the lowest line)."""
    # deferred: only a drawn member needs ezdxf
    import ezdxf

    from specimens.exchange import DXF_UNITS, UNITS

    code = {v: k for k, v in DXF_UNITS.items()}[unit]
    f = 1.0 / UNITS[unit]
    doc = ezdxf.new(units=code)
    msp = doc.modelspace()
    layer = f"voussoirs depth {DEPTH * f:g}"
    for name, q in outlines:
        msp.add_lwpolyline((q * f).tolist(), format="xy", close=True, dxfattribs={"layer": layer})
        at = q.mean(axis=0) * f
        msp.add_text(name, dxfattribs={"layer": "labels", "insert": (float(at[0]), float(at[1])), "height": 20.0})
    doc.saveas(str(path))


def _write_csv(outlines: list[tuple[str, np.ndarray]], path: Path) -> None:
    lines = ["block,x,z,layer"]
    for name, q in outlines:
        lines += [f"{name},{x!r},{z!r},voussoirs depth {DEPTH!r}" for x, z in q.tolist()]
    path.write_text("\n".join(lines) + "\n")


def _write_obj(outlines: list[tuple[str, np.ndarray]], path: Path) -> None:
    """Each block a prism ``DEPTH`` deep (z) with its outline as front and back faces; convex outlines only."""
    lines, nv = [], 0
    for name, q in outlines:
        q = q if signed_area(q) > 0 else q[::-1]
        n = len(q)
        lines.append(f"o {name}")
        for z in (-DEPTH / 2, DEPTH / 2):
            lines += [f"v {x!r} {y!r} {z!r}" for x, y in q.tolist()]
        f = [nv + 1 + k for k in range(n)]
        b = [nv + 1 + n + k for k in range(n)]
        lines += ["f " + " ".join(map(str, reversed(f))), "f " + " ".join(map(str, b))]
        lines += [f"f {f[k]} {f[(k + 1) % n]} {b[(k + 1) % n]} {b[k]}" for k in range(n)]
        nv += 2 * n
    path.write_text("\n".join(lines) + "\n")


def _draw_ring(m: SetArch, path: Path, shape: str) -> None:
    outlines = _ring_outlines(m, shape)
    if m.fmt == "dxf":
        _write_dxf(outlines, path, "mm")
    elif m.fmt == "csv":
        _write_csv(outlines, path)
    else:
        _write_obj(outlines, path)


def _draw_irregular(m: SetArch, path: Path) -> None:
    _write_dxf(_irregular_outlines(), path, "m")


_DRAW = {
    "ring": lambda m, p: _draw_ring(m, p, "curved"),  # voussoirs with arcs (non-convex blocks)
    "ring-convex": lambda m, p: _draw_ring(m, p, "linearised"),  # straight-sided voussoirs
    "irregular": _draw_irregular,
}

#: The set: by parameters (round e = 0, pointed e > 0), then drawn.
ARCH_SET: tuple[SetArch, ...] = (
    SetArch("round-2m-thin-free", 1.0, 1.15, 0.0, 5, "free"),
    SetArch("round-2m-thin-glued", 1.0, 1.15, 0.0, 5, "glued"),
    SetArch("round-0.5m-thin-free", 0.25, 0.284, 0.0, 7, "free"),
    SetArch("round-10m-glued", 5.0, 5.8, 0.0, 7, "glued"),
    SetArch("round-4m-15v-free", 2.0, 2.25, 0.0, 7, "free"),
    SetArch("round-2m-thick-5v-free", 1.0, 1.4, 0.0, 2, "free"),
    SetArch("pointed-2m-free", 1.25, 1.45, 0.25, 6, "free"),
    SetArch("pointed-0.5m-thin-glued", 0.3125, 0.34, 0.0625, 5, "glued"),
    SetArch("pointed-10m-free", 6.25, 6.85, 1.25, 7, "free"),
    SetArch("pointed-2m-thick-glued", 1.25, 1.75, 0.25, 3, "glued"),
    SetArch("lancet-2m-free", 2.0, 2.2, 1.0, 5, "free"),
    SetArch("drawn-ring-dxf-mm", 1.0, 1.15, 0.0, 4, drawing="ring", fmt="dxf"),
    SetArch("drawn-ring-csv", 1.0, 1.15, 0.0, 4, drawing="ring", fmt="csv"),
    SetArch("drawn-ring-convex-dxf", 1.0, 1.15, 0.0, 4, drawing="ring-convex", fmt="dxf"),
    SetArch("drawn-ring-convex-obj", 1.0, 1.15, 0.0, 4, drawing="ring-convex", fmt="obj"),
    SetArch("drawn-irregular-pointed", drawing="irregular", fmt="dxf"),
    SetArch("drawn-survey-on-piers", drawing="survey"),
)


def set_arch(name: str) -> SetArch:
    """The member called ``name``."""
    for m in ARCH_SET:
        if m.name == name:
            return m
    raise ArchdemInputError(f"no arch {name!r} in the set; members: {', '.join(m.name for m in ARCH_SET)}")


__all__ = ["ARCH_SET", "DEPTH", "SetArch", "off_radial_joint", "set_arch"]
