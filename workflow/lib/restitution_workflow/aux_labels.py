"""The numbers of a LaTeX document's labels, from its .aux, for another document's ``xr``.

    python aux_labels.py build/article-labels/restitution.aux | python atomic.py write results/paper/article_labels.aux

The article reads the supplement's labels and the supplement the article's. A label's number (of an
equation, figure, table or section) follows from the document's source alone, so one pdflatex pass of
the article gives them, before the supplement is built: no cycle in the build. That pass's .aux also
holds page numbers and citations, which depend on what the pass found (the supplement's .aux of an
earlier build, or none): only the numbers are kept, each as ``\\newlabel{key}{{number}{}{}{}{}}``,
hyperref's five fields with the four that ``\\ref*`` does not read left empty. The file is therefore the
same bytes whatever the pass found.
"""

from __future__ import annotations

import sys
from pathlib import Path

__all__ = ["label_numbers"]

_PREFIX = "\\newlabel{"


def _group(text: str, start: int) -> tuple[str, int]:
    """The brace group opening at text[start] ('{'): its content and the index after its '}'."""
    if text[start:start + 1] != "{":
        raise ValueError(f"expected '{{' at {start} in {text!r}")
    depth = 0
    for i in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return text[start + 1:i], i + 1
    raise ValueError(f"unbalanced braces in {text!r}")


def label_numbers(aux: str) -> str:
    r"""Each ``\newlabel`` of `aux` with its number only, in the order of `aux`.

    Labels of hyperref's own bookkeeping (those holding ``@``) are left out.

    Examples
    --------
    >>> aux = "\\relax\n\\newlabel{eq:model}{{1}{2}{Model}{equation.2.1}{}}\n\\citation{kim}\n" \
    ...       "\\newlabel{app:a}{{A}{14}{Derivations}{appendix.A}{}}\n\\newlabel{x@cref}{{[x]}{1}}\n"
    >>> print(label_numbers(aux), end="")
    \newlabel{eq:model}{{1}{}{}{}{}}
    \newlabel{app:a}{{A}{}{}{}{}}
    """
    out = []
    for line in aux.splitlines():
        if not line.startswith(_PREFIX):
            continue
        key, end = _group(line, len(_PREFIX) - 1)
        if "@" in key:
            continue
        value, _ = _group(line, end)
        number, _ = _group(value, 0)
        out.append(f"\\newlabel{{{key}}}{{{{{number}}}{{}}{{}}{{}}{{}}}}\n")
    return "".join(out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: aux_labels.py FILE.aux  (writes the labels' numbers to standard output)", file=sys.stderr)
        sys.exit(2)
    try:
        text = Path(sys.argv[1]).read_text(encoding="utf-8", errors="replace")
    except OSError as err:
        print(f"aux_labels.py: {sys.argv[1]}: {err.strerror}", file=sys.stderr)
        sys.exit(2)
    sys.stdout.write(label_numbers(text))
