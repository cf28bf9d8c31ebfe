"""Nothing typed by hand in the manuscript: every result and every parameter in paper/*.tex comes
from a generated macro. A number of more than one digit, a fraction or a decimal in the text or its
mathematics fails, unless it is structural (a label, a reference, a citation) or on the allowlist."""

import re
from pathlib import Path

import pytest

PAPER = Path(__file__).resolve().parents[2] / "paper"
SOURCES = sorted(PAPER.rglob("*.tex"))

#: Numbers that are names or quotations, not results: each with why.
ALLOWED = {
    "DOP853": "the name of an integration method",
    r"\tfrac23": "the paper's printed formula for Delta~, quoted",
    r"Fig.~4": "the paper's own figure number",
}
STRUCTURAL = re.compile(r"\\(label|ref|eqref|cite|input|include|includegraphics|script|url|href|bibliography|"
                        r"bibliographystyle|resultsdir|documentclass|usepackage|setlength|geometry)"
                        r"(\[[^\]]*\])?\{[^}]*\}")


def typed_numbers(text: str) -> list[tuple[int, str]]:
    """(line, token) of every number of two or more characters outside structural commands."""
    if r"\begin{document}" in text:
        head, body = text.split(r"\begin{document}", 1)
        offset = head.count("\n")
    else:
        body, offset = text, 0
    found = []
    for n, line in enumerate(body.splitlines(), offset + 1):
        line = re.sub(r"(?<!\\)%.*", "", line)
        for allowed in ALLOWED:
            line = line.replace(allowed, " ")
        line = STRUCTURAL.sub(" ", line)
        line = re.sub(r"\\[A-Za-z]+", " ", line)   # macro names hold no numbers
        found += [(n, m.group()) for m in re.finditer(r"\d+(?:[./]\d+)*", line) if len(m.group()) > 1]
    return found


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: p.name)
def test_no_number_is_typed_by_hand(path):
    assert typed_numbers(path.read_text()) == [], f"{path.name}: use a generated macro"


def test_the_scan_finds_a_typed_result():
    text = "\\begin{document}\nThe fit gives $c_0 = 0.4647$ over rows 1--10 at $\\alpha = 3/2$ (Fig.~\\ref{fig:4}).\n"
    assert [tok for _, tok in typed_numbers(text)] == ["0.4647", "10", "3/2"]


def test_generated_text_writes_numbers_and_minus_signs_as_mathematics():
    """The ledger's plain-text values become LaTeX: 1.6e-08 a power of ten, a spaced or leading '-'
    a minus sign (a bare '-' in text is a hyphen), hyphenated labels untouched."""
    import sys
    sys.path.insert(0, str(PAPER.parent / "workflow" / "scripts"))
    from common.latex import math_text

    assert math_text("1.6e-08 in the forward one") == r"\(1.6\times 10^{-8}\) in the forward one"
    assert r"\(-\)" in math_text("tau_b - tau_0") and r"\(-\)" in math_text("-1 - (2/3)")
    assert math_text("P-N2-K2-Dprinted") == "P-N2-K2-Dprinted"
