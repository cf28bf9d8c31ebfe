"""An engine's pass through a deck's scratch copy (:mod:`restitution.dem.deck.scratch`), as a child
process within a time budget and an output cap: what it echoed, the atoms its run markers and the
deck's end wrote, its error and whether the budget ended it. Each engine's ``deck_run`` module says
how its engine is started and what its markers write.

The budget is there to end loops that never finish (a settle loop on a value the skipped runs never
change), not to judge how fast an engine sets a deck up: its clock runs only once the engine runs a
line of the deck a second time (a jump, a ``next`` loop, a file included again), which the scratch
copy's tags tell. A pass that runs every line once ends by itself, however slow its set-up (50 000
grains inserted before the first run); only a ceiling of :data:`CEILING` times the budget bounds it,
against a single command that never ends.
"""

from __future__ import annotations

import os
import re
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from .sandbox import available as confining, confine

__all__ = ["DeckRun", "EngineRun", "ATOMS", "ATOMS_AT_END", "RESTART_INFO", "RUN_PRINTED", "CEILING", "MAX_ECHO", "echo_cap", "engine_environment",
           "run_child"]

#: The file in the scratch directory that each run's marker appends the atoms to
ATOMS = "atoms"
#: The file of the atoms where the deck ends
ATOMS_AT_END = "atoms_end"
#: The file in the scratch directory where each read_restart's marker appends what the engine holds
#: after it (LAMMPS' info), one block per read, in the order they ran
RESTART_INFO = "restart_info"
#: What a marker prints before the run it stands for where the engine echoes its own line of the
#: run unsubstituted (LIGGGHTS' marker runs one step of its own): the run's text as the engine
#: substitutes it, so that its length is the deck's
RUN_PRINTED = "restitution_run"
#: The ID prefix of the dump a LAMMPS marker writes the atoms with at its run's set-up
SETUP_DUMP = "restitution_atoms_"
#: A pass whose atoms files grow beyond this is stopped like one out of time
_MAX_OUTPUT = 512 * 2 ** 20
#: The most of an engine's screen (its echo) the audit reads: a pass that writes more is stopped
#: there like one out of time. A loop without a run echoes megabytes a second, and every line read
#: costs the audit's own memory and time (about 0.1 s a MB); the 10 000 runs of a real pour loop
#: echo 11 MB
MAX_ECHO = 16 * 2 ** 20
#: The echo's cap grows with the pass's budget, by this many bytes a second of budget (from
#: :data:`MAX_ECHO`), up to :data:`MAX_ECHO_ASKED`: a user who asks for more time gets a longer loop read too
#: (field round 18, b40: a finite loop of 10 000 passes outgrew 16 MB, and --budget 600 still stopped there)
ECHO_PER_SECOND = 2 ** 20
MAX_ECHO_ASKED = 256 * 2 ** 20


def echo_cap(budget: float) -> int:
    """The most of the engine's echo a pass with this budget reads, in bytes.

    Parameters
    ----------
    budget : float
        The pass's budget of wall time in seconds.

    Returns
    -------
    int

    Examples
    --------
    >>> echo_cap(10) == MAX_ECHO, echo_cap(60) == 60 * 2 ** 20, echo_cap(3600) == MAX_ECHO_ASKED
    (True, True, True)
    """
    return int(min(max(MAX_ECHO, budget * ECHO_PER_SECOND), MAX_ECHO_ASKED))
#: A pass that runs no line twice is bounded by this many times the budget of wall time, not by the
#: budget: a straight pass ends by itself, so only a command that never ends meets the ceiling
CEILING = 10


@dataclass
class EngineRun:
    """What an engine did with a deck's scratch copy.

    Parameters
    ----------
    echo : str
        Its screen: the commands it ran, echoed, and its messages.
    atoms : str
        The atoms each run's marker wrote.
    at_end : str
        The atoms where the deck ended.
    error : str
        The engine's error output ("" where it ended well or was stopped).
    timed_out : bool
        Whether the budget ended it.
    status : int or None
        Its exit status (negative where the budget's kill ended it).
    spent : str
        Where the budget ended it, the part of the budget that ran out ("20 s of wall time in a
        loop", "16 MB of echo"); "" where it ended by itself.
    looped : bool
        Whether the engine ran a line of the deck a second time (a loop) before it ended.
    loop_time : float
        The wall time, in seconds, from the engine's first line run a second time to its end.
    wall : float
        The pass's wall time, in seconds.

    Examples
    --------
    >>> EngineRun("run 0", "", "", "", False, 0).timed_out
    False
    """
    echo: str
    atoms: str
    at_end: str
    error: str
    timed_out: bool
    status: int | None = None
    spent: str = ""
    looped: bool = False
    loop_time: float = 0.0
    wall: float = 0.0


class DeckRun(Protocol):
    """What an engine's ``deck_run`` module provides, as the deck audit (:mod:`restitution.dem.deck`)
    runs a deck's scratch copy in that engine; each module's functions say what is its own.

    Parameters
    ----------
    ENGINE : str
        The engine's name, as its refusals say it.
    INSTALL : str
        How to get the engine, said in one line where it is not installed.

    Examples
    --------
    >>> from restitution.dem.engines.lammps import deck_run
    >>> deck_run.ENGINE, callable(deck_run.run_copy)
    ('LAMMPS', True)
    """
    ENGINE: str
    INSTALL: str

    def available(self) -> bool:
        """Whether the engine can be started here."""

    def marker(self, root: Path):
        """The function ``f(k, run_text) -> str`` that writes stage k's marker: the text that stands for
        the deck's run ``run_text`` in the scratch copy (``root`` the scratch directory), which runs
        as far as the engine must and then appends the atoms to ``root``/ATOMS."""

    def run_copy(self, deck: Path, root: Path, budget: float, original: Path | None = None,
                 check_every: bool = False, tag: str | None = None, ceiling: float | None = None) -> EngineRun:
        """Run the scratch copy ``deck`` (its folder the working directory; ``root`` the scratch
        directory of its screen and atoms files) in the engine within ``budget`` seconds of wall
        time in a loop (from the first line run twice, told by the scratch copy's ``tag``) and
        ``ceiling`` in all, confined to ``root`` where ``original`` (the deck's own folder) is
        given and the system allows it (:func:`restitution.dem.dialect.child.run_child`). A marker
        met again may skip the engine's set-up and its dump of the atoms, unless ``check_every``."""


def engine_environment(root: Path) -> dict:
    """The environment the engine's pass runs in: the user's, as the engine run by hand would see
    it (a deck's ``getenv`` variables choose its parameters), with HOME and TMPDIR in the scratch
    directory ``root`` (what the engine writes there stays there) and one thread.

    Parameters
    ----------
    root : Path
        The scratch directory.

    Returns
    -------
    dict

    Examples
    --------
    >>> env = engine_environment(Path("/s"))
    >>> env["HOME"], env["TMPDIR"], env["OMP_NUM_THREADS"]
    ('/s', '/s', '1')
    """
    return {**os.environ, "HOME": str(root), "TMPDIR": str(root), "OMP_NUM_THREADS": "1"}


def run_child(argv: list, cwd: Path, env: dict, root: Path, budget: float, screen_is_stdout: bool = False,
              original: Path | None = None, readable=(), tag: str | None = None,
              ceiling: float | None = None) -> EngineRun:
    """Run ``argv`` (an engine whose screen goes to ``root``/screen) until it ends, ``budget``
    seconds pass in a loop (all its time without ``tag``), ``ceiling`` seconds pass in all, or its
    files outgrow the cap.

    Parameters
    ----------
    argv : list of str
        The command.
    cwd : Path
        Its working directory (the deck's copied folder).
    env : dict
        Its environment.
    root : Path
        The scratch directory: screen and atoms files.
    budget : float
        Wall-time budget of a loop in seconds: counted from the first line the engine echoes a
        second time.
    screen_is_stdout : bool
        The child's standard output is its screen: written to ``root``/screen.
    original : Path, optional
        The deck's own folder: where the system allows it, the child sees only ``root`` (writable),
        the copy ``cwd`` also at ``original``, and the system's and ``readable``'s folders read-only
        (:func:`restitution.dem.dialect.sandbox.confine`).
    readable : sequence of path
        Folders the program needs beside the system's.
    tag : str, optional
        The scratch copy's tag (:attr:`restitution.dem.deck.scratch.Scratch.tag`): an echoed line
        ending in the tag and a number is a line of the deck, and the same number twice is a line
        run again. Without it the budget counts from the start.
    ceiling : float, optional
        Wall time in seconds the whole pass may take (default :data:`CEILING` times ``budget``; the
        budget itself without ``tag``).

    Returns
    -------
    EngineRun
        ``error`` holds the child's stderr where it ended with a nonzero status.

    Examples
    --------
    >>> import sys, tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     done = run_child([sys.executable, "-c", "import sys; sys.exit(3)"], Path(d), {}, Path(d), 10.0)
    >>> done.status, done.timed_out, done.looped
    (3, False, False)
    """
    screen = root / "screen"
    # a pass made again starts with no screen: the last pass's, read for its size before the engine
    # truncates it, would end this one at once when it outgrew the cap
    screen.unlink(missing_ok=True)
    start = time.monotonic()
    lines = _Repeats(screen, tag) if tag else None
    ceiling = (CEILING * budget if tag else budget) if ceiling is None else ceiling
    confined = confine(root, cwd, original, readable) if original is not None and confining() else None
    with open(screen, "wb") if screen_is_stdout else open(os.devnull, "wb") as stdout:
        proc = subprocess.Popen(argv, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=stdout,
                                stderr=subprocess.PIPE, text=True, preexec_fn=confined)
    spent, cap = "", echo_cap(budget)
    while True:
        try:
            _, err = proc.communicate(timeout=0.05)
            break
        except subprocess.TimeoutExpired:
            echoed, written = (p.stat().st_size if p.exists() else 0 for p in (screen, root / ATOMS))
            now = time.monotonic()
            looped_at = start if lines is None else lines.first_repeat(now)
            if looped_at is not None and now - looped_at > budget:
                spent = f"{budget:g} s of wall time in a loop" if lines else f"{budget:g} s of wall time"
            elif now - start > ceiling:
                straight = lines is not None and looped_at is None
                spent = f"{ceiling:g} s of wall time in all, the ceiling" + (
                    ", in a pass that had run no line twice" if straight else "")
            elif echoed > cap:
                spent = f"{cap / 2 ** 20:g} MB of echo"
            elif written > _MAX_OUTPUT:
                spent = f"{_MAX_OUTPUT / 2 ** 20:g} MB of atoms written"
            if spent:
                proc.kill()
                _, err = proc.communicate()
                break
    # (the budget's kill is no error of the engine's)
    error = "" if spent or proc.returncode == 0 else err.strip()
    if not spent and screen.exists() and screen.stat().st_size > cap:
        spent = f"{cap / 2 ** 20:g} MB of echo"      # ended between two looks: its end is not read
    echo = _head(screen, cap)
    atoms, at_end = ((root / name).read_text(errors="replace") if (root / name).exists() else ""
                     for name in (ATOMS, ATOMS_AT_END))
    end = time.monotonic()
    looped_at = lines.first_repeat(end) if lines else None
    return EngineRun(echo, atoms, at_end, error, bool(spent), proc.returncode, spent, looped=looped_at is not None,
                     loop_time=0.0 if looped_at is None else end - looped_at, wall=end - start)


class _Repeats:
    """Reads an engine's screen as it grows, for the first line of the deck echoed a second time
    (its tag's number seen before): where a loop begins. Only whole lines are read, each once."""

    def __init__(self, screen: Path, tag: str):
        self.screen, self.offset, self.seen, self.at = screen, 0, set(), None
        self.pattern = re.compile(re.escape(tag.encode()) + rb"(\d+)")

    def first_repeat(self, now: float) -> float | None:
        """The time (the clock of ``now``) the first line run twice was seen, None before."""
        if self.at is None and self.screen.exists():
            with open(self.screen, "rb") as f:
                f.seek(self.offset)
                data = f.read(4 * 2 ** 20)
            data = data[:data.rfind(b"\n") + 1]
            self.offset += len(data)
            for m in self.pattern.finditer(data):
                if m.group(1) in self.seen:
                    self.at = now
                    break
                self.seen.add(m.group(1))
        return self.at


def _head(path: Path, cap: int) -> str:
    """The text of the file at ``path`` up to ``cap`` bytes, cut after its last whole line there
    ("" where there is no file): what the engine wrote after the cap is never read."""
    if not path.exists():
        return ""
    with open(path, "rb") as f:
        data = f.read(cap + 1)
    if len(data) > cap:
        data = data[:data.rfind(b"\n", 0, cap) + 1]
    return data.decode(errors="replace")
