"""The mode map's figure: a cell per specimen and frequency, its text the first collapse and first slip."""
from dem.common.figures import save_figure
from dem.experiments.mode_map.figure import catalogue_order, cell_label, mode_map_figure
from dem.experiments.mode_map.run import ModeMapResult


def test_cells_say_the_collapse_the_reach_and_the_first_slip(synthetic, tmp_path):
    spec, study = synthetic
    rows = ModeMapResult.from_study(study, spec.cases()).rows()
    assert cell_label(rows[0]) == "3.13 g *, 1st\nslip R7 1st"
    assert [cell_label(r) for r in rows[1:]] == ["none", "not run", "failed"]
    fig = mode_map_figure(rows, spec.title())
    (ax,) = fig.axes
    assert [t.get_text() for t in ax.get_yticklabels()] == ["Sh02-Sd015", "Sh1-Sd015"]  # thin shape first
    assert [t.get_text() for t in ax.get_xticklabels()] == ["8 Hz", "10 Hz"]
    assert {t.get_text() for t in ax.texts} == {"3.13 g *, 1st\nslip R7 1st", "none", "not run", "failed"}
    assert ax.get_title().startswith("First collapse of a one-cycle sine")
    path = save_figure(fig, tmp_path / "map.png")
    assert path.read_bytes()[:4] == b"\x89PNG"


def test_the_catalogue_order_is_thickness_then_shape():
    ids = ["Sh1-Sd015", "Sh02-Sd020", "Sh06-Sd015", "Sh02-Sd015"]
    assert sorted(ids, key=catalogue_order) == ["Sh02-Sd015", "Sh06-Sd015", "Sh1-Sd015", "Sh02-Sd020"]
