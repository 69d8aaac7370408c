"""Full validation of the DEM (docs/validation.md#1-how-to-reproduce) on the 11 catalogue specimens, glued and free.

For each specimen and configuration: rest drift over 5 s (reference friction), tilt lambda with
no sliding (mu = 10 everywhere) against the discrete LP, hinge joints against the LP layout (or
a four-hinge mechanism within 0.5 % of its lambda), and tilt lambda at the reference friction
(0.577 / 1.0) against the no-sliding value and against the associative LP and the non-associative
multiplier of the same blocks (the three-way check). Writes benchmarks/results/validate_dem.json and .md.

    python benchmarks/validate_dem.py [--ids a,b] [--configs glued,free] [--workers 2] [--start lp|scan]
                                      [--hold-time S] [--ramp-time S] [--engine pybullet|mujoco] [--no-rest]
                                      [--guess-bracket LO,HI] [--probe-ends first|last] [--iterations N]
                                      [--contact C]

Each hold-and-bisect starts at the static LP of the same blocks at the run's friction (the
default protocol); ``--start scan`` starts it from the ramp scan instead;
``--hold-time`` sets how long each level is held and ``--ramp-time`` how long the smooth ramp to
it lasts (default: the protocol's); ``--no-rest`` holds every level the full hold time (no rest
rule, ``TiltProtocol.rest_after = None``; files named ``..._norest``); ``--engine`` runs everything
with the other engine (files named ``..._mujoco``); ``--guess-bracket LO,HI`` starts every bisection
from (LO, HI) x the LP instead of ``TiltProtocol.guess_bracket`` (files named ``..._bracketLO-HI``);
``--probe-ends first`` simulates both ends of that bracket before bisecting instead of
``TiltProtocol.probe_ends`` (files named ``..._probefirst``); ``--iterations N`` runs every
simulation with N solver iterations per step instead of ``PyBulletOptions.solver_iterations`` (files
named ``..._itN``); ``--contact C`` cuts every specimen with effective contact C (relieved joints,
against the LP at the same contact; files named ``..._contactC``).
"""
from __future__ import annotations

import argparse
import json
import math
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

OUT = Path(__file__).resolve().parent / "results"


def rest_drift(sid: str, config: str, seconds: float = 5.0, engine: str = "pybullet", contact: float = 1.0,
               **settings_kw) -> float:
    """Largest displacement of any body point after ``seconds`` at rest [m]."""
    from dem.core.loads import Rest
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.core.simulate import simulate
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    m = from_assembly(discretise(get_specimen(sid).arch, config=config, contact=contact), name=sid)
    r = simulate(m, Settings(engine=engine, **settings_kw), Rest(), seconds, record_every=0.1, stop_on_collapse=False, friction_work=False)
    return float(r.history.dmax.max())


def hinge_match(assembly, dem_hinges, lp_lam: float, tol: float = 0.005) -> tuple[bool, float]:
    """True if the DEM hinges are the LP layout, or a four-hinge mechanism within ``tol`` of lambda."""
    from analytic.limit.limit_discrete import enumerate_mechanisms

    k = enumerate_mechanisms(assembly)
    if tuple(dem_hinges) == tuple(k.hinges):
        return True, float(k.lam)
    from analytic.limit.limit_discrete import mechanism_lambda

    lam = mechanism_lambda(assembly, dem_hinges)
    return bool(np.isfinite(lam) and abs(lam - lp_lam) <= tol * lp_lam), lam


def one(job: tuple[str, str, bool, str, dict, dict, float]) -> dict:
    """One specimen and configuration; ``job[4]``: TiltProtocol fields that differ from the defaults;
    ``job[5]``: Settings fields that differ from the defaults (other than friction and engine);
    ``job[6]``: the effective contact."""
    sid, config, with_drift, engine, proto_kw, settings_kw, contact = job
    from analytic.limit.non_associative import solve_non_associative
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.tilt.check import check_result, na_joints, reference_lp, same_mechanism
    from dem.experiments.tilt.run import TiltProtocol, tilt
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen
    from specimens.constants import NO_SLIDING_MU, REFERENCE_MU_BASE, REFERENCE_MU_JOINT

    asm = discretise(get_specimen(sid).arch, config=config, contact=contact)
    m = from_assembly(asm, name=sid)
    lp = reference_lp(asm, NO_SLIDING_MU, NO_SLIDING_MU)  # exact with no sliding: a collapse below it is spurious
    lp_ref = reference_lp(asm, REFERENCE_MU_JOINT, REFERENCE_MU_BASE)  # associative: no bound
    na = solve_non_associative(asm, REFERENCE_MU_JOINT, REFERENCE_MU_BASE)  # Coulomb without dilatancy
    t0 = time.perf_counter()
    proto = TiltProtocol(**proto_kw)

    def logged_tilt(settings, lp_lam: float) -> tuple:
        """The tilt test and every held level: (lambda / LP, collapsed, time into the hold at collapse [s],
        time into the hold at which it was ended at rest [s]; None if not)."""
        levels = []

        def log(lam, r):
            levels.append((lam / lp_lam, bool(r.collapsed), float(r.t_collapse - proto.ramp_time) if r.collapsed else None,
                           None if math.isnan(r.t_rest) else float(r.t_rest - proto.ramp_time)))

        return tilt(m, settings, proto, label=sid, assembly=asm, on_level=log), levels

    ns, levels = logged_tilt(Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU, engine=engine, **settings_kw), lp.lam)
    ref, levels_ref = logged_tilt(Settings(engine=engine, **settings_kw), lp_ref.lam)
    row = check_result(ns, asm, lp)
    hinges = list(row.hinges)
    ok, lam_h = hinge_match(asm, hinges, lp.lam)
    drift = rest_drift(sid, config, engine=engine, contact=contact, **settings_kw) if with_drift else float("nan")
    return {
        "id": sid, "config": config, "engine": engine, "contact": contact, "start": proto.start, "hold_time": proto.hold_time, "ramp_time": proto.ramp_time,
        "rest_after": proto.rest_after, "guess_bracket": list(proto.guess_bracket),
        "probe_ends": proto.probe_ends, "settings": ns.settings.to_dict(),
        "lp_lambda": lp.lam, "lp_hinges": list(lp.hinges),
        "dem_lambda_nosliding": ns.lam, "levels_nosliding": levels, "bracket_nosliding": list(ns.bracket), "n_sims_nosliding": ns.n_sims,
        "rel_err": row.rel_err, "dem_hinges": hinges, "hinges_match": ok,
        "dem_hinges_lambda": lam_h, "mode_nosliding": ns.mode,
        "dem_lambda_ref": ref.lam, "mode_ref": ref.mode, "lp_lambda_ref_associative": lp_ref.lam,
        "ref_joints": [(j.joint, j.state) for j in ref.joints if j.state != "closed"],
        "lp_lambda_ref_non_associative": na.lam, "na_optimal": na.optimal, "na_gap": na.gap, "na_seconds": na.seconds,
        "na_joints": list(na_joints(na).items()), "ref_same_mechanism_as_na": same_mechanism(ref.joints, na),
        "n_sims_ref": ref.n_sims, "levels_ref": levels_ref, "ref_le_nosliding_plus_1pc": ref.lam <= 1.01 * ns.lam, "rest_drift_5s_m": drift,
        "out_of_plane_ref": ref.out_of_plane, "wall_s": time.perf_counter() - t0,
    }


def sensitivity(job: tuple[str, str]) -> dict:
    """No-sliding lambda at the defaults, with dt halved, and with the hold ramp twice as slow."""
    sid, variant = job
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.tilt.run import TiltProtocol, tilt
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen
    from specimens.constants import NO_SLIDING_MU

    asm = discretise(get_specimen(sid).arch, config="glued")
    m = from_assembly(asm, name=sid)
    s = Settings(mu_joint=NO_SLIDING_MU, mu_base=NO_SLIDING_MU)
    p = TiltProtocol()
    if variant == "dt/2":
        s = s.with_(dt=s.dt / 2)
    elif variant == "ramp rate/2":
        p = p.slowed(2.0)  # every duration of the protocol doubled, the rest rule's included
    r = tilt(m, s, p, assembly=asm)
    return {"id": sid, "variant": variant, "lambda": r.lam, "bracket": list(r.bracket), "wall_s": r.wall_s}


def main() -> None:
    from specimens.catalogue import SPECIMEN_IDS

    ap = argparse.ArgumentParser()
    ap.add_argument("--ids", default="all")
    ap.add_argument("--configs", default="glued,free")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--sensitivity", action="store_true", help="only the dt / ramp-rate insensitivity check")
    ap.add_argument("--start", choices=("scan", "lp"), default="lp", help="first bracket: static LP (default) or ramp scan")
    ap.add_argument("--hold-time", dest="hold", type=float, default=None, help="hold per level [s] (default: protocol's)")
    ap.add_argument("--ramp-time", dest="ramp", type=float, default=None,
                    help="smooth ramp to each level [s] (default: protocol's)")
    ap.add_argument("--engine", choices=("pybullet", "mujoco"), default="pybullet")
    ap.add_argument("--no-rest", dest="rest", action="store_false", help="hold every level the full hold time")
    ap.add_argument("--no-drift", dest="drift", action="store_false", help="skip the 5 s rest-drift runs")
    ap.add_argument("--guess-bracket", dest="bracket", default=None, metavar="LO,HI",
                    help="first bracket x the LP (default: TiltProtocol.guess_bracket)")
    ap.add_argument("--iterations", type=int, default=None, help="PyBullet's solver iterations per step (default: PyBulletOptions')")
    ap.add_argument("--probe-ends", dest="probe", choices=("first", "last"), default=None,
                    help="when the first bracket's ends are simulated (default: TiltProtocol.probe_ends)")
    ap.add_argument("--contact", type=float, default=1.0, help="effective contact of every joint (default 1)")
    a = ap.parse_args()
    bracket = tuple(float(x) for x in a.bracket.split(",")) if a.bracket else None
    if a.sensitivity:
        jobs = [(s, v) for s in ("Sh02-Sd020", "Sh06-Sd015") for v in ("default", "dt/2", "ramp rate/2")]
        with ProcessPoolExecutor(a.workers) as ex:
            rows = list(ex.map(sensitivity, jobs))
        OUT.mkdir(parents=True, exist_ok=True)
        (OUT / "validate_dem_sensitivity.json").write_text(json.dumps(rows, indent=1))
        for r in rows:
            print(r)
        return
    ids = SPECIMEN_IDS if a.ids == "all" else a.ids.split(",")
    proto_kw = {"start": a.start, **{k: v for k, v in (("hold_time", a.hold), ("ramp_time", a.ramp), ("guess_bracket", bracket),
                                                        ("probe_ends", a.probe)) if v is not None},
                **({} if a.rest else {"rest_after": None})}
    if a.iterations is not None and a.engine != "pybullet":
        ap.error("--iterations sets PyBullet's solver iterations (--engine pybullet)")
    settings_kw = {} if a.iterations is None else {"engine_options": {"solver_iterations": a.iterations}}
    jobs = [(s, c, a.drift, a.engine, proto_kw, settings_kw, a.contact) for c in a.configs.split(",") for s in ids]
    stem = ("validate_dem" if a.start == "lp" else "validate_dem_scan_start") + (f"_hold{a.hold:g}" if a.hold else "") \
        + (f"_ramp{a.ramp:g}" if a.ramp else "") + ("" if a.rest else "_norest") \
        + (f"_bracket{bracket[0]:g}-{bracket[1]:g}" if bracket else "") + (f"_probe{a.probe}" if a.probe else "") \
        + (f"_it{a.iterations}" if a.iterations else "") + ("" if a.engine == "pybullet" else f"_{a.engine}") \
        + ("" if a.contact == 1.0 else f"_contact{a.contact:g}")
    t0 = time.perf_counter()
    with ProcessPoolExecutor(a.workers) as ex:
        rows = list(ex.map(one, jobs))
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / f"{stem}.json").write_text(json.dumps({"rows": rows, "wall_s": time.perf_counter() - t0}, indent=1))
    lines = ["| id | config | LP lambda | DEM lambda (mu=10) | err % | sims | hinges match | DEM lambda ref | mode ref | "
             "sims ref | ref <= ns+1% | drift 5 s [mm] |", "|" + "---|" * 12]
    for r in rows:
        lines.append(f"| {r['id']} | {r['config']} | {r['lp_lambda']:.4f} | {r['dem_lambda_nosliding']:.4f} | "
                     f"{100 * r['rel_err']:+.2f} | {r['n_sims_nosliding']} | {r['hinges_match']} | {r['dem_lambda_ref']:.4f} | "
                     f"{r['mode_ref']} | {r['n_sims_ref']} | "
                     f"{r['ref_le_nosliding_plus_1pc']} | {1e3 * r['rest_drift_5s_m']:.3f} |")
    err = np.array([abs(r["rel_err"]) for r in rows])
    lines.append("")
    lines.append(f"start {a.start}: mean |err| {100 * err.mean():.2f} %, within 3 % {int(np.sum(err <= 0.03))}/{len(rows)}, "
                 f"within 2 % {int(np.sum(err <= 0.02))}/{len(rows)}, hinges {sum(r['hinges_match'] for r in rows)}/{len(rows)}, "
                 f"ref <= ns + 1 % {sum(r['ref_le_nosliding_plus_1pc'] for r in rows)}/{len(rows)}, simulations "
                 f"{sum(r['n_sims_nosliding'] + r['n_sims_ref'] for r in rows)}, wall {time.perf_counter() - t0:.0f} s")
    col = [(f, t) for r in rows for f, c, t, _ in r["levels_nosliding"] if c]
    up = [t for f, t in col if f >= 1.0]
    late = sorted((round(t, 2), round(f, 4)) for f, t in col if t > max(up or [0.0]))  # after every genuine one
    lines.append(f"no-sliding held levels: {len(up)} collapses at or above the LP, within {max(up or [float('nan')]):.2f} s "
                 f"of the hold; {len(col) - len(up)} below it (spurious); late collapses (s into the hold, lambda/LP): {late}")
    col_ref = sorted(round(t, 2) for r in rows for f, c, t, _ in r["levels_ref"] if c)
    lines.append(f"reference-friction held levels: {len(col_ref)} collapses, times into the hold [s]: {col_ref}")
    held = [lv for r in rows for lv in r["levels_nosliding"] + r["levels_ref"] if not lv[1]]
    at_rest = sorted(round(lv[3], 2) for lv in held if lv[3] is not None)
    lines.append(f"stable held levels: {len(held)}, ended at rest {len(at_rest)} "
                 f"(times into the hold [s]: {sorted(set(at_rest))})")
    lines += ["", "Three-way check at the reference friction: associative LP, non-associative multiplier (NA), DEM tilt",
              "", "| id | config | LP (associative) | NA | NA below LP % | DEM | DEM vs NA % | DEM mechanism | "
              "NA mechanism | same | MIP [s] |", "|" + "---|" * 11]
    for r in rows:
        na = r["lp_lambda_ref_non_associative"]
        lines.append(f"| {r['id']} | {r['config']} | {r['lp_lambda_ref_associative']:.4f} | {na:.4f} | "
                     f"{100 * (1 - na / r['lp_lambda_ref_associative']):.2f} | {r['dem_lambda_ref']:.4f} | "
                     f"{100 * (r['dem_lambda_ref'] / na - 1):+.2f} | "
                     f"{' '.join(f'{j}:{st}' for j, st in r['ref_joints'])} | {' '.join(f'{j}:{st}' for j, st in r['na_joints'])} | "
                     f"{'yes' if r['ref_same_mechanism_as_na'] else 'no'} | {r['na_seconds']:.1f}{'' if r['na_optimal'] else ' (gap)'} |")
    same = [r for r in rows if r["ref_same_mechanism_as_na"]]
    dev = np.array([r["dem_lambda_ref"] / r["lp_lambda_ref_non_associative"] - 1 for r in same]) if same else np.zeros(0)
    lines.append("")
    lines.append(f"same mechanism in {len(same)}/{len(rows)}; there the DEM is {100 * dev.min():+.2f} to {100 * dev.max():+.2f} % "
                 f"from the non-associative multiplier (within 3 %: {int(np.sum(np.abs(dev) <= 0.03))}/{len(same)}); "
                 f"MIPs optimal {sum(r['na_optimal'] for r in rows)}/{len(rows)}" if same else "same mechanism in none")
    (OUT / f"{stem}.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
