"""``archdem draw``: the engineering drawing of an arch, joints numbered."""
from __future__ import annotations

import argparse

from dem.cli.mesh_cmd import assembly_from_args
from dem.common.options import (
    PLANE_DEPTH_M,
    add_options,
    default_of,
    density_text,
    discretisation_kwargs,
    figure_file,
    geometry_from_args,
)
from specimens.blocks import discretise
from specimens.drawn import gaps_text


def _drawing_from_args(args: argparse.Namespace):
    """``(label, assembly, title)`` of ``--geometry``: a plane drawing needs no depth (only the masses
    the figure states depend on it), so blocks without one are drawn per metre of depth."""
    label, drawn = geometry_from_args(args, plane=True)
    asm = discretise(drawn, shape=args.shape, **discretisation_kwargs(args, drawn))
    per_metre = args.depth is None and asm.source.get("blocks_at_depth_m", 0) > 0
    title = f"{label}\ndensity {asm.density:g} kg/m^3" + (f", blocks without a depth {PLANE_DEPTH_M:g} m deep "
                                                         "(masses per metre)" if per_metre else "")
    return label, asm, title


def _draw(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.drawing import save_drawing

    if args.geometry is not None:
        label, asm, title = _drawing_from_args(args)
    else:
        label, asm = assembly_from_args(args)
        a = asm.arch
        title = f"{label}   Sh = {a.Sh:.2f}, Sd = {a.Sd:.2f}"
    out = figure_file(args.out, "--out")
    save_drawing(asm, out, title=title)
    print(f"drawing written to {out}" + (f"; {density_text(asm)}" if args.geometry is not None else ""))
    if getattr(asm, "gaps", ()):
        print(f"  gaps (no joint between them): {gaps_text(asm.gaps)}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("draw", help="engineering drawing of an arch")
    add_options(p, "draw")
    p.add_argument("--shape", choices=("linearised", "curved"), default=default_of(discretise, "shape"))
    p.set_defaults(func=_draw)
