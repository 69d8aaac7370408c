"""``archdem mesh``: the voussoirs' meshes (convex pieces) of an arch."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, arch_request, default_of, writable_dir
from specimens.blocks import discretise


def _mesh(args: argparse.Namespace) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from specimens.mesh import export_meshes

    req = arch_request(args)
    label, arch = req.structure()
    asm = discretise(arch, config=args.config, shape=args.shape, **req.discretise_kwargs(arch))
    out = writable_dir(args.out)
    files = export_meshes(asm, out, args.format)
    print(f"{label}: {len(files)} file(s) for {asm.n_bodies} bodies written to {out}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("mesh", help="export voussoir meshes (convex pieces) of an arch")
    add_options(p, "mesh")
    p.add_argument("--shape", choices=("linearised", "curved"), default=default_of(discretise, "shape"))
    p.add_argument("--format", choices=("stl", "obj", "glb"), default="stl")
    p.set_defaults(func=_mesh)
