"""What an engine executed, read back from its run of a deck's scratch copy
(:mod:`restitution.dem.deck.scratch`): the commands in the order they ran, each after the engine's
own substitution and with the deck line it came from, and the atoms each run saw.

The engine echoes every command it reads (a line with a variable outside quotes twice: as written,
then substituted), the comment that tags its place with it; its other output is told apart by
carrying no tag and not being a command quoted in an ``if`` it ran.
"""

from __future__ import annotations

import copy
import math
import os
import re
from collections import Counter
from dataclasses import dataclass, replace
from pathlib import Path

from .scratch import (AUDIT, DYNAMIC, GUARDED, MAX_TEXT_BYTES, NOOP, SKIPPED_COMMANDS, STAGE_LABEL, UNSET, Scratch,
                      normalised)
from ..deck_text import TRIPLE, ScriptError, segments, words
from ..dialect.child import ATOMS, RUN_PRINTED, SETUP_DUMP

__all__ = ["Executed", "HeldSizes", "Snapshot", "executed", "skipped", "unchecked", "written_then_read", "unmapped_script", "snapshots", "engine_error", "first_unchecked",
           "SEEDED", "deck_commands"]


@dataclass(slots=True)
class Executed:
    """One command the engine ran: ``loc`` (file or None, line) of the deck line it came from,
    ``text`` as the engine ran it, ``stage`` the run marker's number where it is a run's marker
    (then ``text`` is the run), else None; ``snapshot`` whether that marker wrote the atoms (a
    LAMMPS marker skips its set-up check and its dump where its run was checked before,
    :func:`first_unchecked`; None: each marker wrote them); ``restart`` the read_restart marker's
    number where it is one (``text`` the read_restart); ``unset`` whether it is a set that met no
    atom in the pass (the scratch copy printed it instead of running it); ``written`` a run's text
    as the deck wrote it, before the engine's substitutions."""
    loc: tuple
    text: str
    stage: int | None = None
    snapshot: bool | None = None
    restart: int | None = None
    unset: bool = False
    written: str | None = None


def _echo_lines(echo: str) -> list[str]:
    """The screen's lines, a command whose triple quote spans lines joined into one."""
    if TRIPLE not in echo:
        return echo.split("\n")
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
    return "$" in line and any("$" in piece for piece, quote in segments(line) if not quote)


def _once_each(func):
    """(``func`` computed once per distinct argument, the dict of what it computed)."""
    done: dict = {}

    def once(arg):
        found = done.get(arg)
        if found is None:
            found = done[arg] = func(arg)
        return found
    return once, done


def executed(echo: str, scratch: Scratch) -> list[Executed]:
    """The commands an engine ran, from its echo, each with the deck line it came from.

    A line is the deck's by the tag its scratch copy gave it (:mod:`restitution.dem.deck.scratch`),
    never by its text alone: an untagged echo is a command an ``if`` or a run's ``every`` of a
    line echoed before runs (one it quotes), a line of a file a variable named for an ``include``
    or ``jump`` that ran (by its text, in that file only), or the engine's or the audit's own
    (markers, output), never a deck's command.

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
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), tag="#t@", tags=[(None, 1), (None, 2)])
    >>> [(e.loc, e.text) for e in executed("variable a equal 2 #t@0\\npair_coeff * * hooke $a 0 #t@1\\n"
    ...                                    "pair_coeff * * hooke 2 0\\nvariable a equal 2\\n", s)]
    [((None, 1), 'variable a equal 2'), ((None, 2), 'pair_coeff * * hooke 2 0')]
    """
    prefix, inline = f"include {scratch.root}/stage_", f"label {STAGE_LABEL}"
    marker = re.compile(rf"include {re.escape(str(scratch.root))}/stage_(\d+)|label {STAGE_LABEL}(\d+)")
    restart = re.compile(rf"include {re.escape(str(scratch.root))}/restart_(\d+)")
    tagged = re.compile(rf"{re.escape(scratch.tag)}(\d+|{AUDIT})\s*$")
    # the marker's dump of the atoms: LAMMPS' at its run's set-up, LIGGGHTS' after its step
    dump = (f"write_dump all custom {scratch.root / ATOMS} ", f"dump {SETUP_DUMP}")
    lines = _echo_lines(echo)
    # a loop echoes the same few lines thousands of times: each distinct line normalised once, and
    # scanned once for a $ outside quotes (a marker's quoted if is long)
    key_of, keys = _once_each(normalised)
    substituted, _ = _once_each(_substituted)
    out: list = []
    k, opened, stage_at, unset_at = 0, None, None, None
    ifs: list = []           # the lines echoed whose if or every runs quoted commands, latest last
    files: list = []         # the untagged files an include or jump of the deck opened, innermost last

    def follow(key: str) -> str:
        """The command after the engine's substitutions: one echo after each, until no $ is left
        outside quotes."""
        nonlocal k
        text, head = key, None
        while substituted(text) and k < len(lines) and not tagged.search(lines[k]):
            head = key.split(None, 1)[:1] if head is None else head
            echoed = key_of(lines[k])
            if echoed.split(None, 1)[:1] != head:
                break
            text = echoed
            k += 1
        return text

    while k < len(lines):
        raw = lines[k]
        key = keys.get(raw)          # key_of, inline: the loop's hottest line
        if key is None:
            key = keys[raw] = normalised(raw)
        k += 1
        if not key or _ERROR_CONTEXT.match(key):     # an error quotes the line, tag and all
            continue
        if unset_at is not None and key.startswith(_UNSET_PRINTED):
            # the deck's set, as LAMMPS substituted it: its own line's command
            out.append(Executed(unset_at, key[len(UNSET) + 1:], unset=True))
            unset_at = None
            continue
        m = marker.fullmatch(key) if key.startswith((prefix, inline)) else None
        if m:
            stage = int(m.group(1) or m.group(2))
            f, n, run = scratch.stages[stage]
            stage_at = len(out)
            out.append(Executed((f, n), run, stage, False, written=run))
            opened = run         # the marker's line of that text, echoed next, is the run itself
            _latest(ifs, (f, n), scratch)
            continue
        m = restart.fullmatch(key) if key.startswith(f"include {scratch.root}/restart_") else None
        if m:
            f, n, read = scratch.restarts[int(m.group(1))]
            out.append(Executed((f, n), read, restart=int(m.group(1))))
            opened = read       # its marker's first line, echoed next: the read_restart, substituted
            _latest(ifs, (f, n), scratch)
            continue
        if key.startswith(_RUN_PRINTED) and stage_at is not None:
            out[stage_at].text = key[len(_RUN_PRINTED):]    # the run, substituted by the engine's print
            continue
        if key.startswith(dump) and stage_at is not None:
            out[stage_at].snapshot = True         # the marker's dump of the atoms at this run
            continue
        tag = tagged.search(raw) if scratch.tag in raw else None
        if tag and tag.group(1) == AUDIT:
            text = follow(key) if "$" in key else key   # no $: nothing substituted
            if opened is not None and key == opened:
                out[-1].text = text          # the run, substituted: the stage's own text
            opened = None
            continue
        opened = None
        if tag:
            loc = scratch.tags[int(tag.group(1))]
        elif _MARK.fullmatch(key):
            loc = scratch.lines.get(key)     # a no-op of the audit's, in a deck's line (an if's)
        else:
            loc = next((where for where in reversed(ifs) if key in scratch.quoted.get(where, ())), None)
            if loc is None:
                for depth in range(len(files) - 1, -1, -1):
                    if files[depth] is _ANY_FILE:
                        files[depth] = next((label for label, known in scratch.files.items()
                                             if label not in scratch.tagged and key in known), _ANY_FILE)
                    loc = scratch.files.get(files[depth], {}).get(key)
                    if loc is not None:
                        del files[depth + 1:]     # the files opened inside it have ended
                        break
        if loc is None:
            continue                         # the engine's output, or a line of the audit's
        text = follow(key) if "$" in key else key   # no $: nothing substituted
        if text.startswith(_UNSET):
            unset_at = loc       # a set that met no atom in the pass: its printed text comes next
            _latest(ifs, loc, scratch)
            continue
        out.append(Executed(loc, text))
        _latest(ifs, loc, scratch)
        opened_file = _opened(text, scratch)
        if opened_file is not None:
            files.append(opened_file)
    return out


def _latest(ifs: list, loc, scratch: Scratch) -> None:
    """``loc`` made the latest of the lines whose quoted commands may be echoed next, where it has any."""
    if loc in scratch.quoted:
        if loc in ifs:
            ifs.remove(loc)
        ifs.append(loc)


#: What an engine's error says after its message: the line it stopped on, quoted
_ERROR_CONTEXT = re.compile(r"Last (?:input line|command): ")
#: The print that stands for a set (velocity) met by no atom in the pass (scratch.UNSET), and what it prints
_UNSET = f"print '{UNSET} "
_UNSET_PRINTED = tuple(f"{UNSET} {word} " for word in GUARDED)
#: What a marker's print of its run's substituted text prints before it (child.RUN_PRINTED)
_RUN_PRINTED = f"{RUN_PRINTED} "
#: The audit's no-ops (skipped commands, names from a variable): their text is the audit's alone
_MARK = re.compile(r"label restitution_(skipped|unchecked)_\d+")


#: What _opened gives for a file named through a variable left unsubstituted in the echo: the
#: untagged file whose line the engine echoes next
_ANY_FILE = object()


def _opened(text: str, scratch: Scratch):
    """The copied file an include or jump opens where none of its lines carries a tag (a file the
    deck names by a variable), as the scratch's ``files`` names it; else None."""
    if not text.startswith(("include", "jump")):      # most commands: no split
        return None
    try:
        split = words(text)          # a quoted name is one word, spaces and all, without its quotes
    except ScriptError:
        return None
    if len(split) < 2 or split[0] not in ("include", "jump") or split[1] == "SELF":
        return None
    name = split[1]
    if "$" in name:
        # quoted, its variables are left in the echo, and the engine substitutes them as it opens
        # the file (field round 29, I18: include "${f}"): the file is the one whose lines come next
        return _ANY_FILE
    folder = scratch.deck.parent
    where = Path(os.path.normpath(folder / name))
    # a file named by an absolute path, read from its copy in the scratch
    label = next((name for name, target in scratch.absolute.items() if where == target), None)
    if label is not None:
        return None if label in scratch.tagged or label not in scratch.files else label
    # the deck's own folder named by its absolute path is the copy, where the engine is confined
    for base in (folder, scratch.origin):
        if base is not None and (where == base or base in where.parents):
            label = str(where.relative_to(base))
            label = None if label == scratch.deck.name else label
            return None if label in scratch.tagged or label not in scratch.files else label
    return None


def _skipped_index(cmd: Executed, scratch: Scratch) -> int | None:
    """The index in the scratch's ``skipped`` of the command made a no-op that ``cmd`` is (a no-op
    label, or an output fix's stand-in echoed from its own line), None where it is none."""
    mark = _SKIPPED.fullmatch(cmd.text)
    return int(mark.group(1)) if mark else scratch.silenced.get((cmd.loc, cmd.text))


def deck_commands(commands: list, scratch: Scratch) -> list:
    """The commands of the deck's own that the engine executed: without the fix that stands for an
    output fix not run (a ``fix ID all viscous 0.0`` that keeps its ID for unfix), which is the
    audit's, so that it is never read as a fix that damps every atom.

    Parameters
    ----------
    commands : list of Executed
        What :func:`executed` read from the engine's echo.
    scratch : Scratch
        The copy it ran.

    Returns
    -------
    list of Executed

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), silenced={((None, 4), "fix 2 all viscous 0.0"): 0})
    >>> [c.text for c in deck_commands([Executed((None, 3), "fix 1 all nve/sphere"),
    ...                                 Executed((None, 4), "fix 2 all viscous 0.0")], s)]
    ['fix 1 all nve/sphere']
    """
    out = []
    for cmd in commands:
        if (cmd.loc, cmd.text) in scratch.silenced:
            continue
        mark = _SKIPPED.fullmatch(cmd.text)
        if mark and scratch.skipped[int(mark.group(1))][0] in ("balance", "processors"):
            # never run in the pass (balance may write a file; processors would stop the audit's one
            # process), yet balance makes LAMMPS' ghost atoms anew (reader._REGHOSTING) and the engine
            # stops on a processors after the box: read as the deck's own command
            cmd = replace(cmd, text=scratch.skipped[int(mark.group(1))][2])
        out.append(cmd)
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
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), skipped=[("shell", (None, 3), "shell touch f"),
    ...                                                       ("dump", (None, 4), "dump d all atom 1 d.out")])
    >>> skipped([Executed((None, 4), "label restitution_skipped_1")], s)
    {'dump': (None, 4)}
    """
    out = {}
    for cmd in commands:
        k = _skipped_index(cmd, scratch)
        if k is not None:
            command, loc, _ = scratch.skipped[k]
            out.setdefault(command, loc)
    return out


#: Commands that read a file the deck names (its word, the index of the file name among its words)
_READS = {"include": 1, "jump": 1, "read_data": 1, "molecule": 2, "read_dump": 1, "read_restart": 1}


def _split(text: str) -> list:
    """A command's words as the engine reads them (a quoted name with spaces one word, without its
    quotes: field round 30, SW-D), or split at whitespace where its quotes do not balance."""
    try:
        return words(text)
    except ScriptError:
        return [w.strip("\"'") for w in text.split()]


def _read_file(text: str) -> str | None:
    """The file a command reads, where it is one of those a skipped command could have written."""
    split = _split(text)
    if split and split[0] in _READS and len(split) > _READS[split[0]]:
        return split[_READS[split[0]]]
    if split[:1] == ["variable"] and len(split) > 3 and split[2] in ("file", "atomfile"):
        return split[3]
    if split[:1] == ["fix"] and "file" in split[4:-1]:           # a LIGGGHTS mesh
        return split[split.index("file", 4) + 1]
    return None


#: A variable drawn from the engine's random-number generator at each evaluation
_RANDOM_DEF = re.compile(r"variable\s+(\S+)\s+\S+.*\b(?:random|normal)\(")
#: Commands that evaluate a variable as the runs go (their output, a fix's or dump's values)
_DURING_RUNS = ("thermo_style", "thermo_modify", "fix", "dump", "compute", "fix_modify")


def random_drawn(commands: list, scratch: Scratch, runs_draw: bool = True) -> tuple | None:
    """The first command of the deck that reads a variable drawn from ``random()`` or ``normal()``
    after the engine run by hand has drawn from it where the audit's pass does not: a command the
    pass never runs that reads it (a print, a shell line), or a run while a command that reads it
    as the runs go stands (thermo output, a fix, a dump) or its ``every`` reads it (``runs_draw``:
    the runs were skipped, not made for real). Each evaluation
    draws, so the value read there is not the pass's (field round 21, r25: thermo output of v_r in
    a run, then an if on ${r}: LAMMPS took the other branch). ((file, line), text), or None.

    Parameters
    ----------
    commands : list of Executed
    scratch : Scratch

    Returns
    -------
    tuple or None

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), stages=[(None, 3, "run 10")],
    ...             lines={"variable r equal random(1,9,5)": (None, 1), "thermo_style custom step v_r": (None, 2),
    ...                    "run 10": (None, 3), "pair_coeff * * hooke ${r} 0": (None, 4)})
    >>> random_drawn([Executed((None, 2), "thermo_style custom step v_r"), Executed((None, 3), "run 10", 0),
    ...               Executed((None, 4), "pair_coeff * * hooke 7.2 0")], s)
    ((None, 4), 'pair_coeff * * hooke ${r} 0')
    """
    names = {m.group(1) for key in scratch.lines if (m := _RANDOM_DEF.match(key))}
    if not names:
        return None
    alt = "|".join(map(re.escape, sorted(names, key=len, reverse=True)))
    single = "|".join(re.escape(n) for n in names if len(n) == 1)
    reads = re.compile(rf"v_(?:{alt})\b|\$\{{(?:{alt})\}}" + (rf"|\$(?:{single})" if single else ""))
    at: dict = {}
    for key, loc in scratch.lines.items():
        at.setdefault(loc, []).append(key)
    # the generator is one, whatever the seed after its first use: a random() of a command's own
    # draws from it too (field round 21, r21: print "$(random(0,1,99))")
    draws = re.compile(rf"{reads.pattern}|\b(?:random|normal)\(")
    during = any(key.split()[0] in _DURING_RUNS and draws.search(key) for key in scratch.lines if key.split())
    drawn = False
    for cmd in commands:
        k = _skipped_index(cmd, scratch)
        if k is not None:
            drawn = drawn or bool(draws.search(scratch.skipped[k][2]))
            continue
        if cmd.stage is not None:
            drawn = drawn or runs_draw and (during or bool(draws.search(cmd.text)))
            continue
        read = [key for key in at.get(cmd.loc, ()) if reads.search(key) and not _RANDOM_DEF.match(key)]
        if drawn and read:
            return cmd.loc, read[0]
    return None


def written_then_read(commands: list, scratch: Scratch) -> tuple | None:
    """The first read of a file that a skipped command reached before it names (``shell cp a b``
    then ``include b``; ``print ... file b`` then ``include b``): the engine's pass never wrote it,
    so what it read there is not what the engine run by hand reads (a skipped command among those a
    run kept whole names in its every too); an include or jump of a file a ``shell mv`` (which runs,
    in the copy) named before: the engine reads it, but its commands are not mapped to the deck's
    lines; or a read under another name of the same file (:attr:`Scratch.aliases`) of one that a
    shell mv or rm, a write_restart or a write_data named before. ((file, line), text) of the
    writing, moving or removing command and of the read, and whether the read names the file
    otherwise, or None.

    Parameters
    ----------
    commands : list of Executed
    scratch : Scratch

    Returns
    -------
    tuple or None

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), skipped=[("shell", (None, 3), "shell cp p9.in p.in")])
    >>> written_then_read([Executed((None, 3), "label restitution_skipped_0"),
    ...                    Executed((None, 4), "include p.in")], s)
    (((None, 3), 'shell cp p9.in p.in'), ((None, 4), 'include p.in'), False)

    A quoted name with spaces is one name (the file "k  k.in", not "k"):

    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), skipped=[("print", (None, 3), 'print "x" file "k  k.in"')])
    >>> cmds = [Executed((None, 3), "label restitution_skipped_0"), Executed((None, 4), 'include "j  k"')]
    >>> written_then_read(cmds, s) is None, written_then_read(cmds[:1] + [Executed((None, 4), 'include "k  k.in"')], s)[1]
    (True, ((None, 4), 'include "k  k.in"'))
    """
    reached, moved, ran = [], [], []
    numeric: set = set()           # the variables whose value is a number where a skipped command runs
    for cmd in commands:
        k = _skipped_index(cmd, scratch)
        if k is not None:
            loc, text = scratch.skipped[k][1:]
            reached.append((loc, text, _written_words(text, numeric)))
            continue
        split = _split(cmd.text)
        if split[:1] == ["variable"] and len(split) > 2:
            (numeric.add if split[2] in _NUMERIC_STYLES else numeric.discard)(split[1])
        if cmd.stage is not None and "every" in split:
            # a run kept whole: the commands its every names never run in the pass (field round 37,
            # F16: run 1000 every 1000 "shell mv new.in pc.in", then include pc.in); a run made
            # as its parts runs them, echoed as the deck's own
            for quoted in split[split.index("every") + 2:]:
                first = quoted.split()[:1]
                if first and (first[0] in SKIPPED_COMMANDS or first[0] in _RAN_WRITERS):
                    reached.append((cmd.loc, quoted, _written_words(quoted, numeric)))
            continue
        if split[:1] == ["shell"] and split[1:2] in (["mv"], ["rm"]):
            moved.append((cmd.loc, cmd.text))
            continue
        if split[:1] and split[0] in _RAN_WRITERS:
            ran.append((cmd.loc, cmd.text))
            continue
        name = _read_file(cmd.text)
        if name is None or name == "SELF" or not (reached or moved or ran):
            continue
        base = os.path.basename(name)
        # the same file under another name (a link, its target, a hard link): the copy holds them
        # apart, so a write or a removal under one is unseen under the other (field round 37, F47)
        others = scratch.aliases.get(base, frozenset())
        if set("*%") & set(base):
            # a read by a pattern (read_restart l%.rst): the aliases of every name it may open
            # (field round 38, R26: lbase.rst and l0.rst, links to stale rbase.rst and r0.rst)
            others = others.union(*(names for name, names in scratch.aliases.items() if _may_name(base, name)))
        # a file shell mv put in place (it runs, in the copy) is read by the engine, but its lines
        # are not mapped to the deck's: only the files the copy found when it was made are (field
        # round 36, F09: shell mv new.in pc.in, include pc.in: its pair_coeff unseen, 0.4149
        # printed where LAMMPS ran kn 5000, 0.578975); a file read as data the engine reads itself
        script = split[:1] in (["include"], ["jump"])
        for loc, text, written, names in [
                *((loc, text, written, {base} | others) for loc, text, written in reached),
                *((loc, text, _split(text)[1:], {base} | others if script else others) for loc, text in moved),
                *((loc, text, _split(text)[1:], others) for loc, text in ran)]:
            for one in names:
                if any(_may_name(os.path.basename(word), one) for word in written):
                    return (loc, text), (cmd.loc, cmd.text), one != base
    return None


#: Variable styles whose value, substituted, is one number
_NUMERIC_STYLES = frozenset({"equal", "internal", "format", "timer"})
#: A word of a command line as the engine splits it, quotes kept (to tell a quoted argument)
_RAW_WORD = re.compile(r'"""[\s\S]*?"""|"[^"]*"|\'[^\']*\'|\S+')


def _written_words(text: str, numeric: set) -> list:
    """The words of a skipped command that may name a file it writes: for print and fix print, the
    value of a file or append keyword (field round 35, E77: ``print ${kk}`` then an include was
    refused as a write of any file); every word where a variable may bring such a keyword (an
    unquoted string holding a variable that is not a number, or a variable among the keywords);
    for a writer whose file has a fixed place (:data:`_FILE_WORD`), that word; every word of any
    other command.

    Examples
    --------
    >>> _written_words('print "k ${kk}" screen no file out.txt', set()), _written_words("print ${kk}", {"kk"})
    (['out.txt'], [])
    >>> _written_words("print ${s}", set()), _written_words("shell cp a.in b.in", set())
    (['${s}'], ['cp', 'a.in', 'b.in'])
    >>> _written_words("fix p all print 10 $(step) append log.txt", set())
    ['log.txt']

    A writer whose file has a fixed place: that word, a number's variable before it or not (field
    round 45, M15); a variable in it may name any file, and one before it that is not a number may
    move it:

    >>> _written_words("dump d all custom ${df} d.txt id x vx", {"df"}), _written_words("undump d", set())
    (['d.txt'], [])
    >>> _written_words("dump d all custom 100 ${f} id x", set()), _written_words("restart 1000 a.rst b.rst", set())
    (['${f}'], ['a.rst', 'b.rst'])
    >>> _written_words("dump d all ${s} 100 d.txt id x", set())
    ['d', 'all', '${s}', '100', 'd.txt', 'id', 'x']
    """
    split = _split(text)
    if split[:1] == ["print"]:
        at = 2
    elif split[:1] == ["fix"] and split[3:4] == ["print"]:
        at = 6
    elif split[:1] and split[0] in _FILE_WORD:
        # a writer whose file is the word at a fixed place: only that word names what it writes,
        # unless a variable before it that is not one number may shift it (field round 45, M15:
        # dump d all custom ${df} d.txt, then include k.in, was refused as a write of any file)
        first = _FILE_WORD[split[0]]
        if first is None:
            return []
        if any("$" in _unnumbered(w, numeric) for w in split[1:first]):
            return split[1:]
        return split[first:] if split[0] == "restart" else split[first:first + 1]
    else:
        return split[1:]
    raw = _RAW_WORD.findall(text)
    string = raw[at - 1] if len(raw) >= at else ""
    # a variable substituted unquoted may split into several words (an engine re-reads the line),
    # keywords among them, unless its value is one number
    if "$" in _unnumbered(string, numeric) and not string.startswith(("'", '"')) or any("$" in w for w in split[at:]):
        return split[1:]
    return [split[i + 1] for i in range(at, len(split) - 1) if split[i] in ("file", "append")]


#: The writers whose file is the word at a fixed place (LAMMPS' and LIGGGHTS' manuals): that word's
#: index in the command's words (``dump ID group style N file``, ``write_dump group style file``,
#: ``pair_write i j N style inner outer file``, ...); restart's every word from there (one root
#: or two files, its keywords); None where the command names no file it writes (dump_modify,
#: undump)
_FILE_WORD = {"dump": 5, "write_dump": 3, "write_restart": 1, "write_data": 1, "write_coeff": 1, "log": 1,
              "restart": 2, "pair_write": 7, "bond_write": 5, "angle_write": 3, "dihedral_write": 3,
              "dump_modify": None, "undump": None}


def _unnumbered(text: str, numeric: set) -> str:
    """``text`` without its variable references that are replaced by one number (:func:`_numeric_ref`)."""
    return _VARIABLE.sub(lambda m: "" if _numeric_ref(m.group(), numeric) else m.group(), text)


def _numeric_ref(ref: str, numeric: set) -> bool:
    """Whether a variable reference (``${x}``, ``$(...)``, ``$x``) is replaced by one number."""
    return ref.startswith("$(") or ref.strip("${}") in numeric


#: The writers the copy runs, into itself: a read of their file under its own name reads what they
#: wrote, one under another name of the same file does not (:attr:`Scratch.aliases`)
_RAN_WRITERS = frozenset({"write_restart", "write_data"})


def unmapped_script(commands: list, scratch: Scratch) -> tuple | None:
    """The first include or jump the engine ran of a file in the copy whose lines the copy did not
    map: one over MAX_TEXT_BYTES, a binary one (a NUL byte, in a confined copy: scratch_copy), or a
    link left as a link (to such a file): its commands run in
    the engine and come back without a tag (field round 37, F20: ``include ${f}`` of a 22 MB file,
    F21: a link to it; round 36, F19). ((file, line), text) of the command, or None.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     s = Scratch(Path(d), Path(d, "in.x"))
    ...     with open(Path(d, "big.in"), "wb") as big:
    ...         _ = big.truncate(MAX_TEXT_BYTES + 1)
    ...     unmapped_script([Executed((None, 2), "include big.in"), Executed((None, 3), "include in.x")], s)
    ((None, 2), 'include big.in')
    """
    for cmd in commands:
        if not cmd.text.startswith(("include", "jump")):
            continue
        split = _split(cmd.text)
        if len(split) < 2 or split[0] not in ("include", "jump") or split[1] == "SELF" or "$" in split[1]:
            continue
        path = scratch.deck.parent / split[1]
        try:
            if path.is_symlink() or path.is_file() and (path.stat().st_size > MAX_TEXT_BYTES or scratch.confined
                                                        and b"\0" in path.read_bytes()):
                return cmd.loc, cmd.text
        except OSError:
            continue
    return None


def _may_name(written: str, read: str) -> bool:
    """Whether a file name a skipped command writes may be the one read: the same, or the same with
    the step (or the process) in place of its ``*`` (``%``), which the engines put there (field
    round 36, M05: ``restart 500 r.*`` then ``read_restart r.1000``; a stale r.1000 in the deck's
    folder would have been read).

    Examples
    --------
    >>> _may_name("r.*", "r.1000"), _may_name("r.*", "r.*"), _may_name("d.%.*", "d.3.20"), _may_name("r.*", "s.1")
    (True, True, True, False)
    >>> _may_name("r%.*", "r%.1000"), _may_name("r%.*", "rbase.1000"), _may_name("${f}", "r.1"), _may_name("d.${i}.txt", "e.1")
    (True, True, True, False)
    """
    if written == read:
        return True
    if not set("*%$") & set(written):
        return False
    # a read may name the same pattern (read_restart r%.*, field round 37, R07) or a step of it; a
    # variable in a skipped command's name (never substituted: it never ran) may stand for anything
    # (R30: restart 1000 ${f}, f = r%.*)
    pattern = "".join(".*" if piece.startswith("$") else
                      "".join({"*": r"(?:\d+|\*)", "%": r"(?:\d+|base|%)"}.get(c, re.escape(c)) for c in piece)
                      for piece in _VARIABLE.split(written) if piece)
    return re.fullmatch(pattern, read) is not None


#: A variable's reference in a name: ${name}, $(formula), $x
_VARIABLE = re.compile(r"(\$\{[^}]*\}|\$\([^)]*\)|\$\w)")


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


#: Commands that change nothing a run's set-up checks or the audit reads: the script's control flow
#: (the commands an if or include runs are echoed, and judged, each on its own). A variable is one
#: of them only where no command names it as v_NAME (evaluated at a run's set-up, or per atom)
_QUIET = frozenset({"label", "jump", "if", "include", "next", "variable"})
#: Inserting fixes and the place of their random seed: a fix redefined with another seed alone
#: inserts the same sizes, and LAMMPS' set-up checks nothing of the seed
SEEDED = {"pour": 6, "deposit": 7}


def first_unchecked(commands: list, scratch: Scratch) -> int | None:
    """The place in ``commands`` of the first run whose marker skipped the engine's set-up check and
    its dump of the atoms (``snapshot`` False: a LAMMPS marker does both at its first run only)
    although a command since the last check may have changed what a run checks or sees; None
    where every such run followed only commands that change nothing of it (variables no command
    reads as v_NAME, labels, jumps, ifs, includes, and fixes defined again as they were at the
    check, an inserting fix's seed aside). Those runs then saw the atoms and the contact of the
    last check, which the engine had checked.

    Parameters
    ----------
    commands : list of Executed
    scratch : Scratch
        The copy the engine ran (every command of its files: which variables are read as v_NAME).

    Returns
    -------
    int or None

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"))
    >>> run, again = Executed((None, 3), "run 1", 0, True), Executed((None, 3), "run 1", 0, False)
    >>> first_unchecked([run, Executed((None, 4), "variable i equal 2"), again], s) is None
    True
    >>> first_unchecked([run, Executed((None, 4), "pair_coeff * * hooke 2 0"), again], s)
    2
    """
    text = " ".join(scratch.lines)
    read = None if re.search(r"\bv_\$", text) else set(re.findall(r"\bv_(\w+)", text))
    fixes: dict = {}
    at_check: dict = {}
    changed = False
    for n, cmd in enumerate(commands):
        if cmd.stage is not None:
            if cmd.snapshot is not False:
                changed, at_check = False, dict(fixes)
            elif changed:
                return n
            continue
        try:
            split = words(cmd.text)
        except ScriptError:
            changed = True
            continue
        if not split:
            continue
        if split[0] in ("variable", "next"):
            names = split[1:2] if split[0] == "variable" else split[1:]
            changed = changed or read is None or any(name in read for name in names)
        elif split[0] == "fix" and len(split) > 3:
            seed = SEEDED.get(split[3])
            fixes[split[1]] = split[:seed] + split[seed + 1:] if seed is not None else split
            changed = changed or at_check.get(split[1]) != fixes[split[1]]
        elif split[0] not in _QUIET:
            changed = True
    return None


_SKIPPED = re.compile(NOOP.format(r"(\d+)"))
_UNCHECKED = re.compile(DYNAMIC.format(r"(\d+)"))


def _marks(commands: list, pattern) -> list[int]:
    """The numbers of the no-op markers of one kind among the commands run, in order."""
    return [int(m.group(1)) for cmd in commands if (m := pattern.fullmatch(cmd.text))]


class HeldSizes(set):
    """The (radius, density) of a type's atoms at a run, as a set; ``once`` those exactly one atom
    has (no pair of two spheres of that size exists there).

    Examples
    --------
    >>> held = HeldSizes({(0.5, 1.0), (0.3, 1.0)})
    >>> held.once = frozenset({(0.3, 1.0)})
    >>> sorted(held), sorted(held.once)
    ([(0.3, 1.0), (0.5, 1.0)], [(0.3, 1.0)])
    """

    once: frozenset = frozenset()

    def __repr__(self) -> str:
        return repr(set(self))


class Snapshot(dict):
    """The atoms a run saw, {type: :class:`HeldSizes`}; ``by_id`` each atom's (type, radius) by its
    ID where the dump gives IDs (else None): a growth or a retype of one atom shows there where the
    sizes a type holds stay the same set (field round 30, G01: lv2 grown to the size another sphere
    of its type had, while a third kept the old one). Copies share ``by_id``: nothing changes it.

    Examples
    --------
    >>> import copy
    >>> snap = Snapshot({1: HeldSizes({(0.5, 1.0)})}, by_id={7: (1, 0.5)})
    >>> copy.deepcopy(snap).by_id is snap.by_id, snap
    (True, {1: {(0.5, 1.0)}})
    """

    def __init__(self, sizes: dict, by_id: dict | None = None, before: dict | None = None):
        super().__init__(sizes)
        self.by_id = by_id
        # each atom's (type, radius) by ID as the run's set-up found them, before its fixes acted
        # (LAMMPS' marker writes them: a fix adapt sizes the atoms after the lists are built)
        self.before = before

    def __deepcopy__(self, memo):
        return Snapshot({t: copy.deepcopy(v, memo) for t, v in self.items()}, self.by_id, self.before)


def snapshots(atoms: str) -> list[Snapshot]:
    """Each run's atoms, from the markers' dumps (columns id type radius mass, or type radius mass):
    {type: {(radius, density)}} (a :class:`HeldSizes`, whose ``once`` are the sizes one atom alone
    has), density = mass / (4/3 pi r^3) (a point particle's None), and each atom's type and radius
    by its ID (:class:`Snapshot`).

    Parameters
    ----------
    atoms : str

    Returns
    -------
    list of Snapshot

    Examples
    --------
    >>> snapshots("ITEM: TIMESTEP\\n0\\nITEM: NUMBER OF ATOMS\\n1\\nITEM: BOX BOUNDS pp pp pp\\n0 1\\n0 1\\n0 1\\n"
    ...           "ITEM: ATOMS id type radius mass\\n4 2 0.5 0.5235987755982988\\n")
    [{2: {(0.5, 1.0)}}]
    >>> sorted(_[0][2].once), _[0].by_id
    ([(0.5, 1.0)], {4: (2, 0.5)})
    """
    out, lines, k = [], atoms.split("\n"), 0
    before = None
    # a loop's runs write the same atoms again and again: a block equal to the last of its kind
    # shares its table (ten thousand runs of a tutorial's atoms would hold ten thousand copies)
    last: dict = {}

    def table(kind: str, rows: list) -> dict:
        if kind not in last or last[kind][0] != rows:
            last[kind] = (rows, {int(w[0]): (int(w[1]), float(w[2])) for w in (row.split()[:3] for row in rows)})
        return last[kind][1]

    while k < len(lines):
        if lines[k].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[k + 1])
            k += 2
            while not lines[k].startswith("ITEM: ATOMS"):
                k += 1
            rows = lines[k + 1:k + 1 + n]
            if lines[k].split()[2:] == ["id", "type", "radius"]:
                before = table("before", rows)     # the atoms before the set-up the next block shows
                k += 1 + n
                continue
            by_id = None
            if lines[k].split()[2:3] == ["id"]:
                by_id = table("set-up", rows)
                rows = [row.split(None, 1)[1] for row in rows]
            snap: dict = {}
            counts: dict = {}
            # atoms of one size print the same row: each distinct row read once, with how many
            # atoms print it (a tutorial's tens of thousands of atoms are a handful of rows)
            for row, many in Counter(rows).items():
                t, r, m = row.split()[:3]
                r, m = float(r), float(m)
                volume = 4.0 / 3.0 * math.pi * r ** 3
                # a radius below ~1e-108 has a volume that underflows to 0: no density (named)
                rho = m / volume if volume > 0 else None
                size = (r, None if rho is None else float(f"{rho:.12g}"))
                snap.setdefault(int(t), HeldSizes()).add(size)
                counts[(int(t), size)] = counts.get((int(t), size), 0) + many
            for t, sizes in snap.items():
                sizes.once = frozenset(size for size in sizes if counts[(t, size)] == 1)
            out.append(Snapshot(snap, by_id, before))
            before = None
            k += 1 + n
        else:
            k += 1
    return out


def engine_error(text: str, scratch: Scratch, status: int | None = None) -> tuple[str, str, str]:
    """(where, line, message) of an engine's ERROR: the deck line it names (its last input line).
    Where the engine wrote no ERROR (killed, or crashed), the message says so with its exit status:
    the last line of its screen may be cut off mid-word.

    Parameters
    ----------
    text : str
        The engine's error output.
    scratch : Scratch
    status : int, optional
        Its exit status (negative: the signal that ended it).

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> from pathlib import Path
    >>> s = Scratch(Path("/s"), Path("/s/deck/in.x"), lines={"run 1": (None, 7)})
    >>> engine_error("ERROR: All pair coeffs are not set (src/pair.cpp:1)\\nLast input line: run 1", s)
    ('line 7', 'run 1', 'All pair coeffs are not set')
    >>> engine_error("Last input line: run 1\\n  va", s, -9)[2]
    'it ended without an error message (killed by signal 9)'
    """
    m = re.search(r"ERROR(?: on proc \d+)?: (.*?)(?: \((?:\./)?src/[^)]*\))?$", text, re.M)
    ended = (f" (killed by signal {-status})" if status is not None and status < 0 else
             f" (exit status {status})" if status else "")
    message = m.group(1).strip() if m else f"it ended without an error message{ended}"
    last = re.search(r"Last (?:input line|command): (.*)$", text, re.M)
    line = normalised(last.group(1)) if last else ""
    tag = re.search(rf"{re.escape(scratch.tag)}(\d+)\s*$", last.group(1)) if last else None
    loc = scratch.tags[int(tag.group(1))] if tag else scratch.lines.get(line)
    where = "the deck" if loc is None else f"line {loc[1]}" if loc[0] is None else f"{loc[0]} line {loc[1]}"
    return where, line, message
