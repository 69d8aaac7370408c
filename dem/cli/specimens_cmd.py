"""``archdem specimens``, ``archdem mesh`` and ``archdem draw``."""
from __future__ import annotations

import argparse

from dem.cli.common import (
    add_arch_arguments,
    arch_from_args,
    default_of,
    discretisation_kwargs,
    figure_file,
    print_json,
    writable_dir,
)
from specimens.catalogue import JSON_KEYS, catalogue_rows


def _specimens(args: argparse.Namespace) -> int:
    rows = catalogue_rows()
    if args.json:
        print_json([{k: r[k] for k in JSON_KEYS} for r in rows])
        return 0
    hdr = f"{'id':<11} {'Ri':>6} {'Re':>6} {'e':>6} {'t':>6} {'Sh':>5} {'Sd':>5} {'span':>6} {'rise':>6} {'mass':>6} {'bodies':>11}"
    print(hdr)
    print(f"{'':<11} {'[mm]':>6} {'[mm]':>6} {'[mm]':>6} {'[mm]':>6} {'':>5} {'':>5} {'[mm]':>6} {'[mm]':>6} {'[kg]':>6} {'free/glued':>11}")
    for r in rows:
        print(f"{r['id']:<11} {r['Ri']*1e3:6.0f} {r['Re']*1e3:6.0f} {r['e']*1e3:6.0f} {r['t']*1e3:6.0f} "
              f"{r['Sh']:5.2f} {r['Sd']:5.3f} {r['span']*1e3:6.0f} {r['rise']*1e3:6.1f} {r['mass']:6.3f} "
              f"{r['n_bodies_free']:>5}/{r['n_bodies_glued']:<5}")
    return 0


def _assembly(args: argparse.Namespace):
    from specimens.blocks import discretise

    label, arch = arch_from_args(args)
    kw = discretisation_kwargs(args, arch)
    asm = discretise(arch, config=args.config, shape=getattr(args, "shape", default_of(discretise, "shape")), **kw)
    return label, asm


def _mesh(args: argparse.Namespace) -> int:
    from specimens.mesh import export_meshes

    label, asm = _assembly(args)
    out = writable_dir(args.out)
    files = export_meshes(asm, out, args.format)
    print(f"{label}: {len(files)} file(s) for {asm.n_bodies} bodies written to {out}")
    return 0


def _draw(args: argparse.Namespace) -> int:
    from specimens.drawing import save_drawing

    label, asm = _assembly(args)
    out = figure_file(args.out, "--out")
    a = asm.arch
    save_drawing(asm, out, title=f"{label}   Sh = {a.Sh:.2f}, Sd = {a.Sd:.2f}" if a is not None else label)
    print(f"drawing written to {out}")
    return 0


def register(sub) -> None:
    from specimens.blocks import discretise

    p = sub.add_parser("specimens", help="table of the specimen catalogue")
    p.add_argument("--json", action="store_true", help="print a JSON list")
    p.set_defaults(func=_specimens)

    p = sub.add_parser("mesh", help="export voussoir meshes (convex pieces) of an arch")
    add_arch_arguments(p)
    p.add_argument("--config", choices=("glued", "free"), default=default_of(discretise, "config"))
    p.add_argument("--shape", choices=("linearised", "curved"), default=default_of(discretise, "shape"))
    p.add_argument("--format", choices=("stl", "obj", "glb"), default="stl")
    p.add_argument("--out", required=True, help="output directory")
    p.set_defaults(func=_mesh)

    p = sub.add_parser("draw", help="engineering drawing of an arch")
    add_arch_arguments(p)
    p.add_argument("--config", choices=("glued", "free"), default=default_of(discretise, "config"))
    p.add_argument("--shape", choices=("linearised", "curved"), default=default_of(discretise, "shape"))
    p.add_argument("--out", required=True, help="output image (.png/.pdf/.svg)")
    p.set_defaults(func=_draw)
