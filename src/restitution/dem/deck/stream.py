"""What an engine executed, read back from its run of a deck's scratch copy
(:mod:`restitution.dem.deck.scratch`): the commands in the order they ran, each after the engine's
own substitution and with the deck line it came from, and the atoms each run saw.

The engine echoes every command it reads (a line with a variable outside quotes twice: as written,
then substituted); its other output is told apart by not being a command of the copied files (or
a command quoted in one of their ``if`` lines).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .scratch import DYNAMIC, NOOP, Scratch, normalised
from ..deck_text import TRIPLE, segments

__all__ = ["Executed", "executed", "skipped", "unchecked", "snapshots", "engine_error"]


@dataclass
class Executed:
    """One command the engine ran: ``loc`` (file or None, line) of the deck line it came from,
    ``text`` as the engine ran it, ``stage`` the run marker's number where it is a run's marker
    (then ``text`` is the run), else None."""
    loc: tuple
    text: str
    stage: int | None = None


def _echo_lines(echo: str) -> list[str]:
    """The screen's lines, a command whose triple quote spans lines joined into one."""
    out, pending = [], None
    for line in echo.split("\n"):
        pending = line if pending is None else pending + "\n" + line
        if pending.count(TRIPLE) % 2 == 0:
            out.append(pending)
            pending = None
    if pending is not None:
        out.append(pending)
    return out


def _substituted(line: str) -> bool:
    """Whether the engine substitutes in this line (a $ outside quotes), so echoes it twice."""
    return any("$" in piece for piece, quote in segments(line) if not quote)


def executed(echo: str, scratch: Scratch) -> list[Executed]:
    """The commands an engine ran, from its echo.

    Parameters
    ----------
    echo : str
        The engine's screen output with commands echoed.
    scratch : Scratch
        The copy it ran.

    Returns
    -------
    list of Executed

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), lines={"variable a equal 2": (None, 1),
    ...                                                      "pair_coeff * * hooke $a 0": (None, 2)})
    >>> [(e.loc, e.text) for e in executed("variable a equal 2\\npair_coeff * * hooke $a 0\\n"
    ...                                    "pair_coeff * * hooke 2 0\\nCreated 1 atoms\\n", s)]
    [((None, 1), 'variable a equal 2'), ((None, 2), 'pair_coeff * * hooke 2 0')]
    """
    marker = re.compile(rf"include {re.escape(str(scratch.root))}/stage_(\d+)")
    lines = _echo_lines(echo)
    out, k, opened = [], 0, False
    while k < len(lines):
        key = normalised(lines[k])
        k += 1
        m = marker.fullmatch(key)
        if m:
            stage = int(m.group(1))
            f, n, run = scratch.stages[stage]
            out.append(Executed((f, n), run, stage))
            opened = True        # the marker's first command, echoed next, is the run itself
            continue
        if key not in scratch.lines:
            continue
        loc, text = scratch.lines[key], key
        # one echo after each substitution, until no $ is left outside quotes
        while _substituted(text) and k < len(lines) and normalised(lines[k]).split()[:1] == key.split()[:1]:
            text = normalised(lines[k])
            k += 1
        if opened and text.split()[:1] == out[-1].text.split()[:1]:
            # the run itself, echoed from its marker, substituted (its text may be that of an
            # earlier line: the marker's line is its own)
            out[-1].text, opened = text, False
            continue
        opened = False
        out.append(Executed(loc, text))
    return out


def skipped(commands: list, scratch: Scratch) -> dict:
    """The commands made no-ops that the engine reached: {command: (file, line) of the first}.

    Parameters
    ----------
    commands : list of Executed
        What :func:`executed` read from the engine's echo (a no-op's echo is one of them).
    scratch : Scratch
        The copy it ran.

    Returns
    -------
    dict

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), skipped=[("shell", (None, 3)), ("dump", (None, 4))])
    >>> skipped([Executed((None, 4), "label restitution_skipped_1")], s)
    {'dump': (None, 4)}
    """
    out = {}
    for k in _marks(commands, _SKIPPED):
        command, loc = scratch.skipped[k]
        out.setdefault(command, loc)
    return out


def unchecked(commands: list, scratch: Scratch) -> list:
    """The commands whose name comes from a variable that the engine reached (never run):
    [((file, line), text)].

    Parameters
    ----------
    commands : list of Executed
    scratch : Scratch

    Returns
    -------
    list

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), dynamic=[((None, 2), "${c} 1")])
    >>> unchecked([Executed((None, 2), "label restitution_unchecked_0")], s)
    [((None, 2), '${c} 1')]
    """
    return [scratch.dynamic[k] for k in _marks(commands, _UNCHECKED)]


_SKIPPED = re.compile(NOOP.format(r"(\d+)"))
_UNCHECKED = re.compile(DYNAMIC.format(r"(\d+)"))


def _marks(commands: list, pattern) -> list[int]:
    """The numbers of the no-op markers of one kind among the commands run, in order."""
    return [int(m.group(1)) for cmd in commands if (m := pattern.fullmatch(cmd.text))]


def snapshots(atoms: str) -> list[dict]:
    """Each run's atoms, from the markers' dumps (columns type radius mass): {type: {(radius,
    density)}}, density = mass / (4/3 pi r^3) (a point particle's None).

    Parameters
    ----------
    atoms : str

    Returns
    -------
    list of dict

    Examples
    --------
    >>> snapshots("ITEM: TIMESTEP\\n0\\nITEM: NUMBER OF ATOMS\\n1\\nITEM: BOX BOUNDS pp pp pp\\n0 1\\n0 1\\n0 1\\n"
    ...           "ITEM: ATOMS type radius mass\\n2 0.5 0.5235987755982988\\n")
    [{2: {(0.5, 1.0)}}]
    """
    out, lines, k = [], atoms.split("\n"), 0
    while k < len(lines):
        if lines[k].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[k + 1])
            k += 2
            while not lines[k].startswith("ITEM: ATOMS"):
                k += 1
            snap: dict = {}
            for row in lines[k + 1:k + 1 + n]:
                t, r, m = row.split()[:3]
                r, m = float(r), float(m)
                volume = 4.0 / 3.0 * math.pi * r ** 3
                # a radius below ~1e-108 has a volume that underflows to 0: no density (named)
                rho = m / volume if volume > 0 else None
                snap.setdefault(int(t), set()).add((r, None if rho is None else float(f"{rho:.12g}")))
            out.append(snap)
            k += 1 + n
        else:
            k += 1
    return out


def engine_error(text: str, scratch: Scratch) -> tuple[str, str, str]:
    """(where, line, message) of an engine's ERROR: the deck line it names (its last input line).

    Parameters
    ----------
    text : str
        The engine's error output.
    scratch : Scratch

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), lines={"run 1": (None, 7)})
    >>> engine_error("ERROR: All pair coeffs are not set (src/pair.cpp:1)\\nLast input line: run 1", s)
    ('line 7', 'run 1', 'All pair coeffs are not set')
    """
    m = re.search(r"ERROR(?: on proc \d+)?: (.*?)(?: \((?:\./)?src/[^)]*\))?$", text, re.M)
    message = m.group(1).strip() if m else text.strip().splitlines()[-1] if text.strip() else "it stopped"
    last = re.search(r"Last (?:input line|command): (.*)$", text, re.M)
    line = normalised(last.group(1)) if last else ""
    loc = scratch.lines.get(line)
    where = "the deck" if loc is None else f"line {loc[1]}" if loc[0] is None else f"{loc[0]} line {loc[1]}"
    return where, line, message
