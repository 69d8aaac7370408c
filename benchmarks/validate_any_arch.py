"""The default tilt test against limit analysis on arches outside the catalogue
(docs/validation.md#20-arches-outside-the-catalogue).

Every member of :data:`specimens.arch_set.ARCH_SET` (round and pointed arches by parameters, spans
0.5-10 m, thin to thick, glued and free; drawings in DXF, CSV and OBJ) is tilted as ``archdem tilt``
does by default, and its lambda is set beside the static LP of the same blocks at the same
frictions, the least collapse without dilatancy (mixed-integer), the LP with no sliding and, for a
regular ring, the continuous ring's multiplier.
Writes benchmarks/results/validate_any_arch[_ENGINE].json and .md.

    python benchmarks/validate_any_arch.py [--arches a,b] [--engine pybullet|mujoco] [--workers N]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

OUT = Path(__file__).resolve().parent / "results"


def one(job: tuple[str, str, str]) -> dict:
    """One member (name, engine, drawings folder): its tilt beside its LPs."""
    name, engine, folder = job
    from analytic.limit.limit_continuous import continuous_collapse
    from analytic.limit.limit_discrete import solve_lp
    from analytic.limit.non_associative import solve_non_associative
    from dem.core.settings import Settings
    from dem.experiments.tilt.check import lp_check, lp_slides, na_joints, reference_lp, same_mechanism
    from dem.experiments.tilt.run import tilt
    from specimens.arch_set import set_arch
    from foundation.errors import ArchdemInputError

    m = set_arch(name)
    asm = m.assembly(folder)
    st = Settings(engine=engine)
    lp = reference_lp(asm, st.mu_joint, st.mu_base)
    row = {"arch": name, "source": m.fmt or ("dxf (shipped)" if m.drawing == "survey" else "parameters"),
           "config": "" if m.drawn else m.config, "span_m": m.span, "t_over_Rp": m.thickness_ratio,
           "bodies": len(asm.bodies), "engine": engine, "lp_lambda": lp.lam,
           "lp_sliding": lp_slides(lp),
           "lp_lambda_no_sliding": solve_lp(asm, math.inf, math.inf).lam,
           "continuous_lambda": continuous_collapse(m.arch).lam if m.arch is not None else float("nan"),
           "lp_hinges": [f"{j} {f}" for j, f in lp.hinges]}
    na = solve_non_associative(asm, st.mu_joint, st.mu_base)  # Coulomb without dilatancy, beside the LP
    row |= {"na_lambda": na.lam, "na_optimal": na.optimal, "na_seconds": na.seconds,
            "na_joints": [f"{j} {v}" for j, v in na_joints(na).items()]}
    t0 = time.perf_counter()
    try:
        r = tilt(asm, st, label=name)
    except ArchdemInputError as exc:  # a tilt that finds no answer is a row of the table, not the end of the run
        return row | {"lambda": float("nan"), "err_pct": float("nan"), "mode": "failed", "dem_hinges": [], "n_sims": 30,
                      "wall_s": time.perf_counter() - t0, "within_3pct": False, "warning": str(exc),
                      "same_mechanism_as_na": False}
    chk = lp_check(r, asm, lp)
    return row | {
        "lambda": r.lam, "err_pct": 100 * chk.rel_err, "mode": r.mode,
        "dem_hinges": [f"{j.joint} {j.face}" for j in r.joints if j.state in ("hinge", "hinge+slide")],
        "n_sims": r.n_sims, "wall_s": time.perf_counter() - t0, "within_3pct": bool(chk.agrees), "warning": chk.warning,
        "same_mechanism_as_na": same_mechanism(r.joints, na),
    }


def _num(x: float, fmt: str) -> str:
    return "—" if math.isnan(x) else format(x, fmt)


def table(rows: list[dict]) -> str:
    head = ("| arch | source | config | span [m] | t/Rp | bodies | LP | DEM | error | mode | continuous | "
            "sims | wall [s] | no dilatancy (MIP [s]) | DEM vs it | same mechanism |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    out = []
    for r in rows:
        lp = _num(r["lp_lambda"], ".4f") + (" (slides)" if r["lp_sliding"] else "")
        out.append(f"| {r['arch']} | {r['source']} | {r['config'] or '—'} | {_num(r['span_m'], '.2f')} | "
                   f"{_num(r['t_over_Rp'], '.3f')} | {r['bodies']} | {lp} | {_num(r['lambda'], '.4f')} | "
                   f"{_num(r['err_pct'], '+.2f')} % | {r['mode']} | {_num(r['continuous_lambda'], '.4f')} | "
                   f"{r['n_sims']} | {r['wall_s']:.1f} | {_num(r['na_lambda'], '.4f')} ({r['na_seconds']:.1f}"
                   f"{'' if r['na_optimal'] else ', not proven'}) | {_num(100 * (r['lambda'] / r['na_lambda'] - 1), '+.2f')} % | "
                   f"{'yes' if r['same_mechanism_as_na'] else 'no'} |")
    n3 = sum(r["within_3pct"] for r in rows)
    errs = [r["err_pct"] for r in rows if not math.isnan(r["err_pct"])]
    walls = sorted(r["wall_s"] for r in rows)
    foot = (f"\n{n3} of {len(rows)} within 3 % of the LP ({len(rows) - len(errs)} without an answer); error {min(errs):+.2f} % to {max(errs):+.2f} %, "
            f"mean |error| {sum(map(abs, errs)) / len(errs):.2f} %; wall time per tilt {walls[0]:.1f}-{walls[-1]:.1f} s "
            f"(median {walls[len(walls) // 2]:.1f} s).\n")
    same = [r for r in rows if r["same_mechanism_as_na"]]
    dev = [100 * (r["lambda"] / r["na_lambda"] - 1) for r in same]
    foot += (f"Without dilatancy: {sum(r['na_optimal'] for r in rows)} of {len(rows)} proven optimal, "
             f"{min(r['na_seconds'] for r in rows):.1f}-{max(r['na_seconds'] for r in rows):.1f} s each; the DEM has its "
             f"mechanism on {len(same)} of {len(rows)}" + (f", there {min(dev):+.2f} % to {max(dev):+.2f} % from it" if dev else "")
             + ".\n")
    return head + "\n".join(out) + foot


def main(argv=None) -> int:
    from specimens.arch_set import ARCH_SET
    from foundation.processes import pool_worker_init

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--arches", default="", help="comma-separated members (default: all)")
    ap.add_argument("--engine", default="pybullet")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    a = ap.parse_args(argv)
    names = [n for n in a.arches.split(",") if n] or [m.name for m in ARCH_SET]
    with tempfile.TemporaryDirectory() as folder:
        jobs = [(n, a.engine, folder) for n in names]
        t0 = time.perf_counter()
        with ProcessPoolExecutor(a.workers, initializer=pool_worker_init) as ex:
            rows = list(ex.map(one, jobs))
    md = table(rows) + f"\nWhole run: {time.perf_counter() - t0:.0f} s on {a.workers} workers.\n"
    print(md)
    OUT.mkdir(exist_ok=True)
    stem = "validate_any_arch" + ("" if a.engine == "pybullet" else f"_{a.engine}")
    (OUT / f"{stem}.json").write_text(json.dumps(rows, indent=1))
    (OUT / f"{stem}.md").write_text(md)
    return 0 if all(r["within_3pct"] for r in rows) else 1


if __name__ == "__main__":
    raise SystemExit(main())
