"""A study's file (dem/studies/files.py): a new one never overwritten, a resumed one that exists."""
from __future__ import annotations

import pytest

from dem.studies.files import resumed_study, study_file
from foundation.errors import ArchdemInputError


@pytest.fixture
def here(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "old.h5").write_bytes(b"old")
    (tmp_path / "dir").mkdir()
    return tmp_path


def test_a_new_a_default_and_a_resumed_study(here):
    assert study_file("new.h5", None, "runs", "s") == ("new.h5", False)
    assert study_file(None, "old.h5", "runs", "s") == ("old.h5", True)
    assert study_file(None, None, "runs", "s") == ("runs/s.h5", False)
    assert not (here / "runs").exists()  # checked, not made
    (here / "runs").mkdir()
    (here / "runs" / "s.h5").write_bytes(b"")
    assert study_file(None, None, "runs", "s") == ("runs/s-2.h5", False)


@pytest.mark.parametrize("out, resume, msg", [
    ("new.h5", "old.h5", "give --out (new study) or --resume STUDY.h5, not both"),
    ("", "typo.h5", "not both"),
    (None, "typo.h5", "--resume 'typo.h5': no such study file; start a new study with --out"),
    (None, "", "no such study file"),
    (None, "dir", "--resume dir is a folder; a study is one .h5 file"),
    ("old.h5", None, "--out old.h5 exists; a study is never overwritten"),
    ("dir", None, "--out 'dir': give a study file name (STUDY.h5), not a folder"),
    ("", None, "not a folder"),
    ("x/", None, "--out 'x/': give a study file name (STUDY.h5), not a folder"),
    ("old.h5/s.h5", None, "cannot create directory old.h5: old.h5 is not a folder"),
    ("a" * 250 + ".h5", None, "is too long"),
])
def test_refused_before_any_case(here, out, resume, msg):
    with pytest.raises(ArchdemInputError, match=msg.replace("(", r"\(").replace(")", r"\)")):
        study_file(out, resume, "runs", "s")
    assert not (here / "x").exists() and not (here / "runs").exists()


def test_a_resumed_study_is_an_existing_file(here):
    assert resumed_study("old.h5") == "old.h5"
    with pytest.raises(ArchdemInputError, match="is a folder"):
        resumed_study("dir")
