"""Virtual against physical (docs/validation.md#14-against-the-laboratory): DEM tilt tests of the
catalogue with the calibrated imperfect joints, beside the laboratory tilt tests.

For every catalogue specimen: the laboratory mean and sd (where the shipped table has them), the
ideal LP, the LP at the calibrated contact, the DEM tilt lambda (reference friction, glued) at
full and at calibrated contact in the chosen engines, and the modes; for the laboratory
specimens also an ensemble of ``--ensemble`` realisations (seeded, calibrated scatter) whose mean
and sd stand beside the laboratory's. Writes benchmarks/results/validate_lab.json and .md.

    python benchmarks/validate_lab.py [--engines pybullet,mujoco] [--ensemble 10] [--seed 1] [--workers 2]
"""
from __future__ import annotations

import argparse
import json
import math
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

OUT = Path(__file__).resolve().parent / "results"


def one(job: tuple[str, str, float]) -> dict:
    """Tilt of one specimen in one engine at one contact (reference friction, glued)."""
    sid, engine, contact = job
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.tilt.run import TiltProtocol, tilt
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    asm = discretise(get_specimen(sid).arch, config="glued", contact=contact)
    r = tilt(from_assembly(asm, name=sid), Settings(engine=engine), TiltProtocol(tol=0.005), label=sid, assembly=asm)
    return {"id": sid, "engine": engine, "contact": contact, "lambda": r.lam, "mode": r.mode,
            "joints": [(j.joint, j.state) for j in r.joints if j.state != "closed"], "n_sims": r.n_sims}


def main() -> None:
    from analytic.limit.calibration import LAB_TILT_TESTS, load_calibration, lp_lambda, read_experiments
    from dem.experiments.tilt.ensemble import tilt_ensemble
    from specimens.catalogue import CATALOGUE
    from specimens.imperfection import Imperfection

    ap = argparse.ArgumentParser()
    ap.add_argument("--engines", default="pybullet,mujoco")
    ap.add_argument("--ensemble", type=int, default=10)
    ap.add_argument("--ensemble-engine", default="pybullet")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--workers", type=int, default=2)
    a = ap.parse_args()
    t0 = time.perf_counter()
    cal = load_calibration()
    lab = {t.id: t for t in read_experiments(LAB_TILT_TESTS)}
    engines = a.engines.split(",")
    contact = {s.id: cal.contact(s.arch) for s in CATALOGUE}
    jobs = [(s.id, e, c) for s in CATALOGUE for e in engines for c in (1.0, contact[s.id])]
    with ProcessPoolExecutor(a.workers) as ex:
        runs = list(ex.map(one, jobs))
    by = {(r["id"], r["engine"], r["contact"]): r for r in runs}
    ens = {}
    if a.ensemble > 0:
        for sid in lab:
            arch = next(s.arch for s in CATALOGUE if s.id == sid)
            imp = Imperfection(cal.edge_loss, cal.edge_loss_sd)
            path = OUT / "validate_lab_studies" / f"{sid}-seed{a.seed}-{a.ensemble_engine}.h5"
            path.parent.mkdir(parents=True, exist_ok=True)
            res = tilt_ensemble(sid, arch, imp, a.ensemble, a.seed, path, engine=a.ensemble_engine,
                                workers=a.workers, resume=path.exists(), progress=False)
            ens[sid] = res.summary()
    rows = []
    for s in CATALOGUE:
        t = lab.get(s.id)
        row = {"id": s.id, "lab_mean": t.lambda_mean if t else None, "lab_sd": t.lambda_sd if t else None,
               "lab_mode": t.mode if t else None, "lp_ideal": lp_lambda(s.arch, 1.0), "contact": contact[s.id],
               "lp_effective": lp_lambda(s.arch, contact[s.id])}
        for e in engines:
            row[f"dem_ideal_{e}"] = by[(s.id, e, 1.0)]["lambda"]
            row[f"dem_effective_{e}"] = by[(s.id, e, contact[s.id])]["lambda"]
            row[f"mode_effective_{e}"] = by[(s.id, e, contact[s.id])]["mode"]
            if t:
                tol = max(2 * t.lambda_sd, 0.15 * t.lambda_mean)
                row[f"within_{e}"] = abs(row[f"dem_effective_{e}"] - t.lambda_mean) <= tol
        if s.id in ens:
            row.update({"ensemble_mean": ens[s.id]["lambda_mean"], "ensemble_sd": ens[s.id]["lambda_sd"],
                        "ensemble_modes": ens[s.id]["modes"]})
        rows.append(row)
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "validate_lab.json").write_text(json.dumps({"calibration": cal.to_json(), "rows": rows, "runs": runs,
                                                       "ensembles": ens, "wall_s": time.perf_counter() - t0},
                                                      indent=1, default=str))
    f = lambda v: "-" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.3f}"  # noqa: E731
    head = ["id", "lab mean ± sd", "lab mode", "LP ideal", "contact", "LP eff."]
    for e in engines:
        head += [f"DEM ideal {e}", f"DEM eff. {e}", f"mode {e}"]
    head += [f"ensemble ({a.ensemble_engine}) mean ± sd", "ensemble modes"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        cells = [r["id"], f"{f(r['lab_mean'])} ± {f(r['lab_sd'])}" if r["lab_mean"] else "(prediction)",
                 r["lab_mode"] or "-", f(r["lp_ideal"]), f(r["contact"]), f(r["lp_effective"])]
        for e in engines:
            mark = "" if r.get(f"within_{e}") is None else (" ✓" if r[f"within_{e}"] else " ✗")
            cells += [f(r[f"dem_ideal_{e}"]), f(r[f"dem_effective_{e}"]) + mark, r[f"mode_effective_{e}"]]
        cells += [f"{f(r.get('ensemble_mean'))} ± {f(r.get('ensemble_sd'))}" if "ensemble_mean" in r else "-",
                  ", ".join(f"{m} {k}" for m, k in r.get("ensemble_modes", {}).items()) or "-"]
        lines.append("| " + " | ".join(cells) + " |")
    for e in engines:
        ok = [r for r in rows if r.get(f"within_{e}") is not None]
        modes = sum(r[f"mode_effective_{e}"].startswith(r["lab_mode"]) or (r["lab_mode"] == "sliding" and
                    r[f"mode_effective_{e}"] == "mixed") for r in ok)
        lines.append(f"\n{e}: within max(2 sd, 15 %) of the laboratory mean {sum(r[f'within_{e}'] for r in ok)}/{len(ok)}; "
                     f"observed mode reproduced {modes}/{len(ok)}")
    lines.append(f"\ncalibration: edge loss {cal.edge_loss * 1e3:.2f} mm, scatter {cal.edge_loss_sd * 1e3:.2f} mm; "
                 f"wall {time.perf_counter() - t0:.0f} s")
    (OUT / "validate_lab.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
