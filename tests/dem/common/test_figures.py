"""Writing a figure and checking its file (dem/common/figures.py)."""
from __future__ import annotations

from pathlib import Path

import pytest
from matplotlib.figure import Figure

from dem.common.figures import figure_file, save_figure
from foundation.errors import ArchdemInputError


def _figure() -> Figure:
    fig = Figure(figsize=(2, 1.5))
    fig.subplots().plot([0, 1], [0, 1])
    return fig


def test_the_suffix_chooses_the_format_and_png_is_the_default(tmp_path):
    assert save_figure(_figure(), tmp_path / "a.svg").read_text().lstrip().startswith("<?xml")
    assert (save_figure(_figure(), tmp_path / "b")).read_bytes()[:4] == b"\x89PNG"


def test_an_existing_file_is_kept_unless_overwrite(tmp_path):
    path = save_figure(_figure(), tmp_path / "a.png")
    with pytest.raises(ArchdemInputError, match="exists"):
        save_figure(_figure(), path)
    before = path.stat().st_size
    save_figure(_figure(), path, overwrite=True, dpi=60)
    assert path.stat().st_size < before


def test_tight_crops_to_the_drawn_area(tmp_path):
    from matplotlib.image import imread

    tight = imread(save_figure(_figure(), tmp_path / "t.png")).shape
    whole = imread(save_figure(_figure(), tmp_path / "w.png", tight=False)).shape
    assert whole[:2] == (180, 240)  # 2 x 1.5 in at 120 dpi
    assert tight[:2] != whole[:2]


@pytest.mark.parametrize("name, msg", [("p.xyz", "--plot must end in .png, .pdf, .svg, got 'p.xyz'"),
                                       ("noext", "--plot must end in"), ("old.png", "old.png exists"),
                                       ("folder.png", "--plot folder.png is a folder; give a file name"),
                                       ("a" * 300 + ".png", "is too long")])
def test_a_figure_file_is_new_with_a_known_suffix(tmp_path, monkeypatch, name, msg):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "old.png").write_bytes(b"old")
    (tmp_path / "folder.png").mkdir()
    assert figure_file("new.PDF") == Path("new.PDF")  # the suffix in any case
    with pytest.raises(ArchdemInputError, match=msg):
        figure_file(name)
    with pytest.raises(ArchdemInputError, match="--out must end in"):
        figure_file("o.txt", "--out")
