"""The tilt figure reads alone: the bracket panel's markers have a legend, the load's direction is
drawn, the joints that moved are named on the arch, every axis has its unit."""
from types import SimpleNamespace

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.text import Annotation

from dem.experiments.tilt.figure import BRACKET_LABELS, plot_bracket, plot_collapse, save_tilt_figure


def _legend_texts(ax) -> list[str]:
    leg = ax.get_legend()
    assert leg is not None, "no legend"
    return [t.get_text() for t in leg.get_texts()]


def test_bracket_panel_has_a_legend_for_its_markers_and_units_on_both_axes():
    # a stood level, a collapsed one, the bracket between them
    result = SimpleNamespace(levels=[(0.30, False), (0.32, True)], bracket=(0.30, 0.32))
    ax = plot_bracket(result)
    assert _legend_texts(ax) == list(BRACKET_LABELS) == ["collapsed", "stood", "final bracket"]
    assert "[-]" in ax.get_ylabel() and "[-]" in ax.get_xlabel()
    (right,) = [c for c in ax.child_axes]  # the tilt angle beside lambda
    assert "[deg]" in right.get_ylabel()
    assert "deg" in ax.get_title()


@pytest.fixture(scope="module")
def arch_result():
    # a small free arch under a short hold protocol (as tests/dem/experiments/tilt/test_file.py): hinges
    from dem.core.model import from_assembly
    from dem.core.settings import Settings
    from dem.experiments.tilt.run import TiltProtocol, tilt
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    m = from_assembly(discretise(get_specimen("Sh06-Sd015").arch, n_voussoirs=3, config="free"), name="small")
    return tilt(m, Settings(), TiltProtocol(tol=0.05, ramp_time=0.2, hold_time=0.4, rest_after=0.2))


@pytest.mark.slow
def test_collapse_panel_names_the_moving_joints_and_shows_the_load_direction(arch_result):
    ax = plot_collapse(arch_result)
    moved = {j.joint for j in arch_result.joints if j.state != "closed"}
    assert moved  # the test means something only if some joint hinged or slid
    labels = {t.get_text() for t in ax.texts if (t.get_gid() or "").startswith("joint-label-")}
    assert labels == moved
    arrows = [t for t in ax.texts if isinstance(t, Annotation) and t.get_gid() == "load-direction"]
    assert len(arrows) == 1 and arrows[0].arrow_patch is not None
    x0, x1 = arrows[0].xyann[0], arrows[0].xy[0]
    assert x1 > x0  # gravity's horizontal part points to +x in the tilt (dem.experiments.tilt.run)
    assert any("horizontal load" in t.get_text() for t in ax.texts)
    assert "[m]" in ax.get_xlabel() and "[m]" in ax.get_ylabel() and "deg" in ax.get_title()
    assert {"hinge", "slide", "closed"} <= set(_legend_texts(ax))
    # the labels and the arrow lie inside the axes, where the reader sees them
    fig = ax.figure
    FigureCanvasAgg(fig)
    fig.canvas.draw()
    box = ax.get_window_extent()
    legend = ax.get_legend().get_window_extent()
    for t in [*(t for t in ax.texts if (t.get_gid() or "").startswith("joint-label-")), arrows[0]]:
        e = t.get_window_extent()
        assert box.x0 <= e.x0 and e.x1 <= box.x1 and box.y0 <= e.y0 and e.y1 <= box.y1, t.get_text()
        assert not legend.overlaps(e), t.get_text()  # the states' key hides no name


@pytest.mark.slow
def test_saved_figure_has_both_panels(arch_result, tmp_path):
    out = save_tilt_figure(arch_result, tmp_path / "f.png")
    assert out.stat().st_size > 10_000
