"""Compliant joints against independent truths (docs/validation.md#16-compliant-joints):

* ``vibration``: a block's vertical and rocking free vibration in both engines against the closed forms
  of its springs (at the base's two ends) and ``analytic.compliant.modes``, and the vertical damping ratio
  against ``beta_R omega / 2``;
* ``tilt``: the no-sliding tilt lambda of the catalogue with the study's joints (Table 5.1; ``--beta``
  another damping) against the LP, and how lambda moves with k_n on one specimen;
* ``shake``: one-cycle sine thresholds of the Sd 0.15/0.20 specimens at 2-10 Hz with the study's
  joints, beside the rigid DEM and the four-bar.

Writes benchmarks/results/validate_compliant_<part>.json.

    python benchmarks/validate_compliant.py vibration|tilt|shake [--engines pybullet,mujoco] [--ids ...]
"""
from __future__ import annotations

import argparse
import math
import os
import time

from _common import report

#: A block 0.2 x 0.4 x 0.1 m of 500 kg/m^3 and soft joints: ~11 Hz vertical, ~5 Hz rocking.
BLOCK = (0.2, 0.4, 0.1, 500.0)


def vibration(engines: list[str]) -> dict:
    from analytic.compliant.modes import modes
    from dem.core.model import single_block
    from dem.core.settings import Settings
    from dem.experiments.modes.run import free_vibration
    from specimens.constants import G
    from specimens.frame import single_block as block_structure

    b, h, w, rho = BLOCK
    m = rho * b * h * w
    rows = []
    for kn in (1e6, 1e7):
        f_v = math.sqrt(kn * b * w / m) / (2 * math.pi)
        Io = m * (b * b + h * h) / 12 + m * (h / 2) ** 2
        f_r = math.sqrt((kn * b * w * b * b / 4 - m * G * h / 2) / Io) / (2 * math.pi)
        fm = modes(block_structure(b / 2, h / 2, rho, w), kn, 1e4 * kn).frequencies_hz
        for eng in engines:
            for beta in (0.0, 0.1 / (2 * math.pi * f_v)):  # xi 0.05 in the vertical mode
                t0 = time.perf_counter()
                r = free_vibration(single_block(b, h, w, rho), Settings(engine=eng, dt=1e-4, contact_law="compliant",
                                                                        kn=kn, damping_beta=beta))
                rows.append({"engine": eng, "kn": kn, "beta": beta, "f_vertical": r["vertical"].frequency_hz,
                             "f_vertical_exact": f_v, "f_rocking": r["rocking"].frequency_hz, "f_rocking_exact": f_r,
                             "f_modes": fm[:2].tolist(), "xi_vertical": r["vertical"].damping,
                             "xi_vertical_exact": beta * math.pi * f_v, "xi_rocking": r["rocking"].damping,
                             "xi_rocking_exact": beta * math.pi * f_r * (1 + m * G * h / 2 / (Io * (2 * math.pi * f_r) ** 2)),
                             "wall_s": time.perf_counter() - t0})
                print({k: (round(v, 5) if isinstance(v, float) else v) for k, v in rows[-1].items()}, flush=True)
    return {"block": BLOCK, "dt": 1e-4, "rows": rows}


def tilt(engines: list[str], ids: list[str], beta: float | None = None, planar: bool = False) -> dict:
    from analytic.compliant.elastic_tilt import elastic_tilt
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.tilt.check import check_result
    from dem.experiments.tilt.run import TiltProtocol
    from dem.experiments.tilt.run import tilt as run_tilt
    from specimens.blocks import discretise
    from specimens.catalogue import STUDY_JOINTS, get_specimen
    from specimens.constants import NO_SLIDING_MU

    rows = []
    plan = [(sid, eng, STUDY_JOINTS[sid][0], STUDY_JOINTS[sid][2] if beta is None else beta) for eng in engines for sid in ids]
    if "pybullet" in engines:  # how lambda moves with k_n
        plan += [("Sh06-Sd015", "pybullet", kn, STUDY_JOINTS["Sh06-Sd015"][2]) for kn in (1e7, 3e7, 1e8)]
    for sid, eng, kn, beta in plan:
        asm = discretise(get_specimen(sid).arch, config="glued")
        st = Settings(engine=eng, mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, contact_law="compliant", kn=kn,
                      damping_beta=beta, planar=planar)
        t0 = time.perf_counter()
        res = run_tilt(from_assembly(asm, name=sid), st, TiltProtocol(), label=sid, assembly=asm)
        c = check_result(res, asm)
        statics = elastic_tilt(asm, kn).lam  # the same joints by statics: what the DEM should read
        rows.append({"id": sid, "engine": eng, "kn": kn, "beta": beta, "lam": c.lam, "lp_lam": c.lp_lam,
                     "err_pct": c.err_pct, "statics_lam": statics, "err_vs_statics_pct": 100 * (c.lam / statics - 1),
                     "mode": c.mode, "hinges_match_lp": c.hinges_match_lp, "wall_s": time.perf_counter() - t0})
        print(rows[-1], flush=True)
    return {"config": "glued", "planar": planar, "rows": rows}


def shake(ids: list[str], freqs: list[float], workers: int) -> dict:
    from dem.core.settings import Settings
    from dem.experiments.shake.domain import analytic_domains, dem_failure_domain
    from dem.experiments.shake.step_shake import _lowest_threshold
    from specimens.catalogue import STUDY_JOINTS, get_specimen

    rows = []
    for sid in ids:
        arch = get_specimen(sid).arch
        fb = _lowest_threshold(analytic_domains(arch, freqs, workers=1).get("four-bar"))
        kn, _, beta = STUDY_JOINTS[sid]
        for law, st in (("rigid", Settings()), ("table-5.1", Settings(contact_law="compliant", kn=kn, damping_beta=beta))):
            t0 = time.perf_counter()
            dom = dem_failure_domain(sid, arch, freqs, settings=st, workers=workers)
            for t in dom["thresholds"]:
                a = t["amplitude_g"]
                rows.append({"id": sid, "law": law, "freq": t["freq"], "a_dem_g": a, "a_four_bar_g": fb.get(t["freq"]),
                             "ratio": a / fb[t["freq"]] if a is not None and fb.get(t["freq"]) else None,
                             "survival_bands_above": t.get("survival_bands_above"), "n_sims": t.get("n_sims")})
                print(rows[-1], flush=True)
            print(f"{sid} {law}: {time.perf_counter() - t0:.0f} s", flush=True)
    return {"config": "glued", "freqs": freqs, "rows": rows}


def main() -> None:
    from specimens.catalogue import SPECIMEN_IDS

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("part", choices=("vibration", "tilt", "shake"))
    ap.add_argument("--engines", default="pybullet,mujoco")
    ap.add_argument("--ids", default=None, help="specimens (default: the catalogue for tilt, Sd 0.15/0.20 for shake)")
    ap.add_argument("--freqs", default="2,4,6,8,10")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--undamped", action="store_true", help="tilt: the study's k_n without its damping")
    ap.add_argument("--beta", type=float, default=None,
                    help="tilt: this beta_R [s] instead of the study's (MuJoCo's step shrinks as 1 / beta_R)")
    ap.add_argument("--planar", action="store_true", help="tilt: out-of-plane motion removed, as the 2D statics and LP")
    a = ap.parse_args()
    engines = a.engines.split(",")
    if a.part == "vibration":
        out = vibration(engines)
    elif a.part == "tilt":
        out = tilt(engines, a.ids.split(",") if a.ids else list(SPECIMEN_IDS), 0.0 if a.undamped else a.beta, a.planar)
    else:
        ids = a.ids.split(",") if a.ids else [s for s in SPECIMEN_IDS if s.endswith(("Sd015", "Sd020"))]
        out = shake(ids, [float(f) for f in a.freqs.split(",")], a.workers)
    report(f"validate_compliant_{a.part}" + (f"_{a.engines.replace(',', '_')}" if a.part == "tilt" else "")
           + ("_undamped" if a.undamped else f"_beta{a.beta:g}" if a.beta is not None else "")
           + ("_planar" if a.planar else ""), out)


if __name__ == "__main__":
    main()
