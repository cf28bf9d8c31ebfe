"""The README (issue 45): a page, not a manual. At most 200 lines; the two set-up commands as they
always were, with `make docs` below them; the eps its Python example shows are the library's; every
link into docs/ points at a file; no timing typed in prose (the docs' own check,
tests/library/test_docs_site.py, covers the rest). That its blocks run as printed, command-line
ones included, is tests/library/test_doc_blocks.py's check."""

from __future__ import annotations

import io
import re
from contextlib import redirect_stderr
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text()
TWO_COMMANDS = """```sh
make paper   # creates .venv, installs TeX Live from Debian packages if pdflatex is missing,
             # runs the whole pipeline, prints the path of the PDF (results/paper/restitution.pdf)
make test    # creates .venv, installs TeX Live the same way, runs the whole test suite
```"""


def test_the_readme_fits_on_a_page():
    assert len(README.splitlines()) <= 200


def test_the_two_commands_are_unchanged_and_make_docs_follows_them():
    assert TWO_COMMANDS in README
    assert README.index(TWO_COMMANDS) < README.index("make docs")


def test_the_python_example_runs_and_its_numbers_are_the_librarys():
    code = re.search(r"```python\n(.*?)```", README, flags=re.S).group(1)
    scope: dict = {}
    with redirect_stderr(io.StringIO()):
        exec(compile(code, "README.md", "exec"), scope)
    shown = re.search(r"\[([0-9., ]+)\], the method used", code).group(1)
    assert [round(float(e), 6) for e in scope["r"].eps] == [float(x) for x in shown.split(",")]


def test_the_links_into_the_docs_resolve():
    links = re.findall(r"\]\(((?:docs)/[^)#]+)", README)
    assert links
    for link in links:
        assert (ROOT / link).exists(), link
