"""Engineering drawings (specimens/drawing.py): the box of the drawing's data covers no joint label."""
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

from specimens import Piers, discretise, get_specimen, read_assembly
from specimens.drawing import INFO_BOX_GID, JOINT_LABEL_GID, drawing_figure, drawing_title
from specimens.exchange import EXAMPLE_DRAWING


def _assembly(case: str):
    if case == "drawing":
        return read_assembly(EXAMPLE_DRAWING)
    if case == "piers":  # the tall case: the labels reach the axes' top corners
        return discretise(get_specimen("Sh06-Sd015").arch, piers=Piers(height=0.4, width=0.144, courses=4))
    return discretise(get_specimen(case).arch)


@pytest.mark.parametrize("case", ["Sh02-Sd025", "Sh1-Sd010", "Sh06-Sd015", "piers", "drawing"])
def test_info_box_covers_no_joint_label(case):
    fig = drawing_figure(_assembly(case), title=case)
    FigureCanvasAgg(fig)
    fig.canvas.draw()  # lays the texts out where the saved file has them
    renderer = fig.canvas.get_renderer()
    (ax,) = fig.axes
    (box,) = [t for t in ax.texts if t.get_gid() == INFO_BOX_GID]
    # the frame drawn around the text, which is larger than the text itself
    info = box.get_bbox_patch().get_window_extent(renderer)
    labels = [t for t in ax.texts if t.get_gid() == JOINT_LABEL_GID]
    assert len(labels) == len(_assembly(case).joints)
    covered = [t.get_text() for t in labels if info.overlaps(t.get_window_extent(renderer))]
    assert covered == []
    # and the box stays on the page
    page = fig.bbox
    assert page.x0 <= info.x0 and info.x1 <= page.x1 and page.y0 <= info.y0 and info.y1 <= page.y1


def test_the_title_names_an_arch_s_ratios_or_a_drawing_s_density_and_depth():
    asm = discretise(get_specimen("Sh06-Sd015").arch)
    assert drawing_title("Sh06-Sd015", asm) == "Sh06-Sd015   Sh = 0.60, Sd = 0.15"
    drawn = discretise(read_assembly(EXAMPLE_DRAWING, depth=1.0))
    assert drawing_title("d", drawn) == f"d\ndensity {drawn.density:g} kg/m^3"
    assert drawing_title("d", drawn, 1.0).endswith(", blocks without a depth 1 m deep (masses per metre)")
