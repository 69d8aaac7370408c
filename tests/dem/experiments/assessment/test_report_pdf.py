"""The printable (PDF) assessment report: its pages are rendered to images and read back as text."""
import numpy as np
import pytest

from dem.cli import main

pdfium = pytest.importorskip("pypdfium2")

NTC = ["--spectrum", "ntc2018", "--ag", "0.25", "--F0", "2.4", "--Tc-star", "0.3", "--soil", "C"]


def _pages(path):
    """Each page's fraction of non-white pixels (rendered at 50 dpi) and its text."""
    pdf = pdfium.PdfDocument(str(path))
    ink, text = [], []
    for page in pdf:
        img = np.asarray(page.render(scale=50 / 72).to_pil().convert("L"))
        ink.append(float((img < 245).mean()))
        text.append(page.get_textpage().get_text_range())
    pdf.close()
    return ink, text


@pytest.mark.slow
def test_the_pdf_report_of_an_arch_with_strips(tmp_path, capsys):
    rep = tmp_path / "a.pdf"
    argv = ["assess", "Sh06-Sd015", *NTC, "--frp", "100,0.01,20,10", "--report", str(rep), "--project", "Test vault",
            "--engineer", "A. Engineer", "--json"]
    assert main(argv) == 0
    import json

    d = json.loads(capsys.readouterr().out)
    assert d["report"] == str(rep)
    ink, text = _pages(rep)
    assert 4 <= len(ink) <= 12 and min(ink) > 0.005  # no blank page
    assert max(ink) > 0.05  # the figures' pages
    first, everything = text[0], "\n".join(text)
    for field in ("Seismic assessment — Sh06-Sd015", "Test vault", "A. Engineer", "archdem version", "inputs hash",
                  "1. Inputs", "2. Site", "NTC 2018", "m/s^2"):
        assert field in first, field
    # every step with its formula, the strips' design, the verdicts with each safety index, the figures
    for s in ("(sum m dx)^2 / sum m dx^2", "alpha0 g / (e* FC)", "The strips' design", "Verdicts", "Figures"):
        assert s in everything, s
    from analytic.codes.assessment import CLAUSES, index_text

    for res in (d, d["frp"]):
        for c in res["checks"]:
            assert index_text(c["safety_index"]) in everything
        assert f"governing safety index {index_text(res['safety_index'])}" in first
    assert ("NOT verified" in everything) == (not all(c["verified"] for c in d["checks"] + d["frp"]["checks"]))
    assert "verified" in everything and CLAUSES[("linear", "ground")].split(":")[0] in everything
    # never overwritten
    assert main(["assess", "Sh06-Sd015", *NTC, "--report", str(rep)]) == 2
    assert "exists" in capsys.readouterr().err


def test_a_report_of_another_kind_and_a_title_without_a_pdf_are_refused(tmp_path, capsys):
    assert main(["assess", "Sh06-Sd015", *NTC, "--report", str(tmp_path / "a.docx")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and ".html or .pdf" in err[0]
    assert main(["assess", "Sh06-Sd015", *NTC, "--engineer", "X"]) == 2
    assert "--report FILE.pdf" in capsys.readouterr().err
    assert not list(tmp_path.iterdir())


def test_the_inputs_hash_follows_the_inputs():
    from dem.experiments.assessment.report_pdf import inputs_hash

    a = inputs_hash("x", [("t", 0.1, "m")], {"ag": 1.0})
    assert a == inputs_hash("x", [("t", 0.1, "m")], {"ag": 1.0}) and len(a) == 16
    assert a != inputs_hash("x", [("t", 0.11, "m")], {"ag": 1.0}) != inputs_hash("x", [("t", 0.1, "m")], {"ag": 2.0})


@pytest.mark.slow
def test_the_monument_report(tmp_path):
    from analytic.codes.assessment import monument_site, monument_strips
    from dem.experiments.assessment.report_pdf import write_monument_pdf_report
    from specimens.monuments import NOH_GUMBAD

    rep = tmp_path / "m.pdf"
    n = write_monument_pdf_report(rep, NOH_GUMBAD, monument_site(), monument_strips(), project="Noh Gumbad",
                                  engineer="A. Engineer", date="2026-01-02")
    ink, text = _pages(rep)
    assert len(ink) == n and min(ink) > 0.005
    assert all(s in text[0] for s in ("Noh Gumbad", "A. Engineer", "2026-01-02", "EN 1998-1", "full-height piers"))
    everything = "\n".join(text)
    assert "Configurations" in everything and "NOT verified" in everything and "CNR-DT 200" in everything
    with pytest.raises(Exception, match="exists"):
        write_monument_pdf_report(rep, NOH_GUMBAD, monument_site(), monument_strips())
