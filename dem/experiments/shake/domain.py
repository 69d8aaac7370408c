"""The DEM failure domain of an arch over sine frequencies (:func:`dem_failure_domain`), and the
four-bar and two-bar analytic domains of the same arch to set beside it (:func:`analytic_domains`)."""
from __future__ import annotations

import math
from typing import Sequence

from analytic.rocking.domain import failure_domain as linkage_domain
from dem.core.model import as_model
from dem.core.progress import Progress
from dem.core.settings import Settings, dynamics_settings
from dem.experiments.shake import thresholds
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from foundation.errors import ArchdemInputError


def dem_failure_domain(label: str, arch, freqs: Sequence[float], config: str = "glued", mu_joint: float | None = None,
                       mu_base: float | None = None, a_max_ratio: float = 6.0, scan_ratio: float = 1.15,
                       tol: float = 0.01, workers: int | None = None, disc_kw: dict | None = None,
                       settings=None, protocol=None, scheduler: str | None = None, joints: dict | None = None,
                       engine: str | None = None, dt: float | None = None, progress: Progress | None = None) -> dict:
    """DEM failure domain of ``arch`` (one-cycle plain sines at ``freqs`` [Hz]).

    The amplitude scan runs from the static onset ``lambda g`` (LP with the same friction;
    nothing moves below it) to ``a_max_ratio lambda g``. Returns the dict of
    :func:`dem.experiments.shake.thresholds.failure_domain` plus ``id``, ``lambda``, ``config``, ``mu_joint``, ``mu_base``.
    ``joints``: contact-law fields of :class:`dem.core.settings.Settings` (rigid if None); ``engine``
    and ``dt`` [s]: the physics engine and its time step (defaults: the settings'); all three unless
    ``settings`` is given. ``progress(done, total, note)``: called as each frequency's threshold is found
    (:mod:`dem.core.progress`).
    """
    mu_j = REFERENCE_MU_JOINT if mu_joint is None else float(mu_joint)
    mu_b = REFERENCE_MU_BASE if mu_base is None else float(mu_base)
    model = as_model(arch, config=config, name=label, **(disc_kw or {}))
    lam = thresholds.static_onset(model, Settings(mu_joint=mu_j, mu_base=mu_b))
    if not (math.isfinite(lam) and lam > 0):
        raise ArchdemInputError(f"{label}: the arch has no positive static collapse multiplier (lambda = {lam})")
    run = {k: v for k, v in (("engine", engine), ("dt", dt)) if v is not None}
    st = settings or dynamics_settings(mu_joint=mu_j, mu_base=mu_b, **(joints or {}), **run)
    out = thresholds.failure_domain(model, freqs, st, protocol, workers=workers, a_min_g=lam, a_max_g=a_max_ratio * lam,
                         scan_ratio=scan_ratio, tol=tol, scheduler=scheduler, progress=progress)
    out.update({"id": label, "lambda": lam, "config": config, "mu_joint": mu_j, "mu_base": mu_b,
                "physics_engine": st.engine, "dt": st.dt,
                "input": "sine0", "a_range_g": [lam, a_max_ratio * lam]})
    return out


def analytic_domains(arch, freqs: Sequence[float], density: float = 500.0, workers: int | None = 1,
                     contact: float = 1.0, piers=None) -> dict:
    """Four-bar (minimised layout) and two-bar analytic domains of ``arch`` for the plain sine
    (``sine0``, the DEM input) at ``freqs``: name -> :class:`analytic.rocking.domain.FailureDomain`.
    With an effective ``contact`` < 1 only the four-bar (the two-bar does not model it); on
    ``piers`` only the four-bar of the discrete mechanism through them."""
    # deferred: `archdem --help` imports this module, not the linkages (scipy) (docs/architecture.md#imports)
    from analytic.rocking import linkage

    out = {}
    fb = linkage.governing_four_bar(arch, density, contact, piers)
    out["four-bar"] = linkage_domain(fb, "sine0", freqs, a_max_ratio=10.0, n_scan=24, tol=1e-3, workers=workers)
    if contact != 1.0 or piers is not None:
        return out
    try:
        tb = linkage.arch_two_bar(arch, density, direction=1)
        out["two-bar"] = linkage_domain(tb, "sine0", freqs, a_max_ratio=10.0, n_scan=24, tol=1e-3, workers=workers)
    except ArchdemInputError:  # pragma: no cover - two-bar not defined for this geometry
        pass
    return out


__all__ = ["dem_failure_domain", "analytic_domains"]
