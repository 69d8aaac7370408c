"""The structure a command or a script asks for, checked once: a catalogue id, an arch by its
parameters, on piers or not, a drawing or a rectangular block (:class:`ArchRequest`).

Its fields are the arch options of the command line (their destinations), and its refusals name
those options, so that ``archdem`` and a Python caller get the same one-line errors."""
from __future__ import annotations

import dataclasses
import math
import numbers
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from dem.common.joints import CALIBRATED, contact_fraction
from foundation.errors import ArchdemInputError
from foundation.fields import default_of
from specimens.blocks import DEFAULT_DENSITY, DEFAULT_VOUSSOIRS, check_contact, discretise
from specimens.catalogue import SPECIMEN_WIDTH, get_specimen
from specimens.constants import DRAWN_DENSITY, MAX_LENGTH_M, MIN_LENGTH_M
from specimens.drawn import MAX_BLOCKS, DrawnAssembly, gaps_text
from specimens.exchange import UNITS, read_assembly
from specimens.geometry import PointedArch
from specimens.piers import MAX_COURSES, Piers

#: Densities a request takes [kg/m^3].
DENSITY_RANGE = (1.0, 1e5)
#: Most voussoirs per side (a typo such as 100000 would otherwise take the machine's memory).
MAX_VOUSSOIRS = 100
#: Largest superimposed load on a pier [kN] (a 50 m column of masonry 3 m square is about 10^4 kN).
MAX_PIER_LOAD_KN = 1e6
#: The depth [m] a plane drawing gives blocks that state none (masses per metre of depth).
PLANE_DEPTH_M = 1.0
#: The fields that set piers.
PIER_FIELDS = ("pier_height", "pier_width", "pier_depth", "pier_offset", "pier_courses", "pier_load")
#: The fields of an arch by its parameters: by radii, by ratios.
RADII, RATIOS = ("Ri", "Re", "e"), ("Sh", "Sd", "Rc")


def _opt(help: str, **meta: Any) -> Any:
    """A field that is an option, None unless given: its help in the metadata (``unit``, ``shown``)."""
    return field(default=None, metadata={"help": help, **meta})


def _option(name: str) -> str:
    return "--" + name.replace("_", "-")


def _check_length(name: str, v: float | None, lo: float = MIN_LENGTH_M) -> None:
    if v is not None and not (math.isfinite(v) and lo <= v <= MAX_LENGTH_M):
        raise ArchdemInputError(f"{_option(name)} must be a length between {lo:g} and {MAX_LENGTH_M:g} m, got {v:g}")


@dataclass(frozen=True)
class ArchRequest:
    """What is asked for, checked on construction (one-line :class:`ArchdemInputError`): a catalogue
    ``id``, or the arch's radii ``Ri``, ``Re``, ``e`` or ratios ``Sh``, ``Sd``, ``Rc`` [m, -], its
    out-of-plane ``width`` [m], ``voussoirs`` per side, ``density`` [kg/m^3], ``contact`` (a fraction
    in (0, 1] or ``"calibrated"``), piers (``pier_height``, ``pier_width``, ``pier_depth``,
    ``pier_offset`` [m], ``pier_courses``, ``pier_load`` [kN]); or a drawing ``geometry`` (a file)
    with its ``units`` and ``depth`` [m]; or a rectangular ``block`` of half-width and half-height
    ``(B, H)`` [m]. None: not given (the library's default)."""

    # each field's option help in its metadata (foundation.fields.option_help; "shown": the default it says)
    id: str | None = _opt("specimen id (see `archdem specimens`)")
    Ri: float | None = None
    Re: float | None = None
    e: float | None = None
    Sh: float | None = None
    Sd: float | None = None
    Rc: float | None = None
    width: float | None = _opt("out-of-plane width", unit="m", shown=f"the specimen's, else {SPECIMEN_WIDTH:g}")
    voussoirs: int | None = _opt(f"voussoirs per side, 1 to {MAX_VOUSSOIRS}", shown=DEFAULT_VOUSSOIRS)
    density: float | None = _opt(
        f"density [kg/m^3], {DENSITY_RANGE[0]:g} to {DENSITY_RANGE[1]:g} (default {DEFAULT_DENSITY:g}) of the specimens' "
        f"aerated concrete; a drawing's: the one its file states, else {DRAWN_DENSITY:g}, masonry. Masses and forces "
        "scale with it; a uniform density changes no multiplier (LP, tilt lambda)")
    contact: float | str | None = _opt(
        "effective contact: every joint touches within its central fraction C of the depth, in (0, 1]; 'calibrated': "
        "from the edge loss fitted to laboratory tilt tests (archdem calibrate); masses stay those of the full blocks",
        shown=f"{default_of(discretise, 'contact'):g}: the full joint")
    pier_height: float | None = _opt("pier height from the ground to the springing line")
    pier_width: float | None = _opt("in-plane pier width, at least the ring thickness plus the offset")
    pier_depth: float | None = _opt("out-of-plane pier depth", shown="the arch's width")
    pier_offset: float | None = _opt("how far the pier's inner face stands inside the opening beyond the intrados "
                                     "springing", shown=default_of(Piers, "offset"))
    pier_courses: int | None = _opt(f"courses per pier, 1 to {MAX_COURSES}", shown=default_of(Piers, "courses"))
    pier_load: float | None = _opt(f"superimposed load on each pier [kN], 0 to {MAX_PIER_LOAD_KN:g}, e.g. the masonry "
                                   "above: carried as mass at the centre of the pier's top", shown=0.0)
    geometry: str | Path | None = _opt(
        "blocks drawn as closed outlines: .dxf (polylines), .csv (block,x,z[,layer]), .obj/.stl (convex prisms); at "
        f"most {MAX_BLOCKS} blocks and {MAX_LENGTH_M:g} m across")
    units: str | None = _opt(f"length unit of the drawing if the file does not state it ({', '.join(UNITS)}; default m)")
    depth: float | None = _opt("out-of-plane depth of the drawn blocks [m] where the drawing does not state it (archdem "
                               "draw: optional, a plane drawing needs none)")
    block: tuple[float, float] | None = _opt("a rectangular block of half-width B and half-height H [m] instead of an arch")
    _arch: tuple[str, PointedArch] | None = field(default=None, init=False, repr=False, compare=False)
    _piers: Piers | None = field(default=None, init=False, repr=False, compare=False)

    @classmethod
    def from_namespace(cls, ns: Any) -> ArchRequest:
        """The request of parsed command-line options (an attribute a command lacks is None)."""
        kw = {f.name: getattr(ns, f.name, None) for f in dataclasses.fields(cls) if f.init}
        if kw["units"] not in UNITS:  # a record's units (archdem shake --record), not a drawing's
            kw["units"] = None
        return cls(**kw)

    @property
    def arch_given(self) -> bool:
        """An arch is asked for: an id, any of its parameters or a drawing."""
        return self.id is not None or self.geometry is not None or any(
            getattr(self, k) is not None for k in RADII + RATIOS)

    def __post_init__(self) -> None:
        if self.block is not None:
            try:
                b, h = (float(v) for v in self.block)
            except (TypeError, ValueError):
                raise ArchdemInputError(f"--block must be two lengths B H, got {self.block!r}") from None
            object.__setattr__(self, "block", (b, h))
            if self.arch_given:
                raise ArchdemInputError("give either --block B H or an arch, not both")
        if self.geometry is not None:
            self._check_drawing()
        else:
            self._check_arch()
        v = self.voussoirs
        if v is not None and (isinstance(v, bool) or not isinstance(v, numbers.Integral) or not 1 <= v <= MAX_VOUSSOIRS):
            raise ArchdemInputError(f"--voussoirs must be 1 to {MAX_VOUSSOIRS}, got {self.voussoirs}")
        if self.density is not None and not (math.isfinite(self.density)
                                             and DENSITY_RANGE[0] <= self.density <= DENSITY_RANGE[1]):
            raise ArchdemInputError(f"--density must be between {DENSITY_RANGE[0]:g} and {DENSITY_RANGE[1]:g} "
                                    f"kg/m^3, got {self.density:g}")
        if isinstance(self.contact, str) and self.contact != CALIBRATED:
            raise ArchdemInputError(f"--contact must be a fraction in (0, 1] or '{CALIBRATED}', got {self.contact!r}")
        if self.contact is not None and not isinstance(self.contact, str):
            check_contact(self.contact)

    def _check_drawing(self) -> None:
        given = [k for k in (*RADII, *RATIOS, "width", "voussoirs", *PIER_FIELDS) if getattr(self, k) is not None]
        if self.id is not None or given:
            raise ArchdemInputError("--geometry gives the whole structure: drop "
                                    + ("the specimen id" if self.id is not None else _option(given[0])))
        _check_length("depth", self.depth)
        if self.units is not None and self.units not in UNITS:
            raise ArchdemInputError(f"--units must be one of {', '.join(UNITS)}, got {self.units!r}")

    def _check_arch(self) -> None:
        for name in ("Ri", "Re", "e", "Rc", "width"):
            _check_length(name, getattr(self, name), 0.0 if name == "e" else MIN_LENGTH_M)
        radii, ratios = [getattr(self, k) for k in RADII], [getattr(self, k) for k in RATIOS]
        width = SPECIMEN_WIDTH if self.width is None else self.width
        if self.id is not None:
            if any(v is not None for v in radii + ratios):
                raise ArchdemInputError("give either a specimen id or --Ri/--Re/--e or --Sh/--Sd/--Rc, not both")
            spec = get_specimen(self.id)
            arch = spec.arch if self.width is None else spec.arch.with_width(width)
            object.__setattr__(self, "_arch", (spec.id, arch))
        elif any(v is not None for v in radii + ratios):
            if all(v is not None for v in radii) and all(v is None for v in ratios):
                arch = PointedArch.from_radii(self.Ri, self.Re, self.e, width=width)
            elif all(v is not None for v in ratios) and all(v is None for v in radii):
                arch = PointedArch.from_ratios(self.Sh, self.Sd, self.Rc, width=width)
            else:
                raise ArchdemInputError("give a specimen id, or all of --Ri --Re --e, or all of --Sh --Sd --Rc")
            # lengths that follow from the given ones are bounded too (a ring 1e-280 m thick has no blocks)
            for what, v in (("ring thickness", arch.t), ("span", arch.span), ("rise", arch.rise)):
                if not MIN_LENGTH_M <= v:
                    raise ArchdemInputError(f"these parameters give a {what} of {v:.3g} m, below {MIN_LENGTH_M:g} m")
            object.__setattr__(self, "_arch", (f"Sh{arch.Sh:.3g}-Sd{arch.Sd:.3g}-Rc{arch.Rc:.3g}", arch))
        object.__setattr__(self, "_piers", self._make_piers())

    def _make_piers(self) -> Piers | None:
        given = {k: getattr(self, k) for k in PIER_FIELDS if getattr(self, k) is not None}
        if not given:
            return None
        if "pier_height" not in given or "pier_width" not in given:
            raise ArchdemInputError("piers need both --pier-height and --pier-width")
        for k in ("pier_height", "pier_width", "pier_depth", "pier_offset"):
            _check_length(k, given.get(k), 0.0 if k == "pier_offset" else MIN_LENGTH_M)
        load = given.get("pier_load", 0.0)
        if not (math.isfinite(load) and 0 <= load <= MAX_PIER_LOAD_KN):
            raise ArchdemInputError(f"--pier-load must be a force between 0 and {MAX_PIER_LOAD_KN:g} kN, got {load:g}")
        return Piers(given["pier_height"], given["pier_width"], given.get("pier_depth"), given.get("pier_offset", 0.0),
                     given.get("pier_courses", 1), load * 1e3)

    @property
    def piers(self) -> Piers | None:
        """The :class:`~specimens.piers.Piers` asked for (None without them)."""
        return self._piers

    def structure(self, plane: bool = False) -> tuple[str, PointedArch | DrawnAssembly]:
        """``(label, PointedArch)``, the label naming the piers too; of a drawing ``(its file's stem,
        DrawnAssembly)`` (read here), which :func:`specimens.blocks.discretise` returns as drawn.
        ``plane``: the blocks are drawn in their plane, so one without a depth takes :data:`PLANE_DEPTH_M`."""
        if self.geometry is not None:
            depth = PLANE_DEPTH_M if plane and self.depth is None else self.depth
            return Path(self.geometry).stem, read_assembly(self.geometry, units=self.units, depth=depth,
                                                           density=self.density)
        if self._arch is None:
            raise ArchdemInputError("give a specimen id, or all of --Ri --Re --e, or all of --Sh --Sd --Rc")
        label, arch = self._arch
        p = self._piers
        if p is None:
            return label, arch
        return (f"{label}-piers-H{p.height:g}-B{p.width:g}" + (f"-N{p.courses}" if p.courses > 1 else "")
                + (f"-P{p.load / 1e3:g}kN" if p.load else "")), arch

    def rectangular_block(self) -> tuple[float, float] | None:
        """``(B, H)`` [m] of the block, None when an arch is asked for; neither: a one-line error."""
        if self.block is None and not self.arch_given:
            raise ArchdemInputError("give a specimen id, the arch parameters or --block B H")
        return self.block

    def discretise_kwargs(self, arch: PointedArch | DrawnAssembly | None = None) -> dict[str, Any]:
        """The :func:`specimens.blocks.discretise` keywords asked for (``arch``: needed for
        ``contact="calibrated"`` and to check that the piers carry it)."""
        kw: dict[str, Any] = {}
        if self.voussoirs is not None:
            kw["n_voussoirs"] = self.voussoirs
        if self.density is not None:
            kw["density"] = self.density
        if self.contact is not None:
            kw["contact"] = contact_fraction(self.contact, arch)
        if self._piers is not None:
            if arch is not None:
                self._piers.check(arch)
            kw["piers"] = self._piers
        return kw

    def require_standing(self, label: str, arch: PointedArch | DrawnAssembly) -> None:
        """:func:`require_standing` of ``arch`` cut as asked."""
        require_standing(label, arch, **self.discretise_kwargs(arch))


def density_text(asm: DrawnAssembly) -> str:
    """``density 2000 kg/m^3 (archdem's default for drawings)``: a drawing's density and where it came from."""
    why = {"given": "--density", "file": "stated by the file"}.get(asm.source.get("density_from"),
                                                                   "archdem's default for drawings; --density sets it")
    return f"density {asm.density:g} kg/m^3 ({why})"


def require_standing(label: str, arch: PointedArch | DrawnAssembly, **kw: Any) -> None:
    """Refuse, in one line, an arch (``discretise`` keywords ``kw``) that cannot stand under its own
    weight even without sliding: a test of its capacity would answer nothing. A drawing's refusal names
    its gaps and the parts no joint joins; a drawing that stands with gaps says so on stderr."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import require_standing as _require_standing
    from analytic.limit.limit_discrete import solve_lp

    asm = discretise(arch, **kw)
    if not isinstance(asm, DrawnAssembly):
        _require_standing(label, asm)
        return
    if not solve_lp(asm, math.inf, math.inf).stands:
        raise ArchdemInputError(asm.cannot_stand(label))
    if asm.gaps:
        print(f"archdem: warning: {label}: {gaps_text(asm.gaps)} (no joint between them; it stands without one)",
              file=sys.stderr)
