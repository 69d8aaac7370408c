"""``archdem domain --engine dem``: the DEM failure domain of an arch over sine frequencies,
optionally plotted over the four-bar and two-bar analytic domains of the same specimen.

:func:`dem_domain` is the hook called by ``dem/cli/dynamics_cmd.py`` with its parsed options;
:func:`dem_failure_domain` is the plain function behind it.
"""
from __future__ import annotations

import argparse
import math
from typing import Sequence

from specimens.errors import ArchdemInputError


def static_onset(arch, config: str, mu_joint: float, mu_base: float, disc_kw: dict | None = None) -> float:
    """Static collapse multiplier ``lambda`` of the discretised arch (LP, :func:`analytic.limit_discrete.solve_lp`)."""
    from analytic.limit_discrete import solve_lp
    from specimens.blocks import discretise

    lp = solve_lp(discretise(arch, config=config, **(disc_kw or {})), mu_joint, mu_base)
    return float(lp.lam)


def dem_failure_domain(label: str, arch, freqs: Sequence[float], config: str = "glued", mu_joint: float | None = None,
                       mu_base: float | None = None, a_max_ratio: float = 6.0, scan_ratio: float = 1.15,
                       tol: float = 0.01, workers: int | None = None, disc_kw: dict | None = None,
                       settings=None, protocol=None) -> dict:
    """DEM failure domain of ``arch`` (one-cycle plain sines at ``freqs`` [Hz]).

    The amplitude scan runs from the static onset ``lambda g`` (LP with the same friction;
    nothing moves below it) to ``a_max_ratio lambda g``. Returns the dict of
    :func:`dem.thresholds.failure_domain` plus ``id``, ``lambda``, ``config``, ``mu_joint``, ``mu_base``.
    """
    from dem.model import from_assembly
    from dem.settings import Settings
    from dem.thresholds import failure_domain
    from specimens.blocks import discretise
    from specimens.catalogue import REFERENCE_MU_BASE, REFERENCE_MU_JOINT

    mu_j = REFERENCE_MU_JOINT if mu_joint is None else float(mu_joint)
    mu_b = REFERENCE_MU_BASE if mu_base is None else float(mu_base)
    lam = static_onset(arch, config, mu_j, mu_b, disc_kw)
    if not (math.isfinite(lam) and lam > 0):
        raise ArchdemInputError(f"{label}: the arch has no positive static collapse multiplier (lambda = {lam})")
    model = from_assembly(discretise(arch, config=config, **(disc_kw or {})), name=label)
    st = settings or Settings(mu_joint=mu_j, mu_base=mu_b)
    out = failure_domain(model, freqs, st, protocol, workers=workers, a_min_g=lam, a_max_g=a_max_ratio * lam,
                         scan_ratio=scan_ratio, tol=tol)
    out.update({"id": label, "lambda": lam, "config": config, "mu_joint": mu_j, "mu_base": mu_b,
                "input": "sine0", "a_range_g": [lam, a_max_ratio * lam]})
    return out


def analytic_domains(arch, freqs: Sequence[float], density: float = 500.0, workers: int | None = 1) -> dict:
    """Four-bar (minimised layout) and two-bar analytic domains of ``arch`` for the plain sine
    (``sine0``, the DEM input) at ``freqs``: name -> :class:`analytic.domain.FailureDomain`."""
    from analytic import linkage
    from analytic.domain import failure_domain

    out = {}
    fb = linkage.arch_four_bar(arch, linkage.minimised_layout(arch, density), density, direction=1)
    out["four-bar"] = failure_domain(fb, "sine0", freqs, a_max_ratio=10.0, n_scan=24, tol=1e-3, workers=workers)
    try:
        tb = linkage.arch_two_bar(arch, density, direction=1)
        out["two-bar"] = failure_domain(tb, "sine0", freqs, a_max_ratio=10.0, n_scan=24, tol=1e-3, workers=workers)
    except ArchdemInputError:  # pragma: no cover - two-bar not defined for this geometry
        pass
    return out


def dem_domain(args: argparse.Namespace) -> int:
    """``archdem domain ID --engine dem --freq 2,4,6,8,10 [--plot FILE] [--json]``."""
    from dem.cli.common import arch_from_args, discretisation_kwargs, print_json, writable_file
    from dem.cli.dynamics_cmd import parse_grid

    if getattr(args, "block", None) is not None:
        raise ArchdemInputError("--engine dem takes an arch (id or parameters), not --block")
    if getattr(args, "input", "sine") not in ("sine", "sine0"):
        raise ArchdemInputError("--engine dem runs one-cycle sines only (--input sine0)")
    if getattr(args, "durations", None) is not None:
        raise ArchdemInputError("--engine dem takes --freq, not --durations")
    freqs = parse_grid(args.freq or "2,4,6,8,10")
    if args.plot:
        writable_file(args.plot, overwrite=False)
    label, arch = arch_from_args(args)
    a_max = getattr(args, "amax", 6.0)
    a_max = 6.0 if a_max is None or a_max == 10.0 else float(a_max)  # 10 (the analytic default) is too costly here
    res = dem_failure_domain(label, arch, freqs, getattr(args, "config", None) or "glued",
                             getattr(args, "mu_joint", None), getattr(args, "mu_base", None), a_max_ratio=a_max,
                             workers=getattr(args, "workers", None), disc_kw=discretisation_kwargs(args))
    if args.plot:
        from dem.figures_shake import plot_domain_over_analytic

        density = getattr(args, "density", None) or 500.0
        plot_domain_over_analytic(res, analytic_domains(arch, freqs, density), args.plot,
                                  title=f"{label}: DEM vs rocking linkages, one-cycle sine")
        res["plot"] = str(args.plot)
    if args.json:
        print_json({k: v for k, v in res.items() if k != "thresholds"} | {"thresholds": [
            {k: t[k] for k in ("freq", "amplitude_g", "bracket_g", "mode", "collapse_phase", "n_sims")}
            for t in res["thresholds"]]})
        return 0
    print(f"{label}  DEM ({res['config']}, mu {res['mu_joint']:g}/{res['mu_base']:g})  static lambda {res['lambda']:.4f}")
    for t in res["thresholds"]:
        a = "none up to %.3f g" % res["a_range_g"][1] if t["amplitude_g"] is None else f"{t['amplitude_g']:.4f} g"
        above = ", ".join(f"{b['from_g']:.3f}-{b['to_g']:.3f} g" for b in t["survival_bands_above"])
        print(f"  {t['freq']:6.3g} Hz: collapse from {a}" + (f"; survives again {above}" if above else ""))
    if args.plot:
        print(f"figure: {args.plot}")
    return 0


__all__ = ["dem_domain", "dem_failure_domain", "analytic_domains", "static_onset"]
