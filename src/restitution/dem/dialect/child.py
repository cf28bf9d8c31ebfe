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

__all__ = ["DeckRun", "EngineRun", "ATOMS", "ATOMS_AT_END", "MAX_ECHO", "run_child"]

#: The file in the scratch directory that each run's marker appends the atoms to
ATOMS = "atoms"
#: The file of the atoms where the deck ends
ATOMS_AT_END = "atoms_end"
#: A pass whose atoms files grow beyond this is stopped like one out of time
_MAX_OUTPUT = 512 * 2 ** 20
#: The most of an engine's screen (its echo) the audit reads: a pass that writes more is stopped
#: there like one out of time. A loop without a run echoes megabytes a second, and every line read
#: costs the audit's own memory and time (about 0.1 s a MB); the 10 000 runs of a real pour loop
#: echo 11 MB
MAX_ECHO = 16 * 2 ** 20


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
        Where the budget ended it, the part of the budget that ran out ("20 s of wall time", "16 MB
        of echo"); "" where it ended by itself.

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
                 check_every: bool = False) -> EngineRun:
        """Run the scratch copy ``deck`` (its folder the working directory; ``root`` the scratch
        directory of its screen and atoms files) in the engine within ``budget`` seconds of wall
        time, confined to ``root`` where ``original`` (the deck's own folder) is given and the
        system allows it (:func:`restitution.dem.dialect.child.run_child`). A marker met again
        may skip the engine's set-up and its dump of the atoms, unless ``check_every``."""


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
    spent = ""
    while True:
        try:
            _, err = proc.communicate(timeout=0.05)
            break
        except subprocess.TimeoutExpired:
            echoed, written = (p.stat().st_size if p.exists() else 0 for p in (screen, root / ATOMS))
            if time.monotonic() - start > budget:
                spent = f"{budget:g} s of wall time"
            elif echoed > MAX_ECHO:
                spent = f"{MAX_ECHO / 2 ** 20:g} MB of echo"
            elif written > _MAX_OUTPUT:
                spent = f"{_MAX_OUTPUT / 2 ** 20:g} MB of atoms written"
            if spent:
                proc.kill()
                _, err = proc.communicate()
                break
    # (the budget's kill is no error of the engine's)
    error = "" if spent or proc.returncode == 0 else err.strip()
    if not spent and screen.exists() and screen.stat().st_size > MAX_ECHO:
        spent = f"{MAX_ECHO / 2 ** 20:g} MB of echo"      # ended between two looks: its end is not read
    echo = _head(screen, MAX_ECHO)
    atoms, at_end = ((root / name).read_text(errors="replace") if (root / name).exists() else ""
                     for name in (ATOMS, ATOMS_AT_END))
    return EngineRun(echo, atoms, at_end, error, bool(spent), proc.returncode, spent)


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
