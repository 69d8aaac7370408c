"""Calibration of the imperfect-fit model on laboratory tilt tests (docs/physics/geometry.md#13-imperfect-fit).

The model: every joint loses a strip of width ``edge_loss`` [m] at each edge, so an arch of ring
thickness ``t`` touches over ``c = 1 - 2 edge_loss / t`` of its joints
(:class:`specimens.imperfection.Imperfection`). One length for every specimen: thin rings lose a
larger share of their joints, as the laboratory saw. The fit:

* ``edge_loss`` minimises the sum of squared relative residuals ``(lambda_LP / lambda_lab - 1)^2``
  of the static LP of the glued blocks at the reference friction (the DEM reproduces that LP
  within a few per cent, docs/validation.md#13-effective-contact);
* ``edge_loss_sd``, the scatter of each edge's loss, makes the coefficient of variation of the LP
  over seeded realisations match the laboratory's, pooled over the specimens (least squares,
  taking the model's CoV as proportional to the scatter, then checked at the fitted value);
* **leave-one-out**: each specimen predicted by the ``edge_loss`` fitted on the others — the
  measure of the model, since a fit always looks good on the data it was fitted to.

For comparison the same is done for one contact *fraction* common to all specimens.
"""
from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from specimens.blocks import discretise
from specimens.catalogue import CATALOGUE, SPECIMEN_WIDTH
from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT
from foundation.errors import ArchdemInputError
from foundation.io import atomic_path, to_json, writable_file
from specimens.geometry import PointedArch
from specimens.imperfection import Imperfection

#: The laboratory table shipped with archdem (six specimens of the catalogue).
LAB_TILT_TESTS = Path(__file__).resolve().parents[2] / "specimens" / "data" / "laboratory_tilt_tests.csv"
#: Where ``archdem calibrate`` stores its result and ``--contact calibrated`` reads it.
CALIBRATION_FILE = Path("runs") / "calibration" / "contact.json"
#: The calibration on ``LAB_TILT_TESTS``, used when ``CALIBRATION_FILE`` does not exist.
SHIPPED_CALIBRATION = LAB_TILT_TESTS.parent / "contact_calibration.json"
REQUIRED_COLUMNS = ("id", "lambda_mean", "lambda_sd", "observed_mode")
GEOMETRY_COLUMNS = ("Ri_mm", "Re_mm", "e_mm")
#: Realisations per specimen of the scatter fit (a CoV to about 15 % of itself).
SCATTER_REALISATIONS = 24
SCATTER_SEED = 20261125


@dataclass(frozen=True)
class TiltTest:
    """One specimen's laboratory tilt tests: multiplier mean and sd, number of tests, observed mode."""

    id: str
    arch: PointedArch
    lambda_mean: float
    lambda_sd: float
    n_tests: int
    mode: str  # "rocking" or "sliding"
    mode_text: str


#: How far a catalogue specimen's Ri_mm, Re_mm, e_mm may stand from the catalogue's [m] (a table rounds to the mm).
GEOMETRY_TOL = 1e-3


def read_experiments(path: str | Path) -> list[TiltTest]:
    """The laboratory table ``path`` (CSV, ``#`` comment lines): columns ``id``, ``lambda_mean``,
    ``lambda_sd``, ``observed_mode`` (first word rocking / sliding), optional ``n_tests``; ids of
    the catalogue, or any id with ``Ri_mm``, ``Re_mm``, ``e_mm``."""
    p = Path(path)
    try:
        lines = [ln for ln in p.read_text().splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    except (OSError, UnicodeDecodeError) as exc:
        raise ArchdemInputError(f"cannot read the experiments file {p}: {exc}") from None
    rows = list(csv.DictReader(lines))
    if not rows:
        raise ArchdemInputError(f"{p}: no laboratory tests in the file")
    missing = [c for c in REQUIRED_COLUMNS if c not in rows[0]]
    if missing:
        raise ArchdemInputError(f"{p}: missing column(s) {', '.join(missing)} (need {', '.join(REQUIRED_COLUMNS)})")
    known = {s.id: s for s in CATALOGUE}
    out = []
    for k, r in enumerate(rows, start=2):
        sid = (r["id"] or "").strip()
        try:
            mean, sd = float(r["lambda_mean"]), float(r["lambda_sd"])
            n = int(r.get("n_tests") or 1)
        except (TypeError, ValueError):
            raise ArchdemInputError(f"{p}, row {k} ({sid}): lambda_mean, lambda_sd and n_tests must be numbers") from None
        if not (math.isfinite(mean) and mean > 0 and math.isfinite(sd) and sd > 0 and n >= 1):
            raise ArchdemInputError(f"{p}, row {k} ({sid}): need lambda_mean > 0, lambda_sd > 0 (the fit weighs each "
                                    "test by it), n_tests >= 1")
        mode_text = (r["observed_mode"] or "").strip()
        mode = mode_text.split(":")[0].split()[0].lower() if mode_text else ""
        if mode not in ("rocking", "sliding"):
            raise ArchdemInputError(f"{p}, row {k} ({sid}): observed_mode must start with rocking or sliding")
        geometry = [(r.get(c) or "").strip() for c in GEOMETRY_COLUMNS]
        if any(geometry):
            try:
                Ri, Re, e = (float(v) / 1000 for v in geometry)
            except ValueError:
                raise ArchdemInputError(f"{p}, row {k} ({sid}): Ri_mm, Re_mm, e_mm must be numbers") from None
            if not (all(map(math.isfinite, (Ri, Re, e))) and 0 < Ri < Re and e >= 0):
                raise ArchdemInputError(f"{p}, row {k} ({sid}): need 0 < Ri_mm < Re_mm and e_mm >= 0")
        if sid in known:
            arch = known[sid].arch
            # a catalogue specimen's columns are checked, not ignored: the table gives them to the mm
            if any(geometry) and max(abs(a - b) for a, b in zip((Ri, Re, e), (arch.Ri, arch.Re, arch.e))) > GEOMETRY_TOL:
                raise ArchdemInputError(f"{p}, row {k} ({sid}): Ri_mm, Re_mm, e_mm {'/'.join(geometry)} are not the "
                                        f"catalogue's {arch.Ri * 1e3:g}/{arch.Re * 1e3:g}/{arch.e * 1e3:g} mm")
        elif all(geometry):
            arch = PointedArch.from_radii(Ri, Re, e, width=SPECIMEN_WIDTH)
        else:
            raise ArchdemInputError(f"{p}, row {k}: unknown specimen id {sid!r} (not in the catalogue and no "
                                    f"{', '.join(GEOMETRY_COLUMNS)} columns)")
        ideal = lp_lambda(arch, 1.0)
        if mean > ideal + 3 * sd:  # no edge loss raises the multiplier above the full joints'
            raise ArchdemInputError(f"{p}, row {k} ({sid}): lambda_mean {mean:g} is beyond the multiplier of the arch "
                                    f"with full joints ({ideal:.3f}) by more than 3 sd: not a tilt test of this arch")
        out.append(TiltTest(sid, arch, mean, sd, n, mode, mode_text))
    if len({t.id for t in out}) != len(out):
        raise ArchdemInputError(f"{p}: a specimen id appears twice")
    return out


def lp_lambda(arch: PointedArch, contact: float, bands=None) -> float:
    """Static LP multiplier of the glued blocks at the reference friction, at ``contact``."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.limit.limit_discrete import solve_lp

    return float(solve_lp(discretise(arch, config="glued", contact=contact, bands=bands),
                          REFERENCE_MU_JOINT, REFERENCE_MU_BASE).lam)


def _contact(arch: PointedArch, edge_loss: float) -> float:
    return 1.0 - 2.0 * edge_loss / arch.t


def _fit(tests: list[TiltTest], model: str) -> float:
    """The parameter (edge loss [m] or contact fraction) minimising the squared relative residuals."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from scipy.optimize import minimize_scalar

    t_min = min(t.arch.t for t in tests)
    # bounds: a contact of 0.4 on the thinnest ring at most (thin rings stop standing below it)
    lo, hi = (0.0, 0.3 * t_min) if model == "edge-loss" else (0.4, 1.0)

    def cost(x: float) -> float:
        s = 0.0
        for t in tests:
            c = _contact(t.arch, x) if model == "edge-loss" else x
            lam = lp_lambda(t.arch, c)
            s += (lam / t.lambda_mean - 1.0) ** 2 if math.isfinite(lam) else 1e3
        return s

    return float(minimize_scalar(cost, bounds=(lo, hi), method="bounded", options={"xatol": 1e-6 * (hi - lo)}).x)


def _cov(arch: PointedArch, edge_loss: float, edge_loss_sd: float, n: int, seed: int) -> float:
    """CoV of the LP multiplier over ``n`` realisations of the imperfect joints."""
    imp = Imperfection(edge_loss, edge_loss_sd)
    nominal = discretise(arch, config="glued", contact=imp.contact(arch))
    lams = np.array([lp_lambda(arch, nominal.contact, imp.bands(nominal, seed, k)) for k in range(n)])
    return float(lams.std(ddof=1) / lams.mean())


@dataclass(frozen=True)
class Calibration:
    """Fitted imperfect-fit model and how well it fits and predicts (JSON-ready via :meth:`to_json`)."""

    edge_loss: float  # [m]
    edge_loss_sd: float  # [m]
    rows: list[dict] = field(default_factory=list)
    loo_rms_pct: float = math.nan
    fraction: float = math.nan
    fraction_loo_rms_pct: float = math.nan
    source: str = ""

    def contact(self, arch: PointedArch) -> float:
        """The calibrated effective contact of ``arch``."""
        return Imperfection(self.edge_loss).contact(arch)

    def to_json(self) -> dict:
        return {"model": "edge-loss", "edge_loss_mm": self.edge_loss * 1e3, "edge_loss_sd_mm": self.edge_loss_sd * 1e3,
                "specimens": self.rows, "loo_rms_pct": self.loo_rms_pct,
                "alternative": {"model": "contact fraction", "contact": self.fraction,
                                "loo_rms_pct": self.fraction_loo_rms_pct},
                "experiments": self.source}

    def save(self, path: str | Path, replace: bool = False) -> None:
        """Write the calibration to ``path`` at once (never half a file); an existing one only with ``replace``."""
        with atomic_path(path, overwrite=replace) as tmp:
            tmp.write_text(to_json(self.to_json(), indent=2))

    @classmethod
    def from_json(cls, d: dict) -> "Calibration":
        try:
            return cls(float(d["edge_loss_mm"]) / 1e3, float(d["edge_loss_sd_mm"]) / 1e3, list(d.get("specimens", [])),
                       float(d.get("loo_rms_pct", math.nan)), float(d.get("alternative", {}).get("contact", math.nan)),
                       float(d.get("alternative", {}).get("loo_rms_pct", math.nan)), str(d.get("experiments", "")))
        except (KeyError, TypeError, ValueError):
            raise ArchdemInputError("the calibration file is not one archdem calibrate wrote (edge_loss_mm missing)") from None


def calibrate(tests: list[TiltTest], scatter: bool = True, source: str = "") -> Calibration:
    """Fit the edge loss (and, with ``scatter``, its scatter) to ``tests``; leave-one-out errors."""
    if len(tests) < 2:
        raise ArchdemInputError("calibration needs laboratory tests of at least two specimens")
    d = _fit(tests, "edge-loss")
    f = _fit(tests, "fraction")
    rows = []
    for i, t in enumerate(tests):
        others = tests[:i] + tests[i + 1:]
        d_loo, f_loo = _fit(others, "edge-loss"), _fit(others, "fraction")
        lam_fit = lp_lambda(t.arch, _contact(t.arch, d))
        lam_loo = lp_lambda(t.arch, _contact(t.arch, d_loo))
        rows.append({
            "id": t.id, "t_mm": t.arch.t * 1e3, "lambda_lab": t.lambda_mean, "lambda_lab_sd": t.lambda_sd,
            "observed_mode": t.mode, "lambda_ideal_lp": lp_lambda(t.arch, 1.0), "contact": _contact(t.arch, d),
            "lambda_fit": lam_fit, "residual_pct": 100 * (lam_fit / t.lambda_mean - 1),
            "edge_loss_loo_mm": d_loo * 1e3, "lambda_loo": lam_loo, "loo_error_pct": 100 * (lam_loo / t.lambda_mean - 1),
            "fraction_loo_error_pct": 100 * (lp_lambda(t.arch, f_loo) / t.lambda_mean - 1),
        })
    sd = 0.0
    if scatter:
        # the model's CoV is close to proportional to the scatter: one trial value, a least-squares
        # scale, then the CoV at the fitted scatter for the table
        trial = 0.25 * d if d > 0 else 1e-3
        cov_lab = np.array([t.lambda_sd / t.lambda_mean for t in tests])
        cov_trial = np.array([_cov(t.arch, d, trial, SCATTER_REALISATIONS, SCATTER_SEED) for t in tests])
        sd = float(max(trial * (cov_trial @ cov_lab) / (cov_trial @ cov_trial), 0.0))
        for r, t in zip(rows, tests):
            r["cov_lab"] = t.lambda_sd / t.lambda_mean
            r["cov_model"] = _cov(t.arch, d, sd, SCATTER_REALISATIONS, SCATTER_SEED) if sd > 0 else 0.0
    rms = float(np.sqrt(np.mean([r["loo_error_pct"] ** 2 for r in rows])))
    rms_f = float(np.sqrt(np.mean([r["fraction_loo_error_pct"] ** 2 for r in rows])))
    return Calibration(d, sd, rows, rms, f, rms_f, source)


def calibration_target(path: str | Path, replace: bool = False) -> Path:
    """``path`` checked before the fit: writable (nothing made, so a bad table leaves nothing behind) and,
    unless ``replace``, holding no calibration yet."""
    out = writable_file(path)
    if out.exists() and not replace:
        raise ArchdemInputError(f"{out} holds a calibration already; it is kept unless you give --replace")
    return out


def load_calibration(path: str | Path | None = None) -> Calibration:
    """The calibration at ``path``; by default the one ``archdem calibrate`` stored
    (``CALIBRATION_FILE``) or, if there is none, the one shipped with archdem
    (``SHIPPED_CALIBRATION``: the fit of ``LAB_TILT_TESTS``, which a test recomputes)."""
    p = Path(path) if path is not None else (CALIBRATION_FILE if CALIBRATION_FILE.is_file() else SHIPPED_CALIBRATION)
    if not p.is_file():
        raise ArchdemInputError(f"no calibration file {p} (write one with archdem calibrate)")
    try:
        return Calibration.from_json(json.loads(p.read_text()))
    except (OSError, json.JSONDecodeError) as exc:
        raise ArchdemInputError(f"cannot read the calibration file {p}: {exc}") from None


__all__ = ["TiltTest", "read_experiments", "calibrate", "Calibration", "calibration_target", "load_calibration", "lp_lambda",
           "LAB_TILT_TESTS", "CALIBRATION_FILE", "SHIPPED_CALIBRATION"]
