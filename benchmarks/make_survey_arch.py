"""Draw the example survey-like structure shipped with archdem: a pointed arch on piers as built.

Writes ``specimens/data/survey-arch-on-piers.dxf`` (millimetres, ``$INSUNITS`` = 4): a two-centred
ring 300 mm thick on two piers 700 mm wide, with voussoirs of unequal sizes, joints turned a few
degrees off the radial, a keystone off the axis and piers in courses of their own heights. Every
number below is the drawing's (invented, survey-like); nothing is measured.

    python benchmarks/make_survey_arch.py [--out FILE]
"""
from __future__ import annotations

import argparse
import math
from pathlib import Path

import ezdxf
import numpy as np

from specimens.arch_set import off_radial_joint

RI, RE, E = 1400.0, 1700.0, 350.0  # intrados and extrados radii, centres' offset [mm]
# joints of each half: polar angle about its centre [deg], turn off the radial [deg]
LEFT = [(0.0, 0.0), (9.0, 3.0), (20.0, -4.0), (29.0, 2.0), (41.0, -3.0), (50.0, 4.0), (61.0, -2.0), (68.0, 3.0)]
RIGHT = [(0.0, 0.0), (11.0, -2.0), (19.0, 4.0), (31.0, -3.0), (40.0, 2.0), (52.0, -4.0), (60.0, 3.0), (71.0, -2.0)]
PIER_WIDTH = 700.0
LEFT_COURSES = [380.0, 300.0, 420.0, 400.0]  # bottom to top [mm]
RIGHT_COURSES = [350.0, 450.0, 300.0, 400.0]
RING_DEPTH, PIER_DEPTH = 450.0, 600.0


def _joint(side: int, psi_deg: float, turn_deg: float) -> tuple[np.ndarray, np.ndarray]:
    """Intrados and extrados ends of a joint of half ``side`` (-1 left, +1 right) of this ring."""
    return off_radial_joint(side, psi_deg, turn_deg, RI, RE, E)


def blocks() -> list[tuple[str, str, np.ndarray]]:
    """(name, layer, outline) of every block, left pier to right pier."""
    out = []
    xi = RI - E
    for side, courses, tag in ((-1, LEFT_COURSES, "LP"), (1, RIGHT_COURSES, "RP")):
        y = -sum(courses)
        for k, h in enumerate(courses, start=1):
            x0, x1 = sorted((side * xi, side * (xi + PIER_WIDTH)))
            out.append((f"{tag}{k}", f"piers depth {PIER_DEPTH:g}",
                        np.array([[x0, y], [x1, y], [x1, y + h], [x0, y + h]])))
            y += h
    ring = f"ring depth {RING_DEPTH:g}"
    left = [_joint(-1, *j) for j in LEFT]
    right = [_joint(1, *j) for j in RIGHT]
    for k in range(1, len(left)):
        (a_i, a_e), (b_i, b_e) = left[k - 1], left[k]
        out.append((f"V{k}", ring, np.array([a_i, b_i, b_e, a_e])))
    apex_i = np.array([0.0, math.sqrt(RI**2 - E**2)])
    apex_e = np.array([0.0, math.sqrt(RE**2 - E**2)])
    (l_i, l_e), (r_i, r_e) = left[-1], right[-1]
    out.append(("K", ring, np.array([l_i, apex_i, r_i, r_e, apex_e, l_e])))
    n = len(left) - 1
    for k in range(len(right) - 1, 0, -1):
        (a_i, a_e), (b_i, b_e) = right[k], right[k - 1]
        out.append((f"V{n + len(right) - k}", ring, np.array([a_i, b_i, b_e, a_e])))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "specimens" / "data"
                                         / "survey-arch-on-piers.dxf"))
    args = ap.parse_args()
    doc = ezdxf.new(units=4)  # millimetres
    msp = doc.modelspace()
    for name, layer, outline in blocks():
        msp.add_lwpolyline([tuple(map(float, p)) for p in outline], format="xy", close=True, dxfattribs={"layer": layer})
        at = outline.mean(axis=0)
        msp.add_text(name, dxfattribs={"layer": "labels", "insert": (float(at[0]), float(at[1])), "height": 60})
    total = max(sum(LEFT_COURSES), sum(RIGHT_COURSES))
    g = [(-2400.0, -total - 200.0), (2400.0, -total - 200.0), (2400.0, -total), (-2400.0, -total)]
    msp.add_lwpolyline(g, format="xy", close=True, dxfattribs={"layer": "ground"})
    doc.saveas(args.out)
    print(args.out)


if __name__ == "__main__":
    main()
