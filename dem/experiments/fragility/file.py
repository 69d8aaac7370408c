"""Tables of a fragility study: its stripes and fits as CSV beside the study file."""
from __future__ import annotations

import csv
from pathlib import Path

from foundation.io import atomic_path


def write_tables(res, study_path) -> Path:
    """``STEM-stripes.csv`` (one row per stripe) and ``STEM-fits.csv`` (one row per curve) beside the
    study; derived from the study, so a resumed study rewrites them. Returns the stripes' path."""
    study = Path(study_path)
    stripes = study.with_name(study.stem + "-stripes.csv")
    fits = study.with_name(study.stem + "-fits.csv")
    rows = [{"group": c.group, "unit": c.unit, **{k: v for k, v in s.describe().items() if k != "modes"},
             "modes": " ".join(f"{m}:{n}" for m, n in sorted(s.modes.items()))} for c in res.curves for s in c.stripes]
    frows = [{"group": c.group, "unit": c.unit,
              **({"median": c.fit.median, "median_ci_low": c.fit.median_ci[0], "median_ci_high": c.fit.median_ci[1],
                  "beta": c.fit.beta, "beta_ci_low": c.fit.beta_ci[0], "beta_ci_high": c.fit.beta_ci[1]}
                 if c.fit else dict.fromkeys(("median", "median_ci_low", "median_ci_high", "beta", "beta_ci_low",
                                              "beta_ci_high"), "")),
              "n_runs": sum(s.n for s in c.stripes), "deterministic_threshold": "" if c.deterministic is None
              else c.deterministic, "note": c.fit_note} for c in res.curves]
    for path, table in ((stripes, rows), (fits, frows)):
        if not table:
            continue
        with atomic_path(path, overwrite=True) as tmp, open(tmp, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(table[0]))
            w.writeheader()
            w.writerows(table)
    return stripes
