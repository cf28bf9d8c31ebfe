"""The untrusted deck, made safe for its engine to run: a scratch copy of its folder in which every
command that runs code, writes a file or reaches outside is turned into a no-op, and every run into
a stage marker (an ``include`` of a small file that runs it and then writes the atoms' state).

Line numbers are kept (a rewritten command stays on its first line, its continuation lines become
blank), so ``jump``/``label`` and the refusals' line numbers are the deck's own. A command whose
name comes from a variable cannot be checked before it runs: such a deck is refused.

Every command of the deck and of the files it names as written gets a comment that says where it
stands (``#restitution-NONCE@K``, K an index into :attr:`Scratch.tags`); the engines echo a line as
they read it, comment and all, so the audit tells each echoed command's file and line by its tag,
never by its text (two files, or a marker of the audit's own, may hold the same text). The
markers' lines are tagged as the audit's.
"""

from __future__ import annotations

import os
import re
import secrets
import shutil
import stat
from dataclasses import dataclass, field
from pathlib import Path

from ..dialect.state import DeckError, place
from ..deck_text import (TRIPLE, ScriptError, if_branches, logical_lines, segments as segments_of, strip_comment, words,
                         written_words)
from ..deck_text import words as words_of
from .runtime import IN_RUN_ONLY

__all__ = ["Scratch", "scratch_copy", "NOOP", "DYNAMIC", "SKIPPED_COMMANDS", "MAX_FOLDER_BYTES", "normalised",
           "AUDIT", "split_every", "MAX_PARTS", "MAX_TEXT_BYTES"]

#: The no-op the k-th skipped command becomes (both engines have label; nothing jumps to it): its
#: echo tells that the deck reached it
NOOP = "label restitution_skipped_{}"
#: The no-op the k-th command whose name comes from a variable becomes: a deck that reaches it is refused
DYNAMIC = "label restitution_unchecked_{}"
#: Commands never executed: they run code, write files, change what the engine echoes, or end the
#: skip-run mode. None changes a contact.
SKIPPED_COMMANDS = frozenset({
    "shell", "python", "plugin", "pair_write", "bond_write", "angle_write", "dihedral_write", "write_data", "write_restart", "write_dump", "write_coeff", "dump",
    "dump_modify", "undump", "restart", "log", "print", "info", "echo", "timer", "group2ndx",
    # LIGGGHTS' log of the thermo output: its folder may not be in the copy (field round 47a, M04:
    # thermo_log ../DEM/post/thermo.txt, "Cannot open thermo log file" in the audit's pass only)
    "thermo_log",
    "balance", "rerun", "message", "server", "mdi", "kim", "net", "geturl", "fitpod",
    # these write a file of their own (a VMD script of a region, a matrix of second or third
    # derivatives of the energy)
    "region2vmd", "dynamical_matrix", "third_order",
    # the audit's engine runs on one process, which a layout for several stops ("Specified
    # processors != physical processors"); how the box is split has no part in a contact
    "processors"})
#: shell's subcommands LAMMPS and LIGGGHTS do themselves (a directory, a file moved or removed, an
#: environment variable): no program runs; every other runs one through system()
SHELL_BUILTINS = frozenset({"cd", "mkdir", "mv", "rm", "rmdir", "putenv"})
#: Fix styles never executed (they write files or print): kept as a fix of the same ID that does
#: nothing, so unfix and fix_modify still find it
#: (not fix halt: it reads state and ends a run, its message on the screen, no file; LAMMPS 22 Jul 2025
#: fix halt: attributes bondmax, tlimit, diskfree (statvfs of a path), v_name; keywords error,
#: message, path: where the runs are made for real, the run it ends is the deck's)
_SKIPPED_FIX_PREFIXES = ("ave/", "print", "ttm", "tmd", "reaxff/", "qeq/reaxff", "python",
                         "vector", "external", "mdi", "pafi", "plumed", "colvars", "imd",
                         "couple/", "ave/euler", "dump", "phonon", "saed/vtk")
#: Of those, the ones that push atoms (a drag, a target, code or a program giving forces): their
#: note says so (field round 20, z40: fix ttm's drag was said to have no part in a contact)
PUSHING_FIX_PREFIXES = ("ttm", "tmd", "python", "external", "mdi", "pafi", "plumed", "colvars", "imd", "couple/")
#: A partition spec LAMMPS and LIGGGHTS accept where they run as one partition (the audit's engine
#: does): it holds partition 1; any other stops the engine ("Invalid range string", measured)
_FIRST_PARTITION = re.compile(r"1|\*|1\*|\*1|1\*1")
#: Fixes that average or store values and write nothing but the file their ``file`` keyword names:
#: run without it, so that what a variable reads of them after a run is the engine's
_AVERAGING_FIXES = frozenset({"ave/time", "ave/histo", "ave/histo/weight", "ave/correlate", "ave/correlate/long",
                              "ave/chunk", "ave/atom", "vector"})
#: What the print that stands for a set met by no atom begins with (where the engine guards set)
UNSET = "restitution_unset"
#: The commands guarded so, each with what LAMMPS says where it meets no atom
GUARDED = {"set": "Set command on system without atoms", "velocity": "Velocity command with no atoms existing"}
#: The tag of the audit's own lines (its markers'): never the deck's
AUDIT = "audit"
#: Runs: each a stage, its marker the include that runs it and then writes the atoms' state
RUN_COMMANDS = ("run", "minimize")
#: The characters LAMMPS 22 Jul 2025 replaces in its input by ASCII ones (measured, each alone in a
#: line: typographic quotes, the Unicode spaces, the word joiner and byte-order mark, the minus sign)
_ASCII = str.maketrans({**{c: " " for c in "\u00a0\u202f\u2060\ufeff"},
                        **{chr(c): " " for c in range(0x2000, 0x200c)},
                        "\u2018": "'", "\u2019": "'", "\u201c": '"', "\u201d": '"', "\u2212": "-"})
#: The most parts a ``run N every M`` with commands between them is written out in, each a run of the
#: copy's own (:func:`split_every`); one in more parts stays as written
MAX_PARTS = 1000
#: What a run's every may run that keeps the run as written: a run, quit, clear or jump between
#: the parts, or a file opened there, is the deck's control flow, which the copy does not rewrite
#: (an if is judged by its branches, :func:`_flow`; a label, which LAMMPS passes over where it
#: runs it, is none; ``next`` only steps a variable and arms the skip of the deck's next jump,
#: which LAMMPS keeps across includes, so the copy's parts behave alike: field round 35, E71)
_UNSPLIT = frozenset({"run", "minimize", "quit", "include", "jump", "clear"})
#: How deep includes a run's every names are read for control flow (:func:`_flow`)
_INCLUDE_DEPTH = 4
def _flow(command: str, opened=None, depth: int = 0, labels: frozenset | None = None) -> bool:
    """Whether a command a run's every names is the deck's control flow (:data:`_UNSPLIT`), or an
    if any branch of which is, or an include of a file that holds such a command; a command that
    does not parse counts as such. ``opened`` gives the text of a file an include names (None where
    it does not read it: the include then counts as flow); a file named by a variable counts so.
    Inside an included file, ``jump SELF L`` to a label ``L`` of that file (``labels``) stays in
    the file, which the copy includes as the deck does, so it is none (field round 35, E80); in
    the every's own commands SELF would name the copy's file, not the deck's.

    Examples
    --------
    >>> _flow("if 1 then 'pair_coeff 1 2 hooke 5000 0'"), _flow('if "${a} > 1" then "print x" else quit')
    (False, True)
    >>> _flow("label x"), _flow('include "k.in"'), _flow(""), _flow("next a"), _flow("jump SELF x")
    (False, True, True, False, True)
    >>> files = {"k.in": "pair_coeff 1 2 hooke 5000 0", "r.in": "run 10", "n.in": "include r.in",
    ...          "j.in": "jump SELF b\\nprint a\\nlabel b", "o.in": "jump SELF c\\nlabel b", "f.in": "jump in.x b"}
    >>> _flow("include k.in", files.get), _flow("include n.in", files.get), _flow("include ${f}", files.get)
    (False, True, True)
    >>> _flow("include j.in", files.get), _flow("include o.in", files.get), _flow("include f.in", files.get)
    (False, True, True)
    """
    try:
        parts = words(command)
    except ScriptError:
        return True
    if not parts:
        return True
    if parts[0] == "include" and opened is not None and len(parts) == 2 and "$" not in parts[1] \
            and depth < _INCLUDE_DEPTH:
        text = opened(parts[1])
        if text is None:
            return True
        lines = [line for _, line in logical_lines(text)]
        own = frozenset(line.split()[1] for line in lines if line.split()[:1] == ["label"] and len(line.split()) > 1)
        return any(_flow(line, opened, depth + 1, own) for line in lines)
    if parts[0] == "jump" and labels is not None and len(parts) == 3 and parts[1] == "SELF" and parts[2] in labels:
        return False
    if parts[0] != "if":
        return parts[0] in _UNSPLIT
    branches = if_branches(parts)
    return branches is None or any(_flow(branch, opened, depth, labels) for branch in branches)


def _in_run(command: str) -> bool:
    """Whether a command a run's every names reads a value that differs inside the run from after a
    run of the copy (:data:`restitution.dem.deck.runtime.IN_RUN_ONLY`: a function of the run's own
    start and end, field round 22, t02's ramp(2000,8000) read 2000 where LAMMPS reads 8000; a
    compute's or fix's value, current inside the run). A value substituted from the step, the time
    or a variable is not among them: the commands run after each part, where the copy's step and
    time are the deck's in a clocked pass or in runs made for real, and the pass reads them as run
    dependent, as after any run (round 27, E64); a variable that reads such a value is found after
    the pass (runtime.read_in_run). A command the copy never runs (print, dump, ...) reads none."""
    first = command.split()[0]
    if first in SKIPPED_COMMANDS:
        return False
    return bool(IN_RUN_ONLY.search(command))
#: The label that opens stage k's marker where it stands inline in an if (its echo marks the stage)
STAGE_LABEL = "restitution_stage_"
#: A deck's folder copied whole; a larger one is refused (with the files above it that it names)
MAX_FOLDER_BYTES = 200 * 2 ** 20
#: How many folders above the deck's its files may reach by ``..`` (a CFDEM case's ``../DEM/...``):
#: what they name there is copied beside the copy, at the same place; further is refused
MAX_UP = 3
#: The largest file the copy reads whole: a script the deck runs that is larger is refused
MAX_TEXT_BYTES = 20 * 2 ** 20


@dataclass
class Scratch:
    """The scratch copy of a deck: ``deck`` the copied input script; ``skipped`` the commands made
    no-ops, [(command, (file, line), its text)] (the text names the files it would have written,
    which a later read may need), the k-th echoed as ``NOOP.format(k)`` where reached;
    ``dynamic`` the commands whose name comes from a variable, [((file, line), text)], made
    ``DYNAMIC.format(k)``; ``stages`` the run markers' (file, line, text),
    ``confined`` whether the engine will see nothing outside the scratch directory (else an
    include or jump of a file named by a variable is made ``DYNAMIC`` too);
    indexed by the number in their file name; ``lines`` the normalised text of every command
    of the copied files (and of each command quoted in an ``if``) -> (file, line) of its first;
    ``tag`` the comment that marks a line's place (``tag + K``, K an index into ``tags``, the
    (file, line) of each tagged command, or ``tag + AUDIT``); ``files`` each copied file's own
    map of ``lines`` (a file none names as written is read by its text, once an include or jump
    of it ran); ``tagged`` the files whose commands carry their tag; ``quoted`` the commands an
    ``if`` or a run's ``every`` runs, by the (file, line) of that command (echoed without a tag);
    ``origin`` the deck's own folder, which the confined engine sees as the copy; ``restarts`` the
    (file, line, text) of each ``read_restart`` made a marker (``include`` of ``restart_k``: the read,
    then what the engine holds, :data:`restitution.dem.dialect.child.RESTART_INFO`), where the engine's marker has a ``restart``
    (LAMMPS): a ``write_restart`` then runs, into the copy; ``mirrored`` the paths above the deck's
    folder that its files name (``../DEM/data.txt``, normalised), copied to the same place relative
    to the copy (:func:`scratch_copy`); ``silenced`` the output fixes made a fix that does nothing,
    {((file, line), its text): its index in ``skipped``}; ``redirected`` the files a ``write_restart``
    or ``write_data`` names outside the copy (an absolute path, a climb by ..), each -> the file in
    the scratch it writes instead, which a later read of that name reads; ``absolute`` the files the deck names by an absolute path, each -> its
    copy in the scratch, which the copy's commands name instead; ``left_out`` the names in the deck's
    folder not copied (a pipe, a device, a link to one: :func:`_not_copied`); ``after`` what stage
    k's marker file holds after its marker, where its run is the first part of a run in parts
    (:func:`split_every`): the commands between the parts and the markers of the later ones;
    ``parts`` that run's text as written and its number of parts, by k; ``aliases`` each name in
    the deck's folder that is one file with others there (a link, its target, hard links) -> the
    names of the others: a write under one changes what a read under another reads by hand, where
    the copy holds them apart (:func:`_materialise_links`); ``cd_folders`` the folders in the deck's
    folder that its ``shell cd`` commands name as written (normalised), from which a name climbing by
    .. may land in the copy (:func:`_outside`); ``coupled`` whether the last ``fix couple/cfd``
    met couples in memory, so that it and its sub-fixes run as written."""
    root: Path
    deck: Path
    skipped: list = field(default_factory=list)
    dynamic: list = field(default_factory=list)
    stages: list = field(default_factory=list)
    lines: dict = field(default_factory=dict)
    confined: bool = True
    tag: str = "#restitution@"
    tags: list = field(default_factory=list)
    files: dict = field(default_factory=dict)
    tagged: set = field(default_factory=set)
    quoted: dict = field(default_factory=dict)
    origin: Path | None = None
    restarts: list = field(default_factory=list)
    mirrored: set = field(default_factory=set)
    cd_folders: set = field(default_factory=set)
    silenced: dict = field(default_factory=dict)
    redirected: dict = field(default_factory=dict)
    absolute: dict = field(default_factory=dict)
    left_out: set = field(default_factory=set)
    after: dict = field(default_factory=dict)
    parts: dict = field(default_factory=dict)
    aliases: dict = field(default_factory=dict)
    granular: bool = False
    coupled: bool = False


def normalised(text: str) -> str:
    """A command as the audit compares it with an engine's echo: comment and continuation marks
    removed, whitespace collapsed outside quotes. A quoted text is kept as written: the engines
    take it so, quotes removed, and echo it so (LAMMPS 22 Jul 2025 and LIGGGHTS 3.8 measured:
    ``include "k  k.in"`` opens the file of two spaces, not "k k.in"; a tab in a name likewise).

    Parameters
    ----------
    text : str

    Returns
    -------
    str

    Examples
    --------
    >>> normalised("pair_coeff  * * hooke 1 0   # soft")
    'pair_coeff * * hooke 1 0'
    >>> normalised('  include   "k  k.in"  # two spaces')
    'include "k  k.in"'
    >>> normalised('if "1 > 0"  then  \\'include "a\\tb.in"\\'')
    'if "1 > 0" then \\'include "a\\tb.in"\\''
    """
    text = strip_comment(text)
    if '"' not in text and "'" not in text:
        return " ".join(text.split())
    out = []
    for piece, quote in segments_of(text):
        closed = quote and piece.endswith(quote) and len(piece) >= 2 * len(quote)
        # an unclosed quote (the engine stops on it) is collapsed as before: no name is read from it
        out.append(piece if closed else _BLANKS.sub(" ", piece))
    return "".join(out).strip()


#: A run of whitespace, as str.split() splits at it
_BLANKS = re.compile(r"\s+")


def _not_copied(root: Path) -> tuple:
    """The ``ignore`` of the deck folder's copy, and the set of names it has left out (filled as the
    copy goes): the scratch directory ``root`` itself, where it lies in that folder (a deck saved in
    the temporary directory: the copy copied itself until "File name too long", field round 14,
    x10), what is no file, folder or link (a named pipe, whose read would wait, a socket, a device:
    x11), and a link to such a thing (not counted as left out: the scratch itself)."""
    held = root.resolve()

    def kept(mode: int) -> bool:
        return stat.S_ISREG(mode) or stat.S_ISDIR(mode)

    def ignore(folder, names) -> set:
        out = set()
        for name in names:
            p = Path(folder, name)
            try:
                mode = p.lstat().st_mode
            except OSError:
                out.add(name)
                continue
            try:
                resolved = p.resolve()
            except (OSError, RuntimeError):
                # a loop of links (a -> b -> a; x -> x): copied as links, the engine stops on them
                # where it opens one, as by hand (field round 38, A20: a traceback)
                resolved = None
            if resolved == held:
                out.add(name)
            elif stat.S_ISLNK(mode):
                # a link is copied as a link, which the engine follows: one to a device or a pipe
                # (an include of a link to /dev/zero, read without end: round 15, x05) is left out
                try:
                    if not kept(p.stat().st_mode):
                        out.add(name)
                except OSError:
                    pass                 # a dangling link: copied, the engine finds nothing there
            elif not kept(mode):
                out.add(name)
        left.update(name for name in out if Path(folder, name).resolve() != held)
        return out
    left: set = set()
    return ignore, left


def _materialise_links(copy: Path, source: Path) -> dict:
    """Each link in the copy to a regular file of at most MAX_TEXT_BYTES made a file holding what
    it points to, read where the deck's folder ``source`` (of which ``copy`` is the copy) has the
    link, never in the scratch (a relative link leaving the folder would name the scratch's own
    files there), so that a script read through a link is mapped and made safe as any other
    (field round 36, F14 F17: ``include link.in``, a link to a file of the folder, ran its
    pair_coeff unseen, and F15, a link to a file outside the folder, which the confined engine
    could not open). A link to a folder stays a link; one to anything else was left out
    (:func:`_not_copied`) or is too big to read whole. Returns the names that are one file with
    others (:attr:`Scratch.aliases`): each link with its target, hard links with each other; a
    write or a removal under one name is then seen under the others by hand only (field round 37,
    F47: write_restart a.rst, read_restart link.rst, read the old a.rst frozen in the copy)."""
    same: dict = {}
    for base, _, names in os.walk(copy):
        for name in names:
            link = Path(base, name)
            original = source / link.relative_to(copy)
            try:
                info = original.stat()
            except OSError:
                info = None
            if not link.is_symlink():
                if info is not None and info.st_nlink > 1:
                    same.setdefault((info.st_dev, info.st_ino), set()).add(name)
                continue
            try:
                target = original.resolve(strict=True)
                info = target.stat()
            except (OSError, RuntimeError):
                continue                 # dangling or looping: the engine finds nothing there either
            same.setdefault((info.st_dev, info.st_ino), set()).update({name, target.name})
            if stat.S_ISREG(info.st_mode) and info.st_size <= MAX_TEXT_BYTES:
                data = target.read_bytes()
                link.unlink()
                link.write_bytes(data)
    return {name: frozenset(group - {name}) for group in same.values() if len(group) > 1 for name in group}


def scratch_copy(deck: str | os.PathLike, where: str | os.PathLike, marker, confined: bool = True) -> Scratch:
    """Copy the deck's folder into ``where``/deck and make the copy safe to run.

    Parameters
    ----------
    deck : path
        The input script.
    where : path
        An empty scratch directory.
    marker : callable
        ``marker(k, run_text) -> str``: the text of stage k's marker file (the run, then what
        records the atoms); it is written to ``where``/stage_k. A ``quit`` gets one too,
        ``marker(None, quit_text)``, written to ``where``/quit_n: the engine ends the process
        there, so what it records where the deck ends comes before the quit. Where it has an
        attribute ``restart`` (``restart(read_text) -> str``: the read, then what records the
        engine's state), each ``read_restart`` gets one, written to ``where``/restart_k, and a
        ``write_restart`` whose file stays in the copy runs (else both stay as they are: the
        write never runs).
    confined : bool
        Whether the engine will run where it sees nothing outside ``where``
        (:mod:`restitution.dem.dialect.sandbox`); if not, a file the deck names by a variable
        could lie outside the copied folder, and its include or jump is never run.

    Returns
    -------
    Scratch

    Raises
    ------
    DeckError
        Where the deck's folder, with the files above it that the deck names, holds more than
        MAX_FOLDER_BYTES (the folder is copied whole), or the deck names a file more than MAX_UP
        folders above its own.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = pathlib.Path(d, "in.x"); _ = p.write_text("shell touch f\\nrun 10\\n")
    ...     with tempfile.TemporaryDirectory() as w:
    ...         s = scratch_copy(p, w, lambda k, run: run + "\\n")
    ...         s.deck.read_text().splitlines()[0].replace(s.tag, "#TAG@"), s.skipped
    ('label restitution_skipped_0 #TAG@0', [('shell', (None, 1), 'shell touch f')])
    """
    src = Path(deck).resolve()
    root = Path(where)
    ignore, left_out = _not_copied(root)
    total = _bytes_copied(src.parent, ignore, MAX_FOLDER_BYTES)
    if total > MAX_FOLDER_BYTES:
        raise DeckError("deck", str(src.parent), f"its folder holds more than {MAX_FOLDER_BYTES >> 20} MB, copied "
                                                 "whole to run the deck safely: put the deck and the files it "
                                                 "reads in a folder of their own")
    above, depth = _above(src, total, ignore)
    # a deck that names files above its folder: the copy as deep in the scratch as they reach, and
    # each file named copied at its place relative to it (never the folders' other files)
    copy = root.joinpath("deck", *src.parent.parts[len(src.parent.parts) - depth:])
    try:
        shutil.copytree(src.parent, copy, symlinks=True, ignore=ignore)
        for name in above:
            target = Path(os.path.normpath(copy / name))
            target.parent.mkdir(parents=True, exist_ok=True)
            source = Path(os.path.normpath(src.parent / name))
            if source.is_dir():
                # (the folder above holds the deck's, copied already: a link copied there again
                # stopped the copy, "File exists", field round 38, A18: shell cd .. with a link)
                def again(folder, names, source=source, target=target):
                    there = target / os.path.relpath(folder, source)
                    return ignore(folder, names) | {name for name in names if (there / name).is_symlink()}
                shutil.copytree(source, target, symlinks=True, dirs_exist_ok=True, ignore=again)
            else:
                shutil.copyfile(source, target)
    except (shutil.Error, OSError) as why:
        # a file removed or made unreadable while the folder is copied (field round 26, P02: another
        # process emptied the folder above the deck's, which a shell cd .. has the audit copy)
        first = why.args[0][0] if isinstance(why, shutil.Error) and why.args and why.args[0] else why
        raise DeckError("deck", str(src.parent), "its folder (with the files above it that the deck names) "
                                                 f"changed or could not be read while the audit copied it "
                                                 f"({' '.join(str(first).split())[:200]}); not audited: run "
                                                 "the audit again once nothing writes there") from None
    aliases = _materialise_links(copy, src.parent)
    # a file named by an absolute path (a cluster's /home/... parameter file): copied into the
    # scratch, where the copy's commands read it, made safe as the folder's files are
    absolute = {}
    for name in _absolute(src, total):
        target = root.joinpath("absolute", *Path(name).parts[1:])
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(name, target)
        absolute[name] = target
    # a nonce: a deck cannot write a tag that passes for another line's
    scratch = Scratch(root, copy / src.name, confined=confined, tag=f"#restitution-{secrets.token_hex(4)}@",
                      origin=src.parent, mirrored=set(above), absolute=absolute, left_out=set(left_out),
                      granular=_granular_only(src), aliases=aliases, cd_folders=_cd_folders(src))
    # the deck first: a command written alike in several files is located in the deck
    files = [scratch.deck] + [Path(base, name) for base, _, names in os.walk(root / "deck") for name in sorted(names)
                              if Path(base, name) != scratch.deck] + sorted(absolute.values())
    labels = {target: name for name, target in absolute.items()}
    # the lines of a file the deck reads as commands are the engine's commands when echoed; the
    # text of any other file (an old log, say) is not: only the deck and the files it names by
    # include or jump (every file where such a name comes from a variable) are mapped
    named = _named_files(scratch.deck)
    literal = _named_files(scratch.deck, literal=True)
    for p in files:
        if p.is_symlink():
            continue
        mapped = named is None or p == scratch.deck or p.name in named
        if not mapped and scratch.confined:
            # no include or jump names it (each name literal): the engine reads it as data (a
            # molecule template, a mesh, a table), never as commands, so it is kept as it is: a
            # template titled "run 7 template" was made a run's marker and refused as one (field
            # round 46, Z04; Z09: a phantom stage)
            continue
        if p.stat().st_size > MAX_TEXT_BYTES:
            # not mapped: an include or jump the engine runs of it is refused after the pass
            # (stream.unmapped_script; field round 36, F19: a 22 MB include, its pair_coeff unseen)
            continue
        try:
            # bytes that are not UTF-8 (a Latin-1 comment from another editor) kept as they are:
            # the engines read bytes, and a file passed over here would run unmade safe
            raw = p.read_bytes()
        except OSError:
            continue
        if b"\0" in raw and scratch.confined:
            # a binary file (a mesh in binary STL, ...) is the engine's to read byte for byte: a
            # line of its bytes made safe shortened it (field round 46, Y11: a binary STL floor,
            # LIGGGHTS 0.699141, refused as "Corrupt STL file"). Not mapped, as a large file: an
            # include or jump the engine runs of it is refused after the pass, the view confining
            # what its lines may do (stream.unmapped_script)
            continue
        label = None if p == scratch.deck else labels.get(p) or os.path.relpath(p, copy)
        if mapped and (cr := re.search(rb"\r(?!\n)", raw)) is not None:
            # the engines end a line at a line feed only, where Python's text reading ends one at a
            # lone carriage return too (field round 22, y01: "# note<CR>pair_coeff ..." is one comment
            # line to LAMMPS, two lines to a reader of text): refused, as a line the two read apart
            raise DeckError(place((label, raw.count(b"\n", 0, cr.start()) + 1)), None,
                            "a carriage return not followed by a line feed: the engine reads it as part of the line "
                            "(a space, or inside a comment), not as a line end; not audited (save the file with "
                            "LF or CRLF line ends)")
        # CRLF read as LF, as Python's text reading did before (the engines take CR as a space)
        original = raw.decode("utf-8", errors="surrogateescape").replace("\r\n", "\n")
        # LAMMPS reads typographic quotes and spaces in its input as their ASCII equivalents (it
        # warns and goes on): the copy is made of the text it reads (field round 21, a05: an if in
        # typographic quotes ran its branch in LAMMPS, unseen by the audit)
        text = original.translate(_ASCII) if mapped and getattr(marker, "ascii", False) else original
        # a file named as written is a script: its lines get their tags; any other (a data file,
        # or a script named by a variable) is left as it is, its lines known by their text
        if p == scratch.deck or p.name in literal:
            scratch.tagged.add(label)
        lines = dict(scratch.lines)
        new = _rewritten(text, label, scratch, marker)
        if not mapped:
            scratch.lines = lines
            scratch.files.pop(label, None)
        if new != original:
            p.write_text(new, encoding="utf-8", errors="surrogateescape")
    return scratch


#: A word that names a path above the deck's folder (``../x``, ``a/../../x``)
_UP = re.compile(r"(?:^|/)\.\.(?:/|$)")


def _bytes_copied(top: Path, ignore, limit: int) -> int:
    """The bytes of the regular files under ``top`` (or of the file ``top``) that the copy takes: not
    links, not what ``ignore`` leaves out; counted until they pass ``limit``. A file or folder that
    goes while they are counted counts nothing (a folder above the deck's, ``shell cd ..``, may be
    the temporary directory, whose entries come and go: field round 38, A19 run from there)."""
    if not top.is_dir():
        try:
            return top.stat().st_size
        except OSError:
            return 0
    total = 0
    for base, folders, names in os.walk(top):
        skipped = ignore(base, folders + names)
        folders[:] = [f for f in folders if f not in skipped]
        for name in names:
            p = Path(base, name)
            try:
                if name not in skipped and not p.is_symlink():
                    total += p.stat().st_size
            except OSError:
                continue
        if total > limit:
            break
    return total


def _above(deck: Path, total: int, ignore) -> tuple[list, int]:
    """The paths above the deck's folder that the deck and the files it names (include, jump, and
    those named above it) name by ``..`` as written, normalised (``../DEM/data.txt``), each one that
    exists; and how many folders up the furthest reaches. ``total``: the bytes of the folder;
    ``ignore``: what the copy leaves out (:func:`_not_copied`)."""
    folder, found, todo = deck.parent, set(), [deck]
    for path, n, line, word in _words_named(deck, todo):
        if "$" in word or not _UP.search(word) or os.path.isabs(word):
            continue
        name = os.path.normpath(word)
        up = len(Path(name).parts) - len(Path(name.lstrip("./")).parts) if name.startswith("..") else 0
        source = Path(os.path.normpath(folder / name))
        if not up or not os.path.lexists(source):
            if up:
                continue        # nothing there: the engine says so where it is read
            todo.append(source)  # a file in the folder named by a path through ..
            continue
        if up > MAX_UP or up >= len(folder.parts):
            raise DeckError(f"line {n}" if path == deck else f"{path.name} line {n}", line.strip(),
                            f"it names {word}, {up} folders above the deck's: the audit copies what a deck "
                            f"names up to {MAX_UP} folders above its own (the deck runs in a copy made "
                            "safe); move the case's files nearer")
        if source.is_symlink():
            continue            # as in the folder's copy, a link is not followed
        found.add(name)
        todo.append(source)
        total += _bytes_copied(source, ignore, MAX_FOLDER_BYTES - total)
        if total > MAX_FOLDER_BYTES:
            raise DeckError(f"line {n}" if path == deck else f"{path.name} line {n}", line.strip(),
                            f"the deck's folder and the files above it that the deck names hold more than "
                            f"{MAX_FOLDER_BYTES >> 20} MB, copied to run the deck safely: not audited")
    depth = max((len(Path(n).parts) - len(Path(n.lstrip("./")).parts) for n in found), default=0)
    return sorted(found), depth


def _absolute(deck: Path, total: int) -> list:
    """The files the deck and the scripts it names (include, jump; those named by an absolute path
    too) name by an absolute path as written, each one that is a file; ``total``: the bytes copied
    so far, which these may not take above MAX_FOLDER_BYTES."""
    found, todo = [], [deck]
    for path, n, line, word in _words_named(deck, todo):
        if "$" in word or not os.path.isabs(word) or word in found or not os.path.isfile(word) \
                or Path(word).resolve().is_relative_to(deck.parent):
            continue        # (the deck's own folder: the confined engine sees its copy there)
        total += os.path.getsize(word)
        if total > MAX_FOLDER_BYTES:
            raise DeckError(f"line {n}" if path == deck else f"{path.name} line {n}", line.strip(),
                            f"the deck's folder and the files it names hold more than "
                            f"{MAX_FOLDER_BYTES >> 20} MB, copied to run the deck safely: not audited")
        found.append(word)
        todo.append(Path(word))
    return found


def _words_named(deck: Path, todo: list):
    """(file, line number, line, word without quotes) of every word of the scripts in ``todo``, of
    the scripts each names by include or jump as written (a name by .. or an absolute path is a
    word, which the caller follows or not) and of what the caller appends to ``todo`` as it goes;
    each file read once, one larger than MAX_TEXT_BYTES or unreadable passed over."""
    seen = set()
    while todo:
        path = todo.pop()
        if path in seen or not _text_file(path):
            continue
        seen.add(path)
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        for n, line in enumerate(text.splitlines(), 1):
            for word in _all_words(normalised(line)):
                yield path, n, line, word
        todo += [deck.parent / name for name in _named_files(path) or () if not _UP.search(name)]


def _cd_folders(deck: Path) -> set:
    """The folders inside the deck's that ``shell cd`` commands of the deck and the scripts it names
    name as written (normalised; none by a variable, an absolute path or a climb out)."""
    found, read = set(), set()
    for path, n, line, _ in _words_named(deck, [deck]):
        if (path, n) in read:
            continue             # a line is named once for each of its words
        read.add((path, n))
        said = _all_words(normalised(line))
        if said[:2] == ["shell", "cd"] and len(said) > 2 and "$" not in said[2] and not os.path.isabs(said[2]):
            name = os.path.normpath(said[2])
            if name != ".." and not name.startswith("../"):
                found.add(name)
    return found


def _all_words(text: str) -> list:
    """The words of a command as the engine takes them, a quoted name one word, spaces and tabs
    kept (``"/data/k  v.txt"``), and the words of each quoted command in it (an if's), alike;
    where a quote is not closed (the engine stops there), the text split at whitespace."""
    try:
        found = words_of(text)
    except ScriptError:
        return [word.strip("\"'") for word in text.split()]
    return found + [inner for word in found if word != text and len(word.split()) > 1
                    for inner in _all_words(word)]


def _path_word(path) -> str:
    """A path as one word of a command: quoted where it holds whitespace."""
    text = str(path)
    if not any(c.isspace() for c in text):
        return text
    return f"'{text}'" if '"' in text else f'"{text}"'


def _text_file(path: Path) -> bool:
    """Whether ``path`` (a link followed) is a regular file of at most MAX_TEXT_BYTES, which the
    scan of named files may read whole: not a device, a pipe (whose read would wait) or a link to
    one, nor a huge or sparse file (field round 15, x05-x07: an include of a link to /dev/zero or to
    a 3 GB sparse file ran out of memory, one of a named pipe hung)."""
    try:
        info = path.stat()
    except OSError:
        return False
    return stat.S_ISREG(info.st_mode) and info.st_size <= MAX_TEXT_BYTES


def scripts_named(deck: Path, literal: bool = False) -> list | None:
    """The files a deck's include and jump lines name, and those the files they name name in
    turn, each once (the engines resolve a name from the deck's folder, where they run).

    Parameters
    ----------
    deck : Path
        The input script.
    literal : bool
        Pass over a name that comes from a variable (``include ${part}``); else return None there,
        as no reading of the text can say which file the engine will read.

    Returns
    -------
    list of Path or None
        The paths in the order met; files that do not exist are named too.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     deck = Path(d, "in.main")
    ...     _ = deck.write_text('include walls.in\\nif "1 > 0" then "include laws.in"\\ninclude ${extra}\\n')
    ...     _ = Path(d, "walls.in").write_text("jump SELF end\\n")
    ...     [p.name for p in scripts_named(deck, literal=True)], scripts_named(deck)
    (['walls.in', 'laws.in'], None)
    """
    paths: list = []
    names: set = set()
    todo = [deck]
    while todo:
        path = todo.pop()
        if not _text_file(path):
            continue
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        for line in text.splitlines():
            for name in _file_names(normalised(line)):
                if "$" in name:
                    if literal:
                        continue
                    return None
                if name != "SELF" and Path(name).name not in names:
                    names.add(Path(name).name)
                    paths.append(deck.parent / name)
                    todo.append(deck.parent / name)
    return paths


#: Commands whose quoted arguments are commands the engine runs (an if's branches, a run's every, a
#: partition's command)
_RUNNING = ("if", "run", "partition")


def _file_names(command: str) -> list:
    """The file names an include or jump gives in ``command`` (normalised), or in a command that
    ``command`` runs (an if's, at any depth), each as the engine takes it: quotes removed, its
    spaces and tabs kept (field round 30, I05: ``include "k  k.in"`` opens the file of two spaces;
    I21: the if's quoted ``'include "k k.in"'`` was read as naming "k").

    Examples
    --------
    >>> _file_names('include "k  k.in"'), _file_names("jump j.in loop")
    (['k  k.in'], ['j.in'])
    >>> _file_names('''if "1 > 0" then 'include "k k.in"' else "jump SELF a"''')
    ['k k.in', 'SELF']
    """
    try:
        split = words_of(command)
    except ScriptError:
        # the engine stops on the line; its words read as whitespace splits them, quotes dropped
        split = [w.strip("\"'") for w in command.split()]
        return [split[k + 1] for k, w in enumerate(split[:-1]) if w in ("include", "jump")]
    if len(split) >= 2 and split[0] in ("include", "jump"):
        return [split[1]]
    if split[:1] and split[0] in _RUNNING:
        return [name for word in split[1:] if len(word.split()) > 1 for name in _file_names(normalised(word))]
    return []


def _granular_only(deck: Path) -> bool:
    """Whether the deck and the scripts it names as written set a pair style, and every one they
    set is LAMMPS' ``pair_style granular`` (a global cutoff or none): a restart they read then
    holds that style (a pair_style in an if's quoted command, or in a file named by a variable,
    is not read here, and a line naming pair_style anywhere else counts as another style).

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     deck = Path(d, "in.main")
    ...     _ = deck.write_text("pair_style granular\\nread_restart a.rst\\n")
    ...     first = _granular_only(deck)
    ...     _ = deck.write_text('pair_style granular\\nif "1 > 0" then "pair_style hybrid granular"\\n')
    ...     first, _granular_only(deck)
    (True, False)
    """
    styles = set()
    for path in [deck, *(scripts_named(deck, literal=True) or [])]:
        if not _text_file(path):
            continue
        for _, line in logical_lines(path.read_text(encoding="utf-8", errors="replace")):
            split = normalised(line).split()
            if "pair_style" in line:
                styles.add(split[1] if split[:1] == ["pair_style"] and len(split) in (2, 3) else "")
    return styles == {"granular"}


def _named_files(deck: Path, literal: bool = False) -> set | None:
    """The names (without folders) of :func:`scripts_named`."""
    paths = scripts_named(deck, literal)
    return None if paths is None else {p.name for p in paths}


def _rewritten(text: str, label, scratch: Scratch, marker) -> str:
    """The text with each command made safe, line numbers kept."""
    physical = text.split("\n")
    out = list(physical)
    pending, start = "", 0
    for n, raw in enumerate(physical):
        if not pending:
            start = n
        pending += raw
        if pending.count(TRIPLE) % 2:
            pending += "\n"
            continue
        body = pending.rstrip()
        if body.endswith("&"):
            pending = body[:-1]
            continue
        command, pending = pending, ""
        loc = (label, start + 1)
        new = _safe(command, loc, scratch, marker)
        key = normalised(command)
        if key:
            _known(scratch, key, loc)
        last = n
        if new is not None:
            _known(scratch, normalised(new), loc)
            out[start] = new.replace("\n", " ")
            for k in range(start + 1, n + 1):
                out[k] = ""
            last = start
        if key and label in scratch.tagged:
            # after the command's last line: a comment ends it, which the engine echoes as read
            scratch.tags.append(loc)
            out[last] = f"{out[last]} {scratch.tag}{len(scratch.tags) - 1}"
    return "\n".join(out)


def _known(scratch: Scratch, key: str, loc) -> None:
    """The command ``key`` known as one of line ``loc``: in the whole copy's map (its first) and in
    its file's."""
    scratch.lines.setdefault(key, loc)
    scratch.files.setdefault(loc[0], {}).setdefault(key, loc)


def _audit_lines(scratch: Scratch, text: str) -> str:
    """A marker's text with each line tagged as the audit's own."""
    return "".join(f"{line} {scratch.tag}{AUDIT}\n" if line.strip() else "\n" for line in text.split("\n")[:-1]) \
        + text.split("\n")[-1]


def _safe(command: str, loc, scratch: Scratch, marker, top: bool = True) -> str | None:
    """The command made safe (None where it is already); ``top``: a line of its own, not a command
    an if quotes."""
    key = normalised(command)
    if not key:
        return None
    try:
        read, written = words_of(key), written_words(key)
    except ScriptError:
        read = written = key.split()
    if scratch.absolute and any(w in scratch.absolute for w in read[1:]):
        # a file named by an absolute path: its copy in the scratch, the command made safe as
        # written (a quoted name is one word, spaces and tabs kept: the engine opens it so; a name
        # in an if's quoted command is swapped where _safe_if makes that command safe)
        swapped = " ".join(_path_word(scratch.absolute[r]) if r in scratch.absolute else w
                           for r, w in zip(read, written))
        safe = _safe(swapped, loc, scratch, marker, top)
        return swapped if safe is None else safe
    word = key.split()[0]
    if "$" in word:
        # what it would run cannot be checked first: never run; the deck is refused if it reaches it
        return _labelled(scratch, scratch.dynamic, DYNAMIC, (loc, key), loc)
    if word in getattr(marker, "unknown", ()):
        return None             # a command the engine does not have: it stops there, as on the deck
    restart = getattr(marker, "restart", None)
    # a restart file (where the engine's marker reads restarts back) and a data file are written
    # into the copy: a later read_restart or read_data of them reads what the deck wrote
    if (word == "write_restart" and restart is not None or word == "write_data") and len(read) > 1:
        name = read[1]
        if _outside(name, scratch):
            # a file outside the copy (an absolute path: read-only for the confined engine, which
            # stopped there) is written into the scratch instead, where a read of the same name
            # reads it back; its base name kept (a * in it is the step, as LAMMPS writes it)
            target = scratch.redirected.setdefault(name, scratch.root / f"written_{len(scratch.redirected)}_"
                                                                        f"{Path(name).name}")
            return " ".join([word, _path_word(target), *written[2:]])
        if scratch.confined or "$" not in name:
            # its file lands in the copy (the engine's working folder; confined, nothing else is
            # writable): the deck's read reads it back, in the audit's scratch alone
            return None
    if word == "read_data" and (back := _read_back(key, scratch)) is not None:
        return back
    if word == "read_restart" and restart is not None:
        key = _read_back(key, scratch) or key
        k = len(scratch.restarts)
        scratch.restarts.append((loc[0], loc[1], key))
        path = scratch.root / f"restart_{k}"
        granular = scratch.granular and getattr(marker, "granular_restart", False)
        path.write_text(_audit_lines(scratch, restart(key, granular=True) if granular else restart(key)))
        return f"include {path}"
    if word == "shell" and scratch.confined and key.split()[1:2] and key.split()[1] in SHELL_BUILTINS:
        # the engine does these itself (no program runs), where nothing outside the copy is writable
        return None
    if word == "timer" and _timeout_zero(key):
        # every run after it ends at its first check (LAMMPS measured: no step made), which the
        # engine's pass, whose runs are skipped by the same timer, cannot show
        return _labelled(scratch, scratch.dynamic, DYNAMIC, (loc, key), loc)
    if word in SKIPPED_COMMANDS or word == "labelmap" and "write" in key.split()[1:2]:
        return _labelled(scratch, scratch.skipped, NOOP, (word, loc, key), loc)
    if word in ("include", "jump") and len(read) > 1 and (
            _outside(read[1], scratch) or not scratch.confined and "$" in read[1]):
        # a file outside the copied folder is read as it is, shell lines and all: never run
        return _labelled(scratch, scratch.dynamic, DYNAMIC, (loc, key), loc)
    if word == "partition" and len(key.split()) > 3 and key.split()[1] in ("yes", "no") \
            and _FIRST_PARTITION.fullmatch(key.split()[2]):
        # the engine, one partition, runs the command where it is meant for partition 1 (yes) and
        # never where not (no): field round 20, z30 and L98 (their pair_coeff, coefficientRestitution
        # skipped, the eps before them printed)
        inner = key.split(None, 3)[3]
        if key.split()[1] == "no":
            return _labelled(scratch, scratch.skipped, NOOP, ("partition no 1", loc, key), loc)
        safe = _safe(inner, loc, scratch, marker, top)
        return inner if safe is None else safe
    if word == "quit":
        path = scratch.root / f"quit_{sum(1 for _ in scratch.root.glob('quit_*'))}"
        path.write_text(_audit_lines(scratch, marker(None, key)))
        if not top and getattr(marker, "inline", False):
            return _inline(marker(None, key))
        return f"include {path}"
    if word == "fix":
        words = key.split()
        if len(words) > 3 and words[3] == "balance":
            # it runs: LAMMPS checks at a run's set-up that a pair style with a neighbour history is
            # defined before it, and stops where not (field round 35, X01, and LAMMPS' own
            # examples/granular/in.pour.drum: "Pair styles using neighbor history must be defined
            # before fix bal balance"), which the copy must show; its one way to write is dropped
            return _without_file(scratch, loc, key, "out", "the out keyword of fix balance")
        if len(words) > 3 and words[3] in _AVERAGING_FIXES:
            # it computes what a variable may read after a run (field round 14, r10: an if on
            # $(f_at) after the run stopped on the stand-in, "Mismatched fix in variable formula");
            # its one way to write is dropped
            return _without_file(scratch, loc, key, "file", f"the file keyword of fix {words[3]}")
        if len(words) > 3 and words[3] == "halt" and "message" in words[4:-1]:
            # its message is how the audit sees a soft halt met in the runs made for real (field
            # round 24, H01: message no hid it); it prints, nothing more
            k = words.index("message", 4)
            if words[k + 1] != "yes":
                return " ".join(words[:k + 1] + ["yes"] + words[k + 2:])
            return None
        if len(words) > 3 and words[3].startswith("couple/cfd"):
            # LIGGGHTS' CFD coupling exchanging in memory (mpi) writes nothing, and run alone it
            # exchanges nothing; its sub-fixes hold the per-atom forces a variable or compute may
            # read (field round 47a, M01 M02 and CFDEM's Ergun run decks: the stand-in stopped
            # LIGGGHTS, "Mismatched fix in variable formula", where LIGGGHTS runs them, 0.500006).
            # Coupling through files (file) is not run, nor are the sub-fixes of a coupling not run
            if words[3] == "couple/cfd":
                scratch.coupled = "file" not in words[4:]
            if scratch.coupled:
                return None
        if len(words) > 3 and words[3].startswith(_SKIPPED_FIX_PREFIXES):
            scratch.skipped.append((f"fix {words[3]}", loc, key))
            # a fix of the same ID that never acts, for unfix and fix_modify; its echo from this
            # line tells the deck reached it, as a no-op label's does. Not nve/noforce, which moves
            # each atom at its velocity once more in the runs made for real (LAMMPS measured: a
            # sphere falling at 1 m/s went 0.04 in 2000 steps of 1e-5 beside nve/sphere)
            noop = f"fix {words[1]} all viscous 0.0"
            scratch.silenced[(loc, noop)] = len(scratch.skipped) - 1
            return noop
        return None
    opened = (lambda name: _copied_text(scratch, name)) if getattr(marker, "includes_in_every", False) else None
    queued = getattr(marker, "includes_after_run", False)
    if word in RUN_COMMANDS and top and (parts := split_every(key, opened, queued)) is not None:
        return _parts(scratch, loc, key, marker, *parts)
    if word in RUN_COMMANDS:
        k = len(scratch.stages)
        scratch.stages.append((loc[0], loc[1], key))
        path = scratch.root / f"stage_{k}"
        path.write_text(_audit_lines(scratch, marker(k, key)))
        # the commands a run's every runs are echoed without a tag: known as the run's
        for piece, quote in segments_of(key):
            if quote and piece.endswith(quote) and len(piece) >= 2 * len(quote):
                _quoted(scratch, normalised(piece[len(quote):-len(quote)]), loc)
        if not top and getattr(marker, "inline", False):
            return _inline(f"label {STAGE_LABEL}{k}\n" + marker(k, key))
        return f"include {path}"
    if word == "if":
        return _safe_if(command, loc, scratch, marker)
    if word in GUARDED and top and getattr(marker, "guards_set", False) and not set("\"'") & set(key):
        # a set (a velocity) meets no atom where only a pour (its runs skipped) makes them, and the
        # engine stops ("Set command on system without atoms") where the deck's own run would set
        # the poured atoms: there the command is printed instead (print substitutes its variables,
        # which the echo of a quoted text does not), and the printed line read as the deck's
        probe = f"print '{UNSET} {key}'"
        _quoted(scratch, key, loc)
        _quoted(scratch, probe, loc)
        return f'if "$(count(all)) > 0" then "{key}" else "{probe}"'
    return None


def _without_file(scratch: Scratch, loc, key: str, keyword: str, what: str) -> str | None:
    """A fix that runs in the copy without the keyword by which it writes a file (``keyword`` and
    the name after it), named on stderr as ``what``; None where it has none. The name is dropped as
    the engine reads it: a quoted name is one word, spaces and all (field round 30, O09: file
    "a a.txt" left 'a.txt"' behind, an unmatched quote the engine stopped on). A line that does not
    parse is left as written, for the engine stops on it (an unclosed quote: split at whitespace
    and rewritten without its file, it had become a line the engine ran)."""
    try:
        read, written = words_of(key), written_words(key)
    except ScriptError:
        return None
    kept = [w for k, w in enumerate(written) if read[k] != keyword and (k == 0 or read[k - 1] != keyword)]
    if kept == written:
        return None
    scratch.skipped.append((what, loc, key))
    scratch.silenced[(loc, normalised(" ".join(kept)))] = len(scratch.skipped) - 1
    return " ".join(kept)


def _inline(text: str) -> list:
    """A marker's commands as an if runs them, one quoted argument each (:func:`_safe_if`)."""
    return [line for line in text.split("\n") if line.strip()]


def _arguments(new: str | list, quote: str) -> str:
    """What :func:`_safe` made of an if's command, as the if's argument(s): one command in the quote
    it had, or a marker's commands inline (:func:`_inline`), each in double quotes, or single where
    it holds a double."""
    if isinstance(new, str):
        return f"{quote}{new}{quote}"
    return " ".join(f"'{command}'" if '"' in command else f'"{command}"' for command in new)


def _timeout_zero(key: str) -> bool:
    """Whether ``timer ... timeout T ...`` gives a timeout of no time (0, 0:0, 0:0:0)."""
    words = key.split()
    return any(w == "timeout" and k + 1 < len(words) and re.fullmatch(r"0+(:0+){0,2}", words[k + 1]) is not None
               for k, w in enumerate(words))


def _read_back(key: str, scratch: Scratch) -> str | None:
    """A read (read_data, read_restart) of a file a write redirected into the scratch
    (:attr:`Scratch.redirected`), made to read that file; None where it names no such file."""
    try:
        read, written = words_of(key), written_words(key)
    except ScriptError:
        return None             # the engine stops on the line
    if len(read) < 2 or read[1] not in scratch.redirected:
        return None
    return " ".join([written[0], _path_word(scratch.redirected[read[1]]), *written[2:]])


def remark(scratch: Scratch, marker) -> None:
    """Each run's marker file written anew by ``marker`` (``marker(k, run_text)``, as
    :func:`scratch_copy` takes it), for another pass of the same copy."""
    for k, (_, _, key) in enumerate(scratch.stages):
        (scratch.root / f"stage_{k}").write_text(_audit_lines(scratch, marker(k, key)) + scratch.after.get(k, ""))


def _copied_text(scratch: Scratch, name: str) -> str | None:
    """The text of a file of the copy a command names relative to the deck's folder, None where it
    is not one (outside the copy, not a file, not text)."""
    if _outside(name, scratch):
        return None
    path = scratch.deck.parent / name.strip("\"'")
    try:
        return path.read_text(encoding="utf-8") if path.is_file() and path.stat().st_size <= MAX_TEXT_BYTES else None
    except (OSError, UnicodeDecodeError):
        return None


def split_every(run: str, opened=None, queued: bool = False) -> tuple[list[str], list[str], list[str]] | None:
    """``run N every M c1 c2 ...`` as the runs of its parts and the commands LAMMPS runs after each
    (the last part too), where the pass must run them to see the contact of each part: N and M
    literal, no ``upto`` (its parts depend on the step then), at most :data:`MAX_PARTS` parts, and
    among the commands one the copy does not make a no-op, none of which runs, quits, clears or
    jumps, alone, in an if's branch or in a file it includes (:func:`_flow`), nor reads a ramp or a
    compute (:func:`_in_run`: LAMMPS evaluates them inside its run, where they differ from between
    two runs): those keep the run as written.
    A value substituted from the step or a variable is read after each part of the copy, where
    the pass reads it as after any run. The first part sets the run up as
    LAMMPS' first part always does (``pre yes``); each keeps the run's start, stop and post, which
    LAMMPS applies to every part alike (its run.cpp, 22 Jul 2025). None where it is not such a run.
    With ``queued`` (LIGGGHTS 3.8.0) an ``include`` among the commands only opens its file, which
    is read after the whole run, the file opened last first (measured: ``run 300 every 100 "include
    a.in" "print X" "include b.in"`` prints X three times, then b's lines, a's, b's, a's, b's, a's,
    all at step 300; field round 35, L06 L12): such includes, of files named without a variable (a
    variable would be read at the part's end), are left out of the parts and read after the last.

    Parameters
    ----------
    run : str
        A run command, normalised.
    opened : callable, optional
        The text of a file an include among the commands names (None where not read): an include
        of a file that holds no control flow is run between the parts as the rest.
    queued : bool, optional
        Whether the engine reads a file an include among the commands names only after the run.

    Returns
    -------
    (list of str, list of str, list of str) or None
        The parts' runs, the commands between them, and the includes read after the last part's
        commands, in the order the engine reads them.

    Examples
    --------
    >>> split_every('run 250 every 100 "pair_coeff * * 2000 0" "print x"')
    (['run 100 pre yes', 'run 100', 'run 50'], ['pair_coeff * * 2000 0', 'print x'], [])
    >>> split_every('run 0 pre no every 10 "variable a equal 2"')
    (['run 0 pre yes'], ['variable a equal 2'], [])
    >>> split_every('run 200 every 100 "include a.in" "print x" "include b.in"', queued=True)
    (['run 100 pre yes', 'run 100'], ['print x'], ['include b.in', 'include a.in', 'include b.in', 'include a.in'])
    >>> split_every('run 200 every 100 "include a${n}.in"', queued=True) is None
    True
    >>> split_every('run 100 every 10 "print x"') is None, split_every("run 100 every 10 NULL") is None
    (True, True)
    >>> split_every('run 300 every 100 "pair_coeff * * hooke $(ramp(1000,2000)) 0"') is None
    True
    >>> split_every('run 200 every 100 "pair_coeff * * hooke $(step*2+1000) 0"')[1]
    ['pair_coeff * * hooke $(step*2+1000) 0']
    >>> split_every('run 200 every 100 "variable s equal $(step)" "print $(step)" "timestep $(dt*0.5)"')[0]
    ['run 100 pre yes', 'run 100']
    """
    try:
        split = words(run)
    except ScriptError:
        return None
    if split[:1] != ["run"] or "every" not in split or not split[1:2] or not split[1].isdigit():
        return None
    at = split.index("every")
    keywords, commands = split[2:at], split[at + 2:]
    if len(keywords) % 2 or not split[at + 1:at + 2] or not split[at + 1].isdigit() or int(split[at + 1]) == 0:
        return None
    if any(key not in ("start", "stop", "pre", "post") for key in keywords[::2]):
        return None                 # upto (its steps counted from the step it starts at), or a typo
    firsts = [command.split()[0] if command.split() else "" for command in commands]
    includes = [command for command, first in zip(commands, firsts) if queued and first == "include"]
    if any(len(include.split()) != 2 or "$" in include for include in includes):
        return None
    commands = [command for command in commands if command not in includes]
    firsts = [command.split()[0] if command.split() else "" for command in commands]
    # (balance, never run in the pass, makes LAMMPS' ghost atoms anew, which a part with pre no after
    # it does not see: the reader reads it from its no-op, field round 33, G07)
    if not (commands or includes) or all(first in SKIPPED_COMMANDS and first != "balance" or first == "NULL"
                                         for first in firsts) and not includes \
            or any(_flow(command, opened) for command in commands) \
            or any(_in_run(command) for command in commands):
        return None
    steps, every = int(split[1]), int(split[at + 1])
    count = max(1, -(-steps // every))
    if count > MAX_PARTS:
        return None
    kept = [f"{key} {value}" for key, value in zip(keywords[::2], keywords[1::2]) if key != "pre"]
    later = [f"pre {value}" for key, value in zip(keywords[::2], keywords[1::2]) if key == "pre"][-1:]
    runs = [" ".join(["run", str(min(every, steps - j * every)), *kept, *(["pre yes"] if j == 0 else later)])
            for j in range(count)]
    return runs, commands, [include for _ in range(count) for include in reversed(includes)]


def _parts(scratch: Scratch, loc, key: str, marker, runs: list, between: list, last: list = ()) -> str:
    """A run in parts (:func:`split_every`) as the copy runs it: a marker for each part, a stage of
    its own, the commands made safe after each, and ``last`` (includes the engine reads after the
    run) after the last part's; the first marker's file holds the rest (after its marker:
    :attr:`Scratch.after`), so the run's line stays one include. The commands are echoed without
    a tag, known as the run's line's, as LAMMPS echoes those its every runs."""
    def made_safe(commands: list) -> list:
        lines = []
        for command in commands:
            made = _safe(command, loc, scratch, marker)
            line = command if made is None else made
            _quoted(scratch, normalised(command), loc)
            _quoted(scratch, normalised(line), loc)
            lines.append(line)
        return lines
    lines, read_last = made_safe(between), made_safe(list(last))
    first = len(scratch.stages)
    for run in runs:
        scratch.stages.append((loc[0], loc[1], run))
    after = []
    for j in range(len(runs)):
        after.extend(lines)
        if j + 1 < len(runs):
            after.append(f"include {scratch.root / f'stage_{first + j + 1}'} {scratch.tag}{AUDIT}")
    after.extend(read_last)
    scratch.after[first] = "\n".join(after) + "\n"
    scratch.parts[first] = (key, len(runs))
    for j, run in enumerate(runs):
        (scratch.root / f"stage_{first + j}").write_text(_audit_lines(scratch, marker(first + j, run))
                                                         + scratch.after.get(first + j, ""))
    return f"include {scratch.root / f'stage_{first}'}"


def _labelled(scratch: Scratch, kept: list, template: str, entry, loc) -> str:
    """The no-op label that stands for a command never run: ``entry`` appended to ``kept`` (the
    scratch's ``skipped`` or ``dynamic``), the label numbered by its place there, and known as a
    command of line ``loc``, so that its echo (also from inside an if) tells the deck reached it."""
    kept.append(entry)
    label = template.format(len(kept) - 1)
    _known(scratch, label, loc)
    return label


def _quoted(scratch: Scratch, key: str, loc) -> None:
    """A command an if or a run's every on line ``loc`` runs (echoed after that line, untagged)."""
    if key:
        scratch.quoted.setdefault(loc, set()).add(key)
        _known(scratch, key, loc)


def _outside(name: str, scratch: Scratch) -> bool:
    """Whether a literal file name of include or jump (or write_restart) leaves what the copy made
    safe holds: absolute, or climbing out by .. to a path the deck's files do not name as written
    (those are copied, :attr:`Scratch.mirrored`)."""
    name = name.strip("\"'")
    if os.path.isabs(name) and Path(name).is_relative_to(scratch.root):
        return False          # a copy the scratch made (of a file named by an absolute path)
    norm = os.path.normpath(name)
    # (a name that climbs back into the folder, "sub dir/../k.in", stays in the copy: field round 32, Q18;
    # so does one read from a folder of the deck's that a shell cd enters, "include ../l.in" after
    # "shell cd sub": round 38, A19, refused as outside, LAMMPS read the deck's own l.in; where the
    # deck reads it from elsewhere, the copy holds nothing there and the engine stops, as it says)
    inside = any(not os.path.normpath(os.path.join(folder, norm)).startswith("..") for folder in scratch.cd_folders)
    return "$" not in name and (os.path.isabs(name) or (norm == ".." or norm.startswith("../"))
                                and norm not in scratch.mirrored and not inside)


def _safe_if(command: str, loc, scratch: Scratch, marker) -> str | None:
    """An ``if`` with every command it may run made safe, and each known as a command of its line.

    The conditions are the argument after ``if`` and after each ``elif``; every other argument but
    the keywords is a command, quoted or not, and its name may come from a variable (LAMMPS
    substitutes it when the branch runs): judged by its text, never by whether it looks like one."""
    changed, out, previous = False, [], ""
    for piece, quote in segments_of(normalised(command)):
        if quote and piece.endswith(quote) and len(piece) >= 2 * len(quote):
            inner = piece[len(quote):-len(quote)]
            if previous not in ("if", "elif") and normalised(inner):
                _quoted(scratch, normalised(inner), loc)
                new = _safe(inner, loc, scratch, marker, top=False)
                if new is not None:
                    changed = True
                    piece = _arguments(new, quote)
            previous = piece
        elif not quote:
            words = re.split(r"(\s+)", piece)
            for k, word in enumerate(words):
                if not word or word.isspace():
                    continue
                if previous not in ("if", "elif") and word not in ("if", "then", "elif", "else"):
                    _quoted(scratch, normalised(word), loc)
                    new = _safe(word, loc, scratch, marker, top=False)
                    if new is not None:
                        changed = True
                        words[k] = _arguments(new, '"')
                previous = word
            piece = "".join(words)
        out.append(piece)
    return "".join(out) if changed else None
