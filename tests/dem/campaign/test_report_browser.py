"""The campaign report rendered in a real browser (headless Chromium).

Chromium comes from Debian's packages (the Makefile's test target installs it when it can);
without it the test is skipped with the reason.
"""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from dem.campaign.report import _summary_html
from dem.campaign.runner import run_campaign
from dem.common.campaign import CampaignContext
from specimens.catalogue import select_specimens

pytestmark = pytest.mark.slow  # every test here simulates, spawns processes or runs a campaign

BROWSER = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")

_PROBE = """<script>
window.addEventListener('load', function () {
  var imgs = Array.from(document.images);
  var ok = imgs.filter(function (i) { return i.complete && i.naturalWidth > 0; }).length;
  var out = document.createElement('pre');
  out.id = 'archdem-probe';
  out.textContent = 'images=' + imgs.length + ' loaded=' + ok + ' tables=' + document.querySelectorAll('table.data').length;
  document.body.appendChild(out);
});
</script></body>"""


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("campaign")
    ctx = CampaignContext(out=out, specimens=select_specimens("Sh02-Sd015,Sh1-Sd025"), quick=True, log=lambda s: None)
    manifest = run_campaign(ctx, steps=["catalogue"])
    return Path(manifest["report"])


def test_report_is_self_contained(report):
    text = report.read_text()
    # every image is embedded: no reference to a file beside the report
    srcs = re.findall(r'<img[^>]*src="([^"]+)"', text)
    assert srcs and all(s.startswith("data:image/png;base64,") for s in srcs)
    assert (report.parent / "campaign.h5").exists()


@pytest.mark.skipif(BROWSER is None, reason="no Chromium on this machine (install Debian's 'chromium' to run it)")
def test_report_renders_in_headless_chromium(report, tmp_path):
    page = tmp_path / "probe.html"
    page.write_text(report.read_text().replace("</body>", _PROBE))
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=10000"]
    dom = subprocess.run([BROWSER, *flags, "--dump-dom", page.as_uri()], capture_output=True, text=True, timeout=120)
    m = re.search(r"images=(\d+) loaded=(\d+) tables=(\d+)", dom.stdout)
    assert m, f"the page did not run its load probe: {dom.stderr[-500:]}"
    n_img, n_ok, n_tab = map(int, m.groups())
    expected_imgs = report.read_text().count("<img ")
    assert n_img == expected_imgs > 0 and n_ok == n_img  # every figure decoded by the browser
    assert n_tab >= 1
    shot = tmp_path / "shot.png"
    subprocess.run([BROWSER, *flags, f"--screenshot={shot}", "--window-size=1200,900", page.as_uri()],
                   capture_output=True, timeout=120)
    assert shot.exists() and shot.stat().st_size > 5000


_WIDTH_PROBE = """<script>
window.addEventListener('load', function () {
  var w = document.documentElement.clientWidth, wide = [];
  document.querySelectorAll('body *').forEach(function (e) {
    var r = e.getBoundingClientRect();
    if (r.right > w + 1) { wide.push(e.tagName + (e.className ? '.' + e.className : '')); }
  });
  var out = document.createElement('pre');
  out.id = 'archdem-width';
  out.textContent = 'page=' + w + ' scroll=' + document.documentElement.scrollWidth + ' wide=' + wide.length
    + ' first=' + (wide[0] || '-') + ' summary=' + (document.body.innerHTML.indexOf('<h2>Summary</h2>') >= 0);
  document.body.appendChild(out);
});
</script></body>"""


@pytest.mark.skipif(BROWSER is None, reason="no Chromium on this machine (install Debian's 'chromium' to run it)")
def test_the_report_fits_the_page(tmp_path):
    """The summary up front, the parameters as a table, the monument's checks and calculation: in a
    1000-pixel-wide window no element reaches beyond the page."""
    out = tmp_path / "campaign"
    ctx = CampaignContext(out=out, specimens=select_specimens("Sh06-Sd015"), quick=True, workers=1, log=lambda s: None)
    report = Path(run_campaign(ctx, steps=["catalogue", "assess"])["report"])
    page = tmp_path / "width.html"
    page.write_text(report.read_text().replace("</body>", _WIDTH_PROBE))
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=10000", "--window-size=1000,900"]
    dom = subprocess.run([BROWSER, *flags, "--dump-dom", page.as_uri()], capture_output=True, text=True, timeout=120)
    m = re.search(r"page=(\d+) scroll=(\d+) wide=(\d+) first=(\S+) summary=(\w+)", dom.stdout)
    assert m, f"the page did not run its width probe: {dom.stderr[-500:]}"
    width, scroll, n_wide, first, summary = m.groups()
    assert int(n_wide) == 0, f"{n_wide} elements wider than the page ({width} px), the first a {first}"
    assert int(scroll) <= int(width) and summary == "true"
    shot = tmp_path / "shot.png"
    subprocess.run([BROWSER, *flags, f"--screenshot={shot}", page.as_uri()], capture_output=True, timeout=120)
    assert shot.exists() and shot.stat().st_size > 5000


def test_the_summary_reads_the_steps_tables():
    """Per specimen the laboratory's, the limit analysis's and the DEM's lambda and the least shake threshold,
    read from the steps' typed tables; a step not run leaves its column blank."""
    tables = {"lab": [{"id": "A", "lambda_lab_mean": 0.41, "lambda_dem_effective_mean": 0.39,
                       "lambda_lp_effective": 0.40}],
              "analytic": [{"id": "A", "lambda_discrete_glued": 0.42}, {"id": "B", "lambda_discrete_glued": 0.3}],
              "shake": [{"id": "A", "freq_Hz": 2.0, "a_dem_g": 0.5}, {"id": "A", "freq_Hz": 4.0, "a_dem_g": 0.35},
                        {"id": "A", "freq_Hz": 8.0, "a_dem_g": float("nan")}]}
    page = _summary_html(tables)
    rows = re.findall(r"<tr><td>(\w)</td>(.*?)</tr>", page)
    assert [r[0] for r in rows] == ["A", "B"]
    assert rows[0][1] == "<td>0.41</td><td>0.42</td><td>0.39</td><td>0.35 g at 4 Hz</td>"
    assert rows[1][1] == "<td></td><td>0.3</td><td></td><td></td>"
