"""`make report` seen in a browser: results/report.html opened in headless Chromium, every variant's
four figures shown as the report's own view button shows them, decoded and laid out; and the
manuscript's last section names the commit and the software it was built from.

Snakemake's report is a single-page app with the figures embedded as data URIs, so the HTML holding
a figure's path proves nothing about what a reader sees. A copy of the report gets a script that,
after the app has started, puts each figure on screen through the app (`app.setView`, what a click
on the figure's eye button does) and records the image's decoded and displayed size; Chromium's
--dump-dom returns that record. A screenshot of each main-variant figure is checked for drawn pixels.
Chromium is the Debian package, installed by `make test` as root; skipped with the reason elsewhere.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest


from pipeline_tree import ALL, ROOT, copy_built  # noqa: E402
from test_pipeline import VARIANT_NAMES, snakemake  # noqa: E402

CHROMIUM = shutil.which("chromium")
# Headless, as root (no sandbox), with the network closed: nothing started that would reach out.
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]
FIGURES = [f"results/{variant}/figures/fig{n}.png" for variant in VARIANT_NAMES for n in (1, 2, 3, 4)]

pytestmark = [pytest.mark.browser,
              pytest.mark.skipif(CHROMIUM is None, reason="needs chromium: make test installs it as root "
                                 "(apt-get install chromium)")]

DRIVER = """<script>
// appended by tests/pipeline/test_report_browser.py
(function () {
  const wanted = %s, out = {};
  const pre = document.createElement("pre");
  pre.id = "render-check";
  function record() { pre.textContent = JSON.stringify(out); }
  function show(i) {
    if (i === wanted.length) { out.done = true; return record(); }
    const path = wanted[i], entry = results[path], t0 = Date.now();
    if (!entry) { out[path] = "not a report item"; record(); return show(i + 1); }
    app.setView({content: "img", contentPath: entry.data_uri, resultPath: path});
    (function wait() {
      const img = [...document.querySelectorAll("#app img")].find(im => im.getAttribute("src") === entry.data_uri);
      if (img && img.complete) {
        const box = img.getBoundingClientRect();
        out[path] = {natural: [img.naturalWidth, img.naturalHeight], shown: [box.width, box.height]};
        record();
        return show(i + 1);
      }
      if (Date.now() - t0 > 5000) { out[path] = "not shown within 5 s"; record(); return show(i + 1); }
      setTimeout(wait, 50);
    })();
  }
  window.addEventListener("load", () => setTimeout(() => {
    document.body.appendChild(pre);
    try { show(0); } catch (err) { out.error = String(err); record(); }
  }, 200));
})();
</script>"""


@pytest.fixture(scope="module")
def report(built, tmp_path_factory) -> Path:
    tree = copy_built(built, tmp_path_factory.mktemp("report") / "t")
    snakemake(tree, "--report", "results/report.html")
    return tree / "results/report.html"


def chromium(page: Path, profile: Path, *args: str) -> subprocess.CompletedProcess:
    # virtual time: the page's timers run at once, and Chromium returns when they are done
    return subprocess.run([CHROMIUM, *FLAGS, f"--user-data-dir={profile}", "--virtual-time-budget=60000",
                           *args, page.as_uri()], capture_output=True, text=True, timeout=300)


def driven(report: Path, dest: Path, figures: list[str]) -> Path:
    html = report.read_text()
    end = html.rindex("</body>")
    dest.write_text(html[:end] + DRIVER % json.dumps(figures) + html[end:])
    return dest


def test_every_figure_renders_in_the_report(report, tmp_path):
    proc = chromium(driven(report, tmp_path / "report.html", FIGURES), tmp_path / "profile", "--dump-dom")
    found = re.search(r'<pre id="render-check">([^<]*)</pre>', proc.stdout)
    assert found, f"the report's app did not run:\n{proc.stderr[-2000:]}"
    shown = json.loads(found.group(1).replace("&quot;", '"'))
    assert shown.get("done") and "error" not in shown, shown
    for path in FIGURES:
        assert isinstance(shown[path], dict), (path, shown[path])
        (width, height), (box_width, box_height) = shown[path]["natural"], shown[path]["shown"]
        assert width > 500 and height > 500 and box_width > 300 and box_height > 200, (path, shown[path])


def drawn(report: Path, workdir: Path, figures: list[str]) -> float:
    """The share of dark pixels (axes, curves, text) right of the report's menu, on a screenshot
    taken after `figures` were put on screen."""
    from matplotlib.image import imread

    workdir.mkdir()
    shot = workdir / "shot.png"
    proc = chromium(driven(report, workdir / "report.html", figures), workdir / "profile",
                    "--window-size=1280,1000", f"--screenshot={shot}")
    assert shot.exists(), proc.stderr[-2000:]
    pixels = imread(shot)[:, 300:, :3]
    return float((pixels.min(axis=2) < 0.5).mean())


@pytest.fixture(scope="module")
def landing(report, tmp_path_factory) -> float:
    """The report's first page (its rule graph: thin grey lines, about 0.4 % dark here)."""
    return drawn(report, tmp_path_factory.mktemp("landing") / "shot", [])


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_a_screenshot_of_each_main_figure_shows_a_drawing(report, landing, tmp_path, n):
    figure = f"results/{VARIANT_NAMES[0]}/figures/fig{n}.png"
    share = drawn(report, tmp_path / "shot", [figure])      # 3-4 % on this machine
    assert share > max(0.01, 3 * landing), f"{figure}: {share:.4f} of the screen drawn, first page {landing:.4f}"


@pytest.mark.skipif(ALL != "all", reason="needs pdflatex and latexmk (make test installs them as root)")
def test_the_manuscript_names_its_commit_and_software(built):
    """Parameters of the provenance rule: two builds of one commit in one environment give the same
    bytes (make check, make reproducible), another commit or package version rebuilds the PDF. The
    test's build is a copy without .git; a checkout names its HEAD."""
    from restitution_workflow.provenance import build_commit, versions

    head = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "HEAD"], capture_output=True, text=True)
    if head.returncode == 0:
        assert build_commit(ROOT).startswith(head.stdout.strip())

    text = (built / "results/paper/provenance.tex").read_text()
    commit = re.search(r"\\newcommand\{\\BuildCommit\}\{\\texttt\{([^}]*)\}\}", text).group(1)
    assert re.fullmatch(r"[0-9a-f]{40}( with uncommitted changes)?|unknown \(not a git checkout\)", commit)
    pdf = subprocess.run(["pdftotext", str(built / "results/paper/restitution.pdf"), "-"],
                         capture_output=True, text=True).stdout
    flat = " ".join(pdf.split())
    assert f"built from commit {commit}" in flat
    for name, version in versions().items():
        assert f"{name} {version}" in flat, name
