"""Helpers shared by the sub-commands: arch selection, JSON output, output paths."""
from __future__ import annotations

import argparse
import json
import math
from typing import Any

from specimens.errors import ArchdemInputError
from specimens.io import json_default, writable_dir, writable_file  # noqa: F401 (the CLI modules import them from here)


def add_arch_arguments(p: argparse.ArgumentParser, id_required: bool = False) -> None:
    """Arch by catalogue id (positional) or by parameters."""
    p.add_argument("id", nargs=None if id_required else "?", help="specimen id (see `archdem specimens`)")
    g = p.add_argument_group("arch by parameters (instead of an id; SI units, m)")
    for name in ("Ri", "Re", "e", "Sh", "Sd", "Rc"):
        g.add_argument(f"--{name}", type=float, default=None)
    g.add_argument("--width", type=float, default=None, help="out-of-plane width [m] (default 0.1)")
    g.add_argument("--voussoirs", type=int, default=None, help="voussoirs per side (default 8)")
    g.add_argument("--density", type=float, default=None, help="density [kg/m^3] (default 500)")


def arch_from_args(args: argparse.Namespace):
    """Return ``(label, PointedArch)`` from the id or the parameter options."""
    from specimens.catalogue import get_specimen
    from specimens.geometry import PointedArch

    width = args.width if args.width is not None else 0.1
    by_radii = [args.Ri, args.Re, args.e]
    by_ratio = [args.Sh, args.Sd, args.Rc]
    if args.id is not None:
        if any(v is not None for v in by_radii + by_ratio):
            raise ArchdemInputError("give either a specimen id or --Ri/--Re/--e or --Sh/--Sd/--Rc, not both")
        spec = get_specimen(args.id)
        arch = spec.arch if args.width is None else spec.arch.with_width(width)
        return spec.id, arch
    if all(v is not None for v in by_radii) and all(v is None for v in by_ratio):
        arch = PointedArch.from_radii(args.Ri, args.Re, args.e, width=width)
    elif all(v is not None for v in by_ratio) and all(v is None for v in by_radii):
        arch = PointedArch.from_ratios(args.Sh, args.Sd, args.Rc, width=width)
    else:
        raise ArchdemInputError("give a specimen id, or all of --Ri --Re --e, or all of --Sh --Sd --Rc")
    label = f"Sh{arch.Sh:.3g}-Sd{arch.Sd:.3g}-Rc{arch.Rc:.3g}"
    return label, arch


def discretisation_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    kw: dict[str, Any] = {}
    if getattr(args, "voussoirs", None) is not None:
        if args.voussoirs < 1:
            raise ArchdemInputError(f"--voussoirs must be >= 1, got {args.voussoirs}")
        kw["n_voussoirs"] = args.voussoirs
    if getattr(args, "density", None) is not None:
        if not (args.density > 0 and math.isfinite(args.density)):
            raise ArchdemInputError(f"--density must be positive, got {args.density}")
        kw["density"] = args.density
    return kw




def print_json(obj: Any) -> None:
    print(json.dumps(obj, indent=2, default=json_default, allow_nan=True))






def add_engine_argument(p: argparse.ArgumentParser) -> None:
    """``--engine pybullet|mujoco`` (the physics backend of the simulator)."""
    p.add_argument("--engine", choices=("pybullet", "mujoco"), default="pybullet",
                   help="physics engine (default pybullet; see README 'Choosing an engine')")


def parse_grid(text: str, what: str = "--freq") -> list[float]:
    """``"0.5,1,2"`` or an inclusive range ``"start:stop:step"``."""
    try:
        if ":" in text:
            a, b, s = (float(v) for v in text.split(":"))
            if not (s > 0 and b >= a):
                raise ValueError
            n = int(math.floor((b - a) / s + 1e-9)) + 1
            vals = [a + k * s for k in range(n)]
        else:
            vals = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise ArchdemInputError(f"{what}: expected a list '0.5,1,2' or a range 'start:stop:step', got {text!r}") from None
    if not vals or not all(math.isfinite(v) and v > 0 for v in vals):
        raise ArchdemInputError(f"{what}: values must be positive, got {text!r}")
    return vals
