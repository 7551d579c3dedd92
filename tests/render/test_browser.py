"""report.html in a real browser: headless Chromium (Debian's `chromium` package) opens the
записка of cases/compressor.toml written with --lang ru, every <img> has loaded (naturalWidth >
0), the page logs nothing to the console and raises no error, nothing is fetched from the
network; a screenshot is saved in the test's tmp folder. Without a browser the test skips and
says so (.ci/run installs chromium when it can; an install that fails does not fail CI)."""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app

CASES = Path(__file__).resolve().parents[2] / "cases"
BROWSERS = ("chromium", "chromium-browser")

# run in the page before anything else: collects console.error calls, uncaught errors and
# resources that failed to load; after load, a <pre id="probe"> says what it found
PROBE = """<script>
window.__errors = [];
window.addEventListener('error', function (e) {
  window.__errors.push(String(e.message || (e.target && (e.target.src || e.target.href)) || 'error'));
}, true);
var __ce = console.error;
console.error = function () { window.__errors.push([].slice.call(arguments).join(' ')); __ce.apply(console, arguments); };
window.addEventListener('load', function () {
  var imgs = [].slice.call(document.images);
  var pre = document.createElement('pre');
  pre.id = 'probe';
  pre.textContent = JSON.stringify({
    images: imgs.length,
    widths: imgs.map(function (i) { return i.naturalWidth; }),
    errors: window.__errors, title: document.title,
    h2: [].slice.call(document.querySelectorAll('h2')).map(function (h) { return h.textContent; })});
  document.body.appendChild(pre);
});
</script>"""


def _browser() -> str:
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    pytest.skip("no headless browser: neither chromium nor chromium-browser is on PATH "
                "(apt-get install chromium); the HTML report was not checked in a browser")


def _chromium(browser: str, tmp: Path, *args: str) -> subprocess.CompletedProcess:
    """Headless Chromium with its own profile, no network (every host resolves to nothing)."""
    env = dict(os.environ, HOME=str(tmp))
    cmd = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
           f"--user-data-dir={tmp / 'profile'}", "--host-resolver-rules=MAP * ~NOTFOUND",
           "--enable-logging=stderr", "--v=0", "--virtual-time-budget=10000", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120, env=env)


def _console(stderr: str) -> list[str]:
    """What the page wrote to the console (Chromium logs it as ``CONSOLE…] "message"``)."""
    return [ln for ln in stderr.splitlines() if re.search(r":CONSOLE[(:]", ln)]


def test_report_html_in_headless_chromium(tmp_path):
    browser = _browser()
    out = tmp_path / "out"
    res = CliRunner().invoke(app, ["run", str(CASES / "compressor.toml"), "--lang", "ru",
                                   "--points", "720", "--out", str(out)])
    assert res.exit_code == 0, res.output
    page = out / "report.html"
    html = page.read_text(encoding="utf-8")
    n_img = html.count("<img ")
    assert n_img >= 10

    probed = tmp_path / "probed.html"
    probed.write_text(html.replace("<head>", "<head>" + PROBE, 1), encoding="utf-8")
    run = _chromium(browser, tmp_path, "--dump-dom", probed.as_uri())
    assert run.returncode == 0, run.stderr[-2000:]
    m = re.search(r'<pre id="probe">(.*?)</pre>', run.stdout, re.S)
    assert m, "the page did not finish loading: " + run.stderr[-2000:]
    found = json.loads(m.group(1).replace("&quot;", '"').replace("&amp;", "&")
                       .replace("&lt;", "<").replace("&gt;", ">"))
    assert found["images"] == n_img
    assert all(w > 0 for w in found["widths"]), found["widths"]       # every image loaded
    assert found["errors"] == [], found["errors"]
    assert found["title"].startswith("Компрессор") or found["title"]
    assert "1. Исходные данные" in found["h2"] and "5. Маховик" in found["h2"]
    assert _console(run.stderr) == []

    shot = tmp_path / "report.png"     # the page as it is, untouched
    run = _chromium(browser, tmp_path, "--hide-scrollbars", "--window-size=1240,1754",
                    f"--screenshot={shot}", page.as_uri())
    assert run.returncode == 0, run.stderr[-2000:]
    assert _console(run.stderr) == []
    data = shot.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 20_000
    print(f"screenshot: {shot}")

    printed = tmp_path / "printed.pdf"   # the browser's "Print to PDF": A4, nothing past the edge
    run = _chromium(browser, tmp_path, "--no-pdf-header-footer", f"--print-to-pdf={printed}",
                    page.as_uri())
    assert run.returncode == 0 and printed.read_bytes()[:4] == b"%PDF", run.stderr[-2000:]
    if shutil.which("pdftotext") is not None:
        from test_report_formats import _pages

        pages = _pages(printed)
        assert {(round(min(w, h)), round(max(w, h))) for w, h, _, _ in pages} == {(595, 842)}
        for w, h, right, _ in pages:
            assert right <= w - 10 / 25.4 * 72, (w, right)     # inside the page's 15 mm margin


@pytest.mark.parametrize("template", ["variants_compressor.toml", "variants_engine.toml",
                                      "variants_task2.toml"])
def test_a_task_sheet_prints_on_one_a4_page(tmp_path, template):
    """A teacher prints the HTML sheets from a browser: each variant's sheet is one A4 page,
    a run template's 40-odd data rows too (docs/teacher.md); read back with pypdf."""
    from pypdf import PdfReader

    browser = _browser()
    out = tmp_path / "v"
    res = CliRunner().invoke(app, ["variants", str(CASES / template), "--count", "2", "--seed",
                                   "7", "--sheets", "--sheets-format", "html", "--lang", "ru",
                                   "--out", str(out)])
    assert res.exit_code == 0, res.output
    for sheet in sorted((out / "sheets").glob("variant_*.html")):
        printed = tmp_path / (sheet.stem + ".pdf")
        run = _chromium(browser, tmp_path, "--no-pdf-header-footer",
                        f"--print-to-pdf={printed}", sheet.as_uri())
        assert run.returncode == 0 and printed.read_bytes()[:4] == b"%PDF", run.stderr[-2000:]
        pdf = PdfReader(printed)
        assert len(pdf.pages) == 1, (sheet.name, len(pdf.pages))
        box = pdf.pages[0].mediabox
        assert (round(float(box.width)), round(float(box.height))) == (595, 842)
        text = pdf.pages[0].extract_text()
        assert "Дано" in text and "Задание" in text and "1. Определить" in text, text[:300]
