"""``archdem analytic``: limit analysis of one arch (continuous, discrete, LP, two-bar) or figures."""
from __future__ import annotations

import argparse
import math

from analytic.limit.summary import analyse
from dem.common.options import (
    add_arch_arguments,
    arch_from_args,
    default_of,
    discretisation_kwargs,
    print_json,
    writable_dir,
)
from specimens.blocks import discretise
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from specimens.errors import ArchdemInputError


def register(sub) -> None:
    p = sub.add_parser("analytic", help="limit analysis: continuous, discrete (enumeration and LP), two-bar",
                       description=__doc__.splitlines()[0])
    add_arch_arguments(p)
    p.add_argument("--config", choices=("glued", "free"), default=default_of(discretise, "config"),
                   help="discrete configuration")
    p.add_argument("--mu-joint", type=float, default=None, help=f"block-block friction (default {REFERENCE_MU_JOINT:g})")
    p.add_argument("--mu-base", type=float, default=None, help=f"block-base friction (default {REFERENCE_MU_BASE:g})")
    p.add_argument("--effective-thickness", type=float, default=default_of(analyse, "effective_thickness"),
                   help="continuous analysis of the thinner ring: fraction of t kept about Rp, its "
                        "weight included (unlike --contact, which keeps the full weight) "
                        f"(default {default_of(analyse, 'effective_thickness'):g})")
    p.add_argument("--min-spacing", type=float, default=default_of(analyse, "min_spacing"),
                   help=f"least hinge spacing [rad] (continuous; default {default_of(analyse, 'min_spacing'):g})")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--plot", metavar="DIR", default=None,
                   help="write the catalogue / full-scale figures to DIR (no id needed)")
    p.set_defaults(func=run)


def _finite_mu(name: str, v: float | None, default: float) -> float:
    if v is None:
        return default
    if not (v >= 0):
        raise ArchdemInputError(f"{name} must be >= 0 (inf allowed), got {v}")
    return float(v)


def run(args: argparse.Namespace) -> int:
    if args.plot is not None:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.limit.figures import catalogue_figures

        out = writable_dir(args.plot)
        files = catalogue_figures(out)
        if args.json:
            print_json({"figures": [str(f) for f in files]})
        else:
            for f in files:
                print(f)
        if args.id is None and all(getattr(args, k) is None for k in ("Ri", "Re", "e", "Sh", "Sd", "Rc")):
            return 0
    label, arch = arch_from_args(args)
    mu_j = _finite_mu("--mu-joint", args.mu_joint, REFERENCE_MU_JOINT)
    mu_b = _finite_mu("--mu-base", args.mu_base, REFERENCE_MU_BASE)
    if not (0.05 <= args.effective_thickness <= 1):
        raise ArchdemInputError(f"--effective-thickness must be in [0.05, 1], got {args.effective_thickness}")
    disc_kw = discretisation_kwargs(args, arch)
    if "piers" in disc_kw and (args.effective_thickness != 1.0 or args.min_spacing != 0.0):
        raise ArchdemInputError("--effective-thickness and --min-spacing apply to the ring on a rigid base; on piers "
                                "use --contact")
    res = analyse(arch, args.config, mu_j, mu_b, args.effective_thickness, args.min_spacing, disc_kw)
    res["id"] = label
    res = {k: (None if isinstance(v, float) and math.isnan(v) else v) for k, v in res.items()}
    if args.json:
        print_json(res)
        return 0
    on_piers = "piers" in disc_kw
    print(f"{label}  (config {args.config}, mu_joint {mu_j:g}, mu_base {mu_b:g})"
          + (f"  on piers {res['piers']['height']:g} m high, {res['piers']['width']:g} m wide, "
             f"{res['piers']['courses']} course(s)" if on_piers else ""))
    hc = ", ".join(f"{h['half'][0].upper()} {h['angle_rad']:.3f} {h['face'][:3]}" if "half" in h else
                   f"{h['pier'][0].upper()}P h={h['height_m']:.3f} m {h['face'][:3]}" for h in res["hinges_continuous"])
    print(f"  continuous   lambda = {res['lambda_continuous']:.4f}   hinges: {hc}")
    if on_piers:
        print(f"    ({res['continuous_message']})")
    hd = ", ".join(f"{h['joint']} {h['face'][:3]}" for h in res["hinges_discrete"])
    print(f"  discrete     lambda = {res['lambda_discrete']:.4f}   hinges: {hd}")
    act = ", ".join(f"{k} {v['state']}" for k, v in res["joints_lp"].items() if v["state"] != "closed")
    print(f"  LP (friction) lambda = {res['lambda_lp'] if res['lambda_lp'] is None else round(res['lambda_lp'], 4)}   {act}   [{res['lp_status']}]")
    if on_piers:
        print(f"  two-bar      ({res['two_bar_message']})")
    else:
        print(f"  two-bar      lambda = {res['lambda_two_bar']:.4f}   mu* = {res['mu_star']:.3f}")
    for w in res["warnings"]:
        print(f"  warning: {w}")
    if not res["stands"]:
        print("  the arch cannot stand under self-weight")
    lam = res["lambda_continuous"]
    return 0 if lam is not None and math.isfinite(lam) else 1
