"""LIGGGHTS interprets a deck itself: its scratch copy (:mod:`restitution.dem.deck.scratch`) runs in
the ``liggghts`` binary with every command echoed after LIGGGHTS' own substitution (``-echo
screen``), within a wall-time budget.

LIGGGHTS 3.8.0 has no ``-skiprun``: each run's marker runs one step instead (``run 1``), which sets
the run up as the deck's own run would (LIGGGHTS checks its materials, pair coefficients and meshes
there) and does what its first step does (an insertion fix due then inserts, so a later ``set`` or
``group`` finds the atoms it would find), and then writes the atoms' type, radius and mass as
LIGGGHTS holds them. Particles a run would insert later are not there: their sizes come from the
particle templates in the executed commands, as the reader reads them. A loop that waits for a
value the deck's runs would change ends by the budget.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from ...dialect.child import ATOMS, ATOMS_AT_END, RESTART_INFO, RUN_PRINTED, EngineRun, engine_environment, run_child
from . import run
from .run import MPI_NOT_STARTED, MPI_START_RETRIES

__all__ = ["ENGINE", "MAKES_RUNS", "INSTALL", "available", "marker", "run_copy"]

#: The engine's name, as its refusals say it
ENGINE = "LIGGGHTS"
#: It makes a deck's runs for real where asked (``marker(root, real=True)``): the audit then reads
#: the state they reach (:func:`restitution.dem.deck._made_runs`)
MAKES_RUNS = True
#: How to get it, said in one line where it is not installed
INSTALL = "the deck is run by LIGGGHTS itself, whose binary liggghts is not on PATH: as root, apt-get install " \
          "liggghts (Debian's package, LIGGGHTS 3.8.0)"
#: Full precision for the dump's columns (LIGGGHTS' default %g keeps 6 digits of a mass)
_FORMAT = 'modify format "%d %d %.17g %.17g"'


def available() -> bool:
    """Whether the ``liggghts`` binary is on PATH (:func:`restitution.dem.engines.liggghts.run.available`;
    the contract: :class:`~restitution.dem.dialect.child.DeckRun`)."""
    return run.available()


def marker(root: Path, real: bool = False):
    """The function that writes stage k's marker: a run of one step (with ``real``, the deck's run
    itself), then the atoms as LIGGGHTS holds them (the contract:
    :class:`~restitution.dem.dialect.child.DeckRun`).

    Examples
    --------
    >>> print(marker(Path("/s"))(0, "run 10"))
    run 1 pre yes post no
    write_dump all custom /s/atoms id type radius mass modify format "%d %d %.17g %.17g" append yes
    <BLANKLINE>
    >>> print(marker(Path("/s"), real=True)(0, "run 10").splitlines()[0])
    run 10

    A run whose length a variable gives is printed first, substituted by LIGGGHTS:

    >>> print(marker(Path("/s"))(0, "run ${n}").splitlines()[0])
    print "restitution_run run ${n}"

    A read_restart (of a file the deck wrote in its copy) is followed by LIGGGHTS' account of what
    it holds:

    >>> print(marker(Path("/s")).restart("read_restart f.restart"), end="")
    read_restart f.restart
    info system groups out append /s/restart_info
    """
    def text(k: int | None, run: str) -> str:
        if k is None:
            # a quit: LIGGGHTS ends the process there (exit status 1, no message), the deck's end
            # (field round 20, L86: it was run as a stage, and the runs after it audited as the deck's)
            return f"{_ending(root)}{run}\n"
        # "pre yes": the set-up of every run of the deck's, not the shortened one LIGGGHTS may take
        # for a run right after another
        made = run if real else "run 1 pre yes post no"
        # the deck's run is not echoed where the marker's own stands for it: a length given by a
        # variable (field round 15, R01: run ${r_1step}) is printed as LIGGGHTS substitutes it
        # (print substitutes inside its quotes, which no echo does)
        said = f'print "{RUN_PRINTED} {run}"\n' if not real and "$" in run and not set("\"'") & set(run) else ""
        return f"{said}{made}\nwrite_dump all custom {root / ATOMS} id type radius mass {_FORMAT} append yes\n"

    def restart(read: str) -> str:
        # units, atom style, types, pair style and groups, in LIGGGHTS 3.8.0's words (its info has
        # no "coeffs" and no time step; the audit reads it back, never the binary file)
        return f"{read}\ninfo system groups out append {root / RESTART_INFO}\n"
    text.restart = restart
    # LIGGGHTS 3.8.0 stops on an include inside an if ("Cannot use include command within an if
    # command"): a run or quit an if runs gets the marker's commands inline (field round 20, L95, L97)
    text.inline = True
    text.unknown = UNKNOWN_COMMANDS
    # a file a run's every includes is only opened there and read after the whole run, the file
    # opened last first (measured in LIGGGHTS 3.8.0; field round 35, L06 L12): the copy reads them so
    text.includes_after_run = True
    return text


#: Commands LAMMPS has and LIGGGHTS 3.8.0 does not ("ERROR: Unknown command", measured one by one):
#: the pass leaves them as written, so LIGGGHTS stops where the deck's own run would (field round
#: 33, G28 G29: balance, a no-op in the pass, was answered where LIGGGHTS stops)
UNKNOWN_COMMANDS = frozenset({"python", "plugin", "bond_write", "angle_write", "dihedral_write", "write_coeff",
                              "timer", "group2ndx", "balance", "rerun", "message", "server", "mdi", "kim", "net",
                              "geturl", "fitpod", "region2vmd", "dynamical_matrix", "third_order"})


def _ending(root: Path) -> str:
    """The commands that write the atoms where the deck ends, into ``root``."""
    return f"write_dump all custom {root / ATOMS_AT_END} id type radius mass {_FORMAT}\n"


def _cleared_at_end(echo: str, root: Path) -> bool:
    """Whether LIGGGHTS stopped on the end's dump of the atoms (:func:`_ending`, into ``root``) after
    the deck's last box was cleared (a ``clear`` echoed after every command that makes a box), so
    that nothing is left to write: after ``clear`` the atom style has no radius and there is no box.

    Examples
    --------
    >>> end = _ending(Path("/s")).strip()
    >>> _cleared_at_end(f"create_box 1 r\\nrun 1\\nclear\\n{end}\\nERROR: Dumping an atom property that "
    ...                 "isn't allocated", Path("/s"))
    True

    A box made after the ``clear``, or a stop elsewhere, is the deck's own:

    >>> _cleared_at_end(f"clear\\ncreate_box 1 r\\n{end}\\nERROR: Invalid atom property", Path("/s"))
    False
    >>> _cleared_at_end("clear\\nread_data x\\nERROR: Cannot open file x", Path("/s"))
    False
    """
    lines = echo.split("\nERROR", 1)[0].splitlines() if "\nERROR" in echo else []
    if not lines or lines[-1].strip() != _ending(root).strip():
        return False
    firsts = [ln.split()[0] for ln in lines[:-1] if ln.split()]
    return next((w for w in reversed(firsts) if w in ("clear", "create_box", "read_data", "read_restart")), None) \
        == "clear"


def run_copy(deck: Path, root: Path, budget: float, original: Path | None = None,
             check_every: bool = True, tag: str | None = None,
             ceiling: float | None = None, real: bool = False) -> EngineRun:
    """Run the scratch copy ``deck`` in LIGGGHTS, each run of one step (with ``real``, as the deck
    has it: its markers then those of ``marker(root, real=True)``), within ``budget`` seconds in
    a loop and ``ceiling`` in all (:func:`~restitution.dem.dialect.child.run_child`; ``tag`` the
    scratch copy's; every marker runs its step and writes the atoms: ``check_every`` is always so here).

    The contract: :class:`~restitution.dem.dialect.child.DeckRun`.
    """
    # the deck included, then the end's atoms: a deck that jumps to another file never reaches
    # the include appended to its own
    driver = root / "driver"
    driver.write_text(f"include {deck}\n{_ending(root)}")
    env = engine_environment(root)
    # its screen is its standard output, line-buffered (stdbuf): an error that aborts MPI loses what
    # a -screen file still held in its buffer, the echo of the command it stopped on with it
    argv = ["liggghts", "-echo", "screen", "-log", "none", "-nocite", "-in", str(driver)]
    stdbuf = shutil.which("stdbuf")
    for _ in range(1 + MPI_START_RETRIES):
        # a pass made again (the runs made for real) starts afresh: its reads' accounts are its own
        for name in (ATOMS, ATOMS_AT_END, RESTART_INFO):
            (root / name).unlink(missing_ok=True)
        done = run_child([stdbuf, "-oL", *argv] if stdbuf else argv, deck.parent, env, root, budget,
                         screen_is_stdout=True, original=original, tag=tag, ceiling=ceiling)
        # Open MPI's singleton start fails now and then under load, before LIGGGHTS reads a line
        if not (done.status and MPI_NOT_STARTED in done.echo + done.error):
            break
    # LIGGGHTS' quit ends with status 1 and no message: after its marker wrote the atoms where the
    # deck ends, no ERROR on the screen, it is the deck's end, no error
    quit = (root / ATOMS_AT_END).exists() and not any(ln.startswith("ERROR") for ln in done.echo.splitlines())
    if done.status and not done.timed_out and not quit:
        # the deck ran to its end, its last box cleared (field round 45, M02, R12-R19): the end's
        # dump has no atoms to write, and its stop is the audit's own, not the deck's (as LAMMPS'
        # child, which writes no atoms where there is no box); else LIGGGHTS writes its ERROR to
        # the screen file, and ends with status 1
        done.error = "" if _cleared_at_end(done.echo, root) else \
            next((ln for ln in reversed(done.echo.splitlines()) if ln.startswith("ERROR")), "") \
            or done.error or f"LIGGGHTS ended with status {done.status}"
    return done
