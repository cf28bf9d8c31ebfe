"""LAMMPS' and LIGGGHTS' input-script text as the audit compares it with what an engine echoed:
how a file becomes commands and words. The engines themselves substitute variables, evaluate
expressions and decide which commands run (:mod:`restitution.dem.deck.scratch`,
:mod:`restitution.dem.deck.stream`); nothing here does.

LAMMPS (22 Jul 2025, and LIGGGHTS, which shares its parser) reads a script as follows, and so
does :func:`logical_lines` with :func:`words`:

1. A line whose last printable character is ``&`` continues on the next, the ``&`` removed (even
   in a comment); a line with an odd number of triple quotes ``\"\"\"`` continues with its newline
   kept, so a triple-quoted text may span lines.
2. ``#`` starts a comment, except inside single, double or triple quotes.
3. The line is split into words at whitespace; a word in quotes is one word, quotes removed.
"""

from __future__ import annotations

__all__ = ["ScriptError", "TRIPLE", "segments", "logical_lines", "strip_comment", "words", "written_words",
           "if_branches"]

#: LAMMPS' triple quote, which may span lines
TRIPLE = '"""'


# ---------------------------------------------------------------------------- words
class ScriptError(ValueError):
    """Why a line is not a command LAMMPS would run (the caller names the line)."""


def _segments(line: str):
    """(text, quote) pieces of ``line``: quote is "" outside quotes, else the quote that opened the
    piece (the quotes themselves belong to the quoted piece). LAMMPS' own scan: a quote anywhere,
    even inside a word, opens or closes."""
    if '"' not in line and "'" not in line:
        # no quote: one piece (an engine's echo is mostly such lines, scanned by the thousand)
        return [(line, "")] if line else []
    out, start, quote, k = [], 0, "", 0
    while k < len(line):
        if not quote:
            opening = TRIPLE if line.startswith(TRIPLE, k) else line[k] if line[k] in "\"'" else ""
            if opening:
                if k > start:
                    out.append((line[start:k], ""))
                start, quote = k, opening
                k += len(opening)
                continue
        elif line.startswith(quote, k):
            k += len(quote)
            out.append((line[start:k], quote))
            start, quote = k, ""
            continue
        k += 1
    if start < len(line):
        out.append((line[start:], quote))
    return out


def segments(line: str) -> list[tuple[str, str]]:
    """(text, quote) pieces of ``line`` as LAMMPS scans it: quote is "" outside quotes, else the
    quote that opened the piece (the quotes belong to the piece).

    Parameters
    ----------
    line : str

    Returns
    -------
    list of (str, str)

    Examples
    --------
    >>> segments('if "${a} > 1" then "run 1"')
    [('if ', ''), ('"${a} > 1"', '"'), (' then ', ''), ('"run 1"', '"')]
    """
    return list(_segments(line))


def strip_comment(line: str) -> str:
    """``line`` up to its first ``#`` outside quotes."""
    if "#" not in line:
        return line
    kept = []
    for text, quote in _segments(line):
        if not quote and "#" in text:
            kept.append(text.split("#", 1)[0])
            break
        kept.append(text)
    return "".join(kept)


def logical_lines(text: str) -> list[tuple[int, str]]:
    """(number of the first physical line, command text) of every non-blank command in ``text``:
    continuations joined, comments removed, quotes kept."""
    out, pending, start = [], "", 0
    for n, raw in enumerate(text.splitlines(), 1):
        if not pending:
            start = n
        pending += raw
        if pending.count(TRIPLE) % 2:
            pending += "\n"          # an open triple quote: the text goes on, newline and all
            continue
        body = pending.rstrip()
        if body.endswith("&"):
            pending = body[:-1]
            continue
        line = strip_comment(pending).strip()
        pending = ""
        if line:
            out.append((start, line))
    if pending.strip() and strip_comment(pending).strip():
        out.append((start, strip_comment(pending).strip()))   # LAMMPS runs an unfinished last line too
    return out


def words(line: str) -> list[str]:
    """The words of a command: split at whitespace, a quoted text one word without its quotes.
    ScriptError where a quote is not closed, or a closing quote runs into more text (LAMMPS stops
    on both)."""
    if '"' not in line and "'" not in line:
        return line.split()       # no quote: whitespace alone splits it (str.isspace's whitespace)
    return [line[start:end] for _, _, start, end in _spans(line)]


def if_branches(parts: list) -> list[str] | None:
    """The commands an ``if COND then C... [elif COND C...]... [else C...]`` may run, given its
    words (:func:`words`): the words after ``then``, each ``elif``'s condition skipped, and after
    ``else``. None where the words are not such an if.

    Parameters
    ----------
    parts : list of str
        The if's words, its quoted commands without their quotes.

    Returns
    -------
    list of str or None

    Examples
    --------
    >>> if_branches(words('if "${a} > 1" then "print x" "pair_coeff * * 1" elif "${a} < 0" quit else "run 1"'))
    ['print x', 'pair_coeff * * 1', 'quit', 'run 1']
    >>> if_branches(["if", "1"]) is None
    True
    """
    if len(parts) < 4 or parts[0] != "if" or parts[2] != "then":
        return None
    branches, k = [], 3
    while k < len(parts):
        if parts[k] == "elif":
            k += 2
        elif parts[k] == "else":
            k += 1
        else:
            branches.append(parts[k])
            k += 1
    return branches


def written_words(line: str) -> list[str]:
    """The words of a command as written, a quoted word with its quotes: the k-th is the k-th of
    :func:`words`, so that a command can be written again without some of its words, the others
    kept as the engine reads them (a quoted name with spaces stays one word). ScriptError as
    :func:`words` raises it.

    Parameters
    ----------
    line : str
        A command, its comment removed.

    Returns
    -------
    list of str

    Examples
    --------
    >>> written_words('fix a all ave/time 1 1 1 v_x file "a  a.txt" mode scalar')[-4:]
    ['file', '"a  a.txt"', 'mode', 'scalar']
    """
    if '"' not in line and "'" not in line:
        return line.split()
    return [line[start:end] for start, end, _, _ in _spans(line)]


def _spans(line: str) -> list[tuple[int, int, int, int]]:
    """(start, end) of each word of ``line`` as written and (start, end) of what the engine takes of
    it (a quoted word without its quotes)."""
    out, k, n = [], 0, len(line)
    while k < n:
        if line[k].isspace():
            k += 1
            continue
        quote = TRIPLE if line.startswith(TRIPLE, k) else line[k] if line[k] in "\"'" else ""
        if quote:
            end = line.find(quote, k + len(quote))
            if end < 0:
                raise ScriptError(f"a {quote} quote is not closed (LAMMPS stops: unbalanced quotes)")
            after = end + len(quote)
            if after < n and not line[after].isspace():
                raise ScriptError(f"text runs on after a closing {quote} quote (LAMMPS stops: unbalanced quotes)")
            out.append((k, after, k + len(quote), end))
            k = after
        else:
            end = k
            while end < n and not line[end].isspace():
                end += 1
            out.append((k, end, k, end))
            k = end
    return out
