"""An engine's pass through a deck's scratch copy (:mod:`restitution.dem.deck.scratch`), as a child
process within a wall-time budget and an output cap: what it echoed, the atoms its run markers and
the deck's end wrote, its error and whether the budget ended it. Each engine's ``deck_run`` module
says how its engine is started and what its markers write.
"""

from __future__ import annotations

import os
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from .sandbox import available as confining, confine

__all__ = ["DeckRun", "EngineRun", "ATOMS", "ATOMS_AT_END", "run_child"]

#: The file in the scratch directory that each run's marker appends the atoms to
ATOMS = "atoms"
#: The file of the atoms where the deck ends
ATOMS_AT_END = "atoms_end"
#: A pass that writes more than this is stopped like one out of time
_MAX_OUTPUT = 512 * 2 ** 20


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

    def run_copy(self, deck: Path, root: Path, budget: float, original: Path | None = None) -> EngineRun:
        """Run the scratch copy ``deck`` (its folder the working directory; ``root`` the scratch
        directory of its screen and atoms files) in the engine within ``budget`` seconds of wall
        time, confined to ``root`` where ``original`` (the deck's own folder) is given and the
        system allows it (:func:`restitution.dem.dialect.child.run_child`)."""


def run_child(argv: list, cwd: Path, env: dict, root: Path, budget: float, screen_is_stdout: bool = False,
              original: Path | None = None, readable=()) -> EngineRun:
    """Run ``argv`` (an engine whose screen goes to ``root``/screen) until it ends, ``budget``
    seconds pass or its files outgrow the cap.

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
        Wall-time budget in seconds.
    screen_is_stdout : bool
        The child's standard output is its screen: written to ``root``/screen.
    original : Path, optional
        The deck's own folder: where the system allows it, the child sees only ``root`` (writable),
        the copy ``cwd`` also at ``original``, and the system's and ``readable``'s folders read-only
        (:func:`restitution.dem.dialect.sandbox.confine`).
    readable : sequence of path
        Folders the program needs beside the system's.

    Returns
    -------
    EngineRun
        ``error`` holds the child's stderr where it ended with a nonzero status.

    Examples
    --------
    >>> import sys, tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     done = run_child([sys.executable, "-c", "import sys; sys.exit(3)"], Path(d), {}, Path(d), 10.0)
    >>> done.status, done.timed_out
    (3, False)
    """
    screen = root / "screen"
    start = time.monotonic()
    confined = confine(root, cwd, original, readable) if original is not None and confining() else None
    with open(screen, "wb") if screen_is_stdout else open(os.devnull, "wb") as stdout:
        proc = subprocess.Popen(argv, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=stdout,
                                stderr=subprocess.PIPE, text=True, preexec_fn=confined)
    timed_out = False
    while True:
        try:
            _, err = proc.communicate(timeout=0.05)
            break
        except subprocess.TimeoutExpired:
            out = sum(p.stat().st_size for p in (screen, root / ATOMS) if p.exists())
            if time.monotonic() - start > budget or out > _MAX_OUTPUT:
                timed_out = True
                proc.kill()
                _, err = proc.communicate()
                break
    echo = screen.read_text(errors="replace") if screen.exists() else ""
    atoms, at_end = ((root / name).read_text(errors="replace") if (root / name).exists() else ""
                     for name in (ATOMS, ATOMS_AT_END))
    error = "" if timed_out or proc.returncode == 0 else err.strip()
    return EngineRun(echo, atoms, at_end, error, timed_out, proc.returncode)
