"""``archdem draw``: the engineering drawing of an arch, joints numbered."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, arch_request, default_of, figure_file
from dem.common.request import PLANE_DEPTH_M, density_text
from specimens.blocks import discretise
from specimens.drawn import gaps_text


def _draw(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.drawing import drawing_title, save_drawing

    drawn = args.geometry is not None
    req = arch_request(args)
    # a plane drawing needs no depth (only the masses the figure states do): blocks without one per metre
    label, structure = req.structure(plane=drawn)
    asm = discretise(structure, shape=args.shape, **({} if drawn else {"config": args.config}),
                     **req.discretise_kwargs(structure))
    per_metre = drawn and args.depth is None and asm.source.get("blocks_at_depth_m", 0) > 0
    out = figure_file(args.out, "--out")
    save_drawing(asm, out, title=drawing_title(label, asm, PLANE_DEPTH_M if per_metre else None))
    print(f"drawing written to {out}" + (f"; {density_text(asm)}" if drawn else ""))
    if getattr(asm, "gaps", ()):
        print(f"  gaps (no joint between them): {gaps_text(asm.gaps)}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("draw", help="engineering drawing of an arch")
    add_options(p, "draw")
    p.add_argument("--shape", choices=("linearised", "curved"), default=default_of(discretise, "shape"))
    p.set_defaults(func=_draw)
