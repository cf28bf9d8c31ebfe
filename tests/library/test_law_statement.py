"""The scaled law is written one way everywhere a reader meets it (issue 55): Omega multiplies the
elastic term, x'' + Omega x^alpha + x^gamma x' = 0. `help(restitution)` and `restitution.core`
had put it on the damping term."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# Omega written in front of the damping term x^gamma x' (plain text, or LaTeX's \Omega / \Om)
WRONG = re.compile(r"(Omega|\\Om(ega)?)\s*\*?\s*x~?\s*\^\s*\{?\s*\\?gamma\s*\}?\s*\*?\s*(x~?'|\\dot)")
TEXT = [ROOT / "README.md", *ROOT.glob("src/**/*.py"), *ROOT.glob("workflow/**/*.py"), *ROOT.glob("docs/**/*.md"),
        *ROOT.glob("docs/**/*.py"), *ROOT.glob("docs/**/*.rst"), *ROOT.glob("paper/**/*.tex")]


def test_the_pattern_finds_the_wrong_form_and_not_the_right_one():
    assert WRONG.search("x'' + Omega x^gamma x' + x^alpha = 0")
    assert WRONG.search(r"\ddot x + \Omega x^{\gamma}\dot x + x^\alpha = 0")
    assert not WRONG.search("x'' + Omega x^alpha + x^gamma x' = 0")


def test_no_file_puts_omega_on_the_damping_term():
    found = [f"{p.relative_to(ROOT)}: {m.group(0)}" for p in TEXT if "_build" not in p.parts
             for m in WRONG.finditer(p.read_text(errors="replace"))]
    assert not found, "\n".join(found)


def test_the_package_help_states_the_law():
    import restitution
    import restitution.core
    for module in (restitution, restitution.core):
        assert "x'' + Omega x^alpha + x^gamma x' = 0" in module.__doc__
