"""The catalogue's table as ``archdem specimens`` prints it."""
from specimens.catalogue import CATALOGUE, catalogue_rows, catalogue_table


def test_the_table_is_a_header_with_units_then_a_line_per_specimen_in_mm():
    rows = catalogue_rows()
    lines = catalogue_table(rows)
    assert len(lines) == 2 + len(CATALOGUE) and lines[0].split()[:3] == ["id", "Ri", "Re"] and "[kg]" in lines[1]
    first = lines[2].split()
    assert first[0] == rows[0]["id"] and float(first[1]) == round(rows[0]["Ri"] * 1e3)
    assert first[-1] == f"{rows[0]['n_bodies_free']}/{rows[0]['n_bodies_glued']}"
    assert len({len(line.rstrip()) for line in lines[2:]}) == 1  # the columns line up
