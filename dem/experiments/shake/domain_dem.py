"""``archdem domain --engine dem``: the DEM failure domain of an arch over sine frequencies,
optionally plotted over the four-bar and two-bar analytic domains of the same specimen."""
from __future__ import annotations

import argparse

from dem.common.options import (
    arch_from_args,
    contact_law_settings,
    default_of,
    discretisation_kwargs,
    parse_grid,
    piers_from_args,
    print_json,
    writable_file,
)
from dem.experiments.shake.domain import analytic_domains, dem_failure_domain
from specimens.errors import ArchdemInputError


def dem_domain(args: argparse.Namespace) -> int:
    """``archdem domain ID --engine dem --freq 2,4,6,8,10 [--plot FILE] [--json]``."""
    if getattr(args, "block", None) is not None:
        raise ArchdemInputError("--engine dem takes an arch (id or parameters), not --block")
    if getattr(args, "input", "sine") not in ("sine", "sine0"):
        raise ArchdemInputError("--engine dem runs one-cycle sines only (--input sine0)")
    if getattr(args, "durations", None) is not None:
        raise ArchdemInputError("--engine dem takes --freq, not --durations")
    from analytic.domain import failure_domain
    from dem.experiments.shake.step_shake import SHAKE_FREQS
    from specimens.blocks import DEFAULT_DENSITY

    freqs = parse_grid(args.freq) if args.freq is not None else list(SHAKE_FREQS)
    if args.plot:
        writable_file(args.plot, overwrite=False)
    label, arch = arch_from_args(args)
    law = contact_law_settings(args, getattr(args, "id", None))
    dem_a_max = default_of(dem_failure_domain, "a_max_ratio")
    a_max = getattr(args, "amax", dem_a_max)
    # the analytic default (failure_domain's a_max_ratio) is too costly here: the DEM's own default instead
    a_max = dem_a_max if a_max is None or a_max == default_of(failure_domain, "a_max_ratio") else float(a_max)
    res = dem_failure_domain(label, arch, freqs, getattr(args, "config", None) or default_of(dem_failure_domain, "config"),
                             getattr(args, "mu_joint", None), getattr(args, "mu_base", None), a_max_ratio=a_max,
                             workers=getattr(args, "workers", None), disc_kw=discretisation_kwargs(args, arch),
                             scheduler=getattr(args, "scheduler", None), joints=law or None)
    if args.plot:
        from dem.experiments.shake.figure import plot_domain_over_analytic

        density = getattr(args, "density", None) or DEFAULT_DENSITY
        contact = discretisation_kwargs(args, arch).get("contact", 1.0)
        plot_domain_over_analytic(res, analytic_domains(arch, freqs, density, contact=contact,
                                                        piers=piers_from_args(args)), args.plot,
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
