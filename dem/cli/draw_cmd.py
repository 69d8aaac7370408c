"""``archdem draw``: the engineering drawing of an arch, joints numbered."""
from __future__ import annotations

import argparse

from dem.cli.mesh_cmd import assembly_from_args
from dem.common.options import add_arch_arguments, default_of, figure_file
from specimens.blocks import discretise


def _draw(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.drawing import save_drawing

    label, asm = assembly_from_args(args)
    out = figure_file(args.out, "--out")
    a = asm.arch
    save_drawing(asm, out, title=f"{label}   Sh = {a.Sh:.2f}, Sd = {a.Sd:.2f}" if a is not None else label)
    print(f"drawing written to {out}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("draw", help="engineering drawing of an arch")
    add_arch_arguments(p)
    p.add_argument("--config", choices=("glued", "free"), default=default_of(discretise, "config"))
    p.add_argument("--shape", choices=("linearised", "curved"), default=default_of(discretise, "shape"))
    p.add_argument("--out", required=True, help="output image (.png/.pdf/.svg)")
    p.set_defaults(func=_draw)
