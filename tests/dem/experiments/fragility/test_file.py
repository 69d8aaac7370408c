"""The fragility study's tables (dem/experiments/fragility/file.py): the stripes and fits written through
the result's schema, read back typed, and the printed summary from the same result."""
from analytic.codes.fragility import fit_lognormal, stripes
from dem.common.tables import read_csv
from dem.experiments.fragility.file import write_tables
from dem.experiments.fragility.run import FITS_SCHEMA, Curve, FragilityResult


def _result(tmp_path) -> FragilityResult:
    xs = [0.2, 0.2, 0.3, 0.3, 0.4, 0.4]
    fitted = stripes(xs, [False, False, True, False, True, True], ["none", "none", "rocking", "none", "rocking",
                                                                   "rocking"])
    bare = stripes([0.2, 0.3], [False, False], ["none", "sliding"])
    curves = [Curve("2 Hz", "g", fitted, fit_lognormal(fitted, n_boot=50, seed=1), "", 0.31),
              Curve("4 Hz", "g", bare, None, "every run survived")]
    return FragilityResult("b", curves, 8, ("4 Hz 0.5 #0: boom",), str(tmp_path / "s.h5"), 2.4)


def test_the_tables_are_written_through_their_schemas(tmp_path):
    res = _result(tmp_path)
    path = write_tables(res, tmp_path / "s.h5")
    assert path == tmp_path / "s-stripes.csv" and (tmp_path / "s-stripes.schema.json").is_file()
    schema, rows = read_csv(path)
    assert schema == FragilityResult.SCHEMA and len(rows) == 5
    assert rows[2] == {"group": "2 Hz", "unit": "g", "intensity": 0.4, "n_runs": 2, "n_collapsed": 2, "p": 1.0,
                       "ci_low": rows[2]["ci_low"], "ci_high": 1.0, "modes": "rocking:2"}
    assert rows[1]["modes"] == "none:1 rocking:1" and rows[4]["modes"] == "sliding:1"
    schema, fits = read_csv(tmp_path / "s-fits.csv")
    assert schema == FITS_SCHEMA and [f["n_runs"] for f in fits] == [6, 2]
    assert 0.2 < fits[0]["median"] < 0.4 and fits[0]["deterministic_threshold"] == 0.31
    # no fit: empty cells, read back as missing values; the note kept
    assert fits[1]["median"] is None and fits[1]["deterministic_threshold"] is None
    assert fits[1]["note"] == "every run survived"
    assert (tmp_path / "s-fits.csv").read_text().splitlines()[2].startswith("4 Hz,g,,,,,,,2,,every")


def test_the_printed_summary(tmp_path):
    lines = _result(tmp_path).lines(2)
    assert lines[0] == f"b: 8 runs (2 realisations per stripe), 2 s -> {tmp_path / 's.h5'}"
    assert "deterministic threshold 0.31 g" in lines[1] and lines[1].endswith("0.2:0/2  0.3:1/2  0.4:2/2")
    assert lines[2].startswith("  4 Hz: no fit (every run survived)") and "0.3:0/1" in lines[2]
    assert lines[3] == "  1 runs failed; first: 4 Hz 0.5 #0: boom"
