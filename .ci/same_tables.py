"""Whether two campaign folders hold the same tables, cell by cell.

    python .ci/same_tables.py RUN_A RUN_B [TABLE ...]
    (default: the catalogue, tilt, shake and map tables of the quick campaign)

Cells are compared as written: the campaign writes floats at full precision (shortest repr), so
equal text is equal numbers; the columns of IGNORED (wall times) are not compared. Prints one line
per differing cell (with the relative difference of numbers) and exits 1 if any differ, 2 if a
table is missing or unreadable, 0 if all are equal.
Standard library only: it runs on any of the supported Pythons without archdem installed.
"""
from __future__ import annotations

import csv
import math
import sys
from pathlib import Path

TABLES = ("catalogue/catalogue.csv", "tilt/tilt.csv", "shake/shake.csv", "map/map.csv",
          "map/map_points.csv")
# the machine's wall times, not results: of a run, of the threshold checks, of the solve without dilatancy
IGNORED = ("wall_s", "check_wall_s", "seconds_na")


def read_table(path: Path) -> tuple[list[str], list[list[str]]]:
    """Header and rows of a CSV file."""
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    if not rows:
        raise ValueError(f"{path}: empty table")
    return rows[0], rows[1:]


def _rel(a: str, b: str) -> str:
    try:
        x, y = float(a), float(b)
    except ValueError:
        return ""
    if math.isnan(x) and math.isnan(y):
        return ""
    scale = max(abs(x), abs(y))
    return f" (relative difference {abs(x - y) / scale:.3g})" if scale > 0 and math.isfinite(scale) else ""


def differences(a: Path, b: Path) -> list[str]:
    """One line per difference between tables ``a`` and ``b`` (header, row count, cells)."""
    ha, ra = read_table(a)
    hb, rb = read_table(b)
    if ha != hb:
        return [f"{b.name}: columns differ: {ha} vs {hb}"]
    out = []
    if len(ra) != len(rb):
        out.append(f"{b.name}: {len(ra)} rows vs {len(rb)}")
    for i, (x, y) in enumerate(zip(ra, rb), start=1):
        for col, u, v in zip(ha, x, y):
            if u != v and col not in IGNORED:
                out.append(f"{b.name} row {i} {col}: {u} vs {v}{_rel(u, v)}")
    return out


def main(argv: list[str]) -> int:
    if len(argv) < 2:
        print("usage: same_tables.py RUN_A RUN_B [TABLE ...]", file=sys.stderr)
        return 2
    a, b = Path(argv[0]), Path(argv[1])
    tables = argv[2:] or list(TABLES)
    diffs, cells = [], 0
    for t in tables:
        try:
            diffs += differences(a / t, b / t)
            cells += sum(len(r) for r in read_table(a / t)[1])
        except (OSError, ValueError, csv.Error) as e:
            print(f"same_tables: cannot read {t}: {e}", file=sys.stderr)
            return 2
    for d in diffs:
        print(d)
    print(f"same_tables: {len(tables)} tables, {cells} cells: "
          + ("identical" if not diffs else f"{len(diffs)} differences") + f" ({a} vs {b})")
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
