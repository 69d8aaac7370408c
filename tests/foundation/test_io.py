"""The one grid parser of every command: ranges and lists, refused in one line when wrong."""
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from foundation.errors import ArchdemInputError
from foundation.io import MAX_GRID_POINTS, parse_grid


def test_ranges_include_their_end_and_lists_keep_their_order():
    assert parse_grid("1:2:0.5") == [1.0, 1.5, 2.0]
    assert parse_grid("6, 2,4") == [6.0, 2.0, 4.0]
    assert len(parse_grid(f"1:{MAX_GRID_POINTS}:1")) == MAX_GRID_POINTS


@pytest.mark.parametrize("text", ["", " ", "4,,6", "4,", ",4", "abc", "1:2", "2:1:0.5", "1:2:0", "1:2:-1",
                                  "1:inf:1", "nan", "-1,2", "0", f"1:{MAX_GRID_POINTS + 1}:1", "1:1e9:1e-9"])
def test_bad_grids_are_refused_in_one_line(text):
    with pytest.raises(ArchdemInputError, match="^--freq: ") as exc:
        parse_grid(text, "--freq")
    assert "\n" not in str(exc.value)


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="0123456789.,:-e +naif", max_size=24))
def test_any_text_gives_a_valid_grid_or_an_input_error(text):
    try:
        vals = parse_grid(text)
    except ArchdemInputError:
        return
    assert 0 < len(vals) <= MAX_GRID_POINTS and all(v > 0 and v == v and v != float("inf") for v in vals)


def test_outputs_are_checked_without_making_anything(tmp_path, monkeypatch):
    """Empty names, folders, names too long for their temporary files, paths under a file or on a
    mount that refuses writes: each one input error, and nothing made."""
    from foundation.io import can_make_dir, exclusive, writable_dir, writable_file

    monkeypatch.chdir(tmp_path)
    (tmp_path / "f").write_text("x")
    (tmp_path / "d").mkdir()
    for bad, match in (("", "empty"), ("d", "is a folder"), ("a" * 250 + ".png", "too long"),
                       ("f/x.png", "not a folder"), ("/proc/nowhere/x.png", "not writable")):
        with pytest.raises(ArchdemInputError, match=match):
            writable_file(bad)
    for check in (can_make_dir, writable_dir):
        with pytest.raises(ArchdemInputError, match="empty"):
            check(" ")
    assert writable_file("new/x.png") and not (tmp_path / "new").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["d", "f"]
    with pytest.raises(ArchdemInputError, match="cannot make the lock file"):
        with exclusive(tmp_path / ("." + "a" * 260 + ".lock"), "x"):
            pass
