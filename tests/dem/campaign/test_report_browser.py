"""The campaign report rendered in a real browser (headless Chromium).

Chromium comes from Debian's packages (the Makefile's test target installs it when it can);
without it the test is skipped with the reason.
"""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from dem.campaign.context import CampaignContext
from dem.campaign.runner import run_campaign
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
