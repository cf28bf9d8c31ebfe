"""The code a reader copies first runs as printed (issue 55): every Python block and every console
block of the README and of Getting started.

- A ```python block runs alone, in a fresh namespace, as a reader pastes it. A comment naming an
  attribute of one of its values (``c.ended_by``) names one that exists.
- The ``{code-cell}`` blocks of a MyST notebook page run in order in one namespace, as the docs
  build's kernel runs them.
- A ```console block's ``$ restitution ...`` lines run through the command, and what it prints is
  compared with what the block shows, loosely: spaces collapsed, numbers equal to 1e-9 relative,
  and a line ``...`` stands for any lines.
"""

from __future__ import annotations

import io
import math
import re
import shlex
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

from restitution.cli import main

ROOT = Path(__file__).resolve().parents[2]
PAGES = ["README.md", "docs/getting-started.md"]
FENCE = re.compile(r"^```(\S*)[^\n]*\n(.*?)^```", flags=re.S | re.M)


def blocks(page: str, kind: str) -> list[tuple[int, str]]:
    """(line number, text) of each fenced block of that kind (``python``, ``console``,
    ``{code-cell}``), a code cell's option lines (``:tags: ...``) left out."""
    text = (ROOT / page).read_text()
    found = []
    for m in FENCE.finditer(text):
        if m.group(1) == kind:
            body = m.group(2)
            if kind == "{code-cell}":
                body = "".join(ln for ln in body.splitlines(True) if not ln.startswith(":"))
            found.append((text.count("\n", 0, m.start()) + 1, body))
    return found


def _ids(items):
    return [f"{page}:{line}" for page, line, _ in items]


PYTHON = [(p, line, code) for p in PAGES for line, code in blocks(p, "python")]
CONSOLE = [(p, line, text) for p in PAGES for line, text in blocks(p, "console")]
NOTEBOOKS = [p for p in PAGES if blocks(p, "{code-cell}")]

# `name.attr` in a comment: the attributes a reader is told to look at
_MENTION = re.compile(r"\b([A-Za-z_]\w*)\.([A-Za-z_]\w*)\b")


def _run_python(code: str, where: str, scope: dict) -> dict:
    with redirect_stderr(io.StringIO()), redirect_stdout(io.StringIO()):
        exec(compile(code, where, "exec"), scope)
    return scope


def test_the_pages_have_blocks_to_run():
    assert len(PYTHON) >= 2 and len(CONSOLE) >= 3 and NOTEBOOKS == ["docs/getting-started.md"]


@pytest.mark.parametrize("page, line, code", PYTHON, ids=_ids(PYTHON))
def test_each_python_block_runs_alone_and_its_comments_name_real_attributes(page, line, code):
    scope = _run_python(code, f"{page}:{line}", {})
    missing = []
    for comment in re.findall(r"#(.*)$", code, flags=re.M):
        for name, attr in _MENTION.findall(comment):
            value = scope.get(name)
            if value is not None and not hasattr(value, attr):
                missing.append(f"{name}.{attr}")
    assert not missing, f"{page}:{line}: the comments name {missing}, which do not exist"


@pytest.mark.parametrize("page", NOTEBOOKS)
def test_a_notebook_pages_cells_run_in_order(page):
    scope: dict = {}
    for line, code in blocks(page, "{code-cell}"):
        _run_python(code, f"{page}:{line}", scope)


def _same_line(shown: str, got: str) -> bool:
    a, b = shown.split(), got.split()
    if len(a) != len(b):
        return False
    for x, y in zip(a, b):
        if x == y:
            continue
        try:
            fx, fy = float(x), float(y)
        except ValueError:
            return False
        if not math.isclose(fx, fy, rel_tol=1e-9, abs_tol=0.0):
            return False
    return True


def matches(shown: str, got: str) -> bool:
    """Whether the printed output ``got`` is what the block shows (see the module docstring)."""
    want = [ln for ln in shown.splitlines() if ln.strip()]
    have = [ln for ln in got.splitlines() if ln.strip()]

    def walk(i: int, j: int) -> bool:
        if i == len(want):
            return j == len(have)
        if want[i].strip() == "...":
            return any(walk(i + 1, k) for k in range(j, len(have) + 1))
        return j < len(have) and _same_line(want[i], have[j]) and walk(i + 1, j + 1)

    return walk(0, 0)


def test_the_loose_comparison_still_compares():
    assert matches("eps  0.330674371344\n...\nend force\n", "eps 0.3306743713440001\nx 1\ny 2\nend force\n")
    assert not matches("eps  0.330674371344\n", "eps  0.330674371\n")
    assert not matches("end  force\n", "end  overlap\n")
    assert not matches("a\nb\n", "a\n")


def _commands(text: str) -> list[tuple[str, str]]:
    """Each ``$ command`` of a console block with the lines it shows, up to the next ``$``."""
    out, current = [], None
    for ln in text.splitlines():
        if ln.startswith("$ "):
            current = [ln[2:], []]
            out.append(current)
        elif current is not None:
            current[1].append(ln)
    return [(cmd, "\n".join(lines)) for cmd, lines in out]


@pytest.mark.parametrize("page, line, text", CONSOLE, ids=_ids(CONSOLE))
def test_each_console_block_prints_what_it_shows(page, line, text):
    commands = _commands(text)
    assert commands, f"{page}:{line}: no '$ ' line"
    for command, shown in commands:
        argv = shlex.split(command)
        assert argv[0] == "restitution", f"{page}:{line}: only the restitution command is run here"
        out = io.StringIO()
        with redirect_stderr(io.StringIO()):
            assert main(argv[1:], out=out) == 0, command
        assert matches(shown, out.getvalue()), f"{page}:{line}: {command}\nshown:\n{shown}\nprinted:\n{out.getvalue()}"
