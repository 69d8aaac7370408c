"""Tables of a fragility study: its stripes and fits as CSV beside the study file, each with its schema
(:class:`~dem.experiments.fragility.run.FragilityResult`)."""
from __future__ import annotations

import os
from pathlib import Path

from dem.common.tables import Schema, schema_path, write_csv
from dem.experiments.fragility.run import FITS_SCHEMA, FragilityResult, stripes_csv
from foundation.io import atomic_path


def _write(path: Path, rows: list[dict], schema: Schema) -> None:
    """``rows`` as CSV at ``path`` and the schema beside it, each written whole or not at all."""
    with atomic_path(path, overwrite=True) as tmp:
        write_csv(tmp, rows, schema)
        side = schema_path(tmp)
    os.replace(side, schema_path(path))


def write_tables(res: FragilityResult, study_path: str | os.PathLike) -> Path:
    """``STEM-stripes.csv`` (one row per stripe) and ``STEM-fits.csv`` (one row per curve) beside the
    study; derived from the study, so a resumed study rewrites them. Returns the stripes' path."""
    stripes = stripes_csv(study_path)
    fits = stripes.with_name(Path(study_path).stem + "-fits.csv")
    for path, table, schema in ((stripes, res.rows(), res.SCHEMA), (fits, res.fit_rows(), FITS_SCHEMA)):
        if table:
            _write(path, table, schema)
    return stripes
