"""Two spheres colliding head-on, or a sphere and a flat wall, in the real LIGGGHTS engine (Debian
package ``liggghts``).

One input file holds every requested collision, separated by LIGGGHTS' ``clear`` (the engine takes
about a second to start); each run prints its final velocities on a marked line, read back here.
LIGGGHTS integrates like LAMMPS (fix nve/sphere: velocity Verlet, the force from the half-step
velocity), so eps is first order in dt: :func:`liggghts_eps_extrapolated` runs three steps and
removes the two leading orders (restitution.dem.extrapolate).

Its Examples need LIGGGHTS (``apt-get install liggghts``), so the doctests skip them; the case
they run is hertz with e = 0.9 and limitForce off, whose eps is e.
"""

from __future__ import annotations

import math
import shutil
import subprocess
import tempfile
from pathlib import Path

from ...engine import EngineProcess
from ...extrapolate import eps_extrapolated
from ...pair import Pair
from .contact import LIGGGHTS_MODEL_TYPES

__all__ = ["available", "liggghts_pair_style", "PROCESS", "liggghts_eps_runs", "eps_runs", "liggghts_states", "liggghts_eps_extrapolated",
           "liggghts_wall_eps_runs"]

_MARK = "RESTITUTION-RESULT"


def liggghts_pair_style(*, model: str, E: float, nu: float, e: float, limit_force: bool,
                        characteristic_velocity: float | None = None, E2: float | None = None,
                        nu2: float | None = None) -> str:
    """The box, material and pair_style lines of a LIGGGHTS deck for that contact model (one atom
    type, or two when the second sphere has its own E2, nu2; e for every pair), frictionless and
    with no tangential model (head-on contacts need none).

    Parameters
    ----------
    model, E, nu, e, limit_force, characteristic_velocity, E2, nu2
        As :func:`~restitution.dem.engines.liggghts.contact.liggghts_contact` takes them.

    Returns
    -------
    str
        The lines, joined by newlines.

    Examples
    --------
    >>> print(liggghts_pair_style(model="hertz", E=5e6, nu=0.45, e=0.9, limit_force=False))
    create_box 1 box
    fix m1 all property/global youngsModulus peratomtype 5000000.0
    fix m2 all property/global poissonsRatio peratomtype 0.45
    fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
    fix m4 all property/global coefficientFriction peratomtypepair 1 0.0
    pair_style gran model hertz tangential no_history limitForce off
    pair_coeff * *
    """
    two = E2 is not None
    n = 2 if two else 1
    lines = [f"create_box {n} box",
             f"fix m1 all property/global youngsModulus peratomtype {E!r}" + (f" {E2!r}" if two else ""),
             f"fix m2 all property/global poissonsRatio peratomtype {nu!r}" + (f" {nu2!r}" if two else ""),
             f"fix m3 all property/global coefficientRestitution peratomtypepair {n} " + " ".join([repr(e)] * n * n),
             f"fix m4 all property/global coefficientFriction peratomtypepair {n} " + " ".join(["0.0"] * n * n)]
    if model == "hooke":
        lines.append(f"fix m5 all property/global characteristicVelocity scalar {characteristic_velocity!r}")
    lines.append(f"pair_style gran model {model} tangential no_history limitForce {'on' if limit_force else 'off'}")
    lines.append("pair_coeff * *")
    return "\n".join(lines)


def _run_block(pair: Pair, contact_lines: str, g: float, dt: float, steps: int, tag: int,
               types: tuple | None = None) -> str:
    gap = pair.R1 + pair.R2
    box = 4.0 * gap
    rho = [m / (4.0 / 3.0 * math.pi * r ** 3) for m, r in ((pair.m1, pair.R1), (pair.m2, pair.R2))]
    v1 = g * pair.m2 / (pair.m1 + pair.m2)     # centre-of-mass frame
    v2 = -g * pair.m1 / (pair.m1 + pair.m2)
    second = 2 if contact_lines.startswith("create_box 2") else 1   # the second sphere's atom type
    first, second = types if types is not None else (1, second)
    # LIGGGHTS stops unless the atom types start from 1: a pair of other types gets a resting
    # sphere of type 1 off the collision's axis, out of reach of both (3 gap away, radius R1 / 2)
    bystander = "" if 1 in (first, second) else f"""
create_atoms 1 single 0 {3 * gap!r} 0 units box
set atom 3 diameter {pair.R1!r} density {rho[0]!r}"""
    # touching at zero overlap: no partial first step biases the result
    return _prologue(box, contact_lines, 0.5 * gap, dt) + f"""
create_atoms {first} single {-pair.R1!r} 0 0 units box
create_atoms {second} single {pair.R2!r} 0 0 units box
set atom 1 diameter {2 * pair.R1!r} density {rho[0]!r}
set atom 2 diameter {2 * pair.R2!r} density {rho[1]!r}{bystander}
set atom 1 vx {v1!r}
set atom 2 vx {v2!r}
fix integr all nve/sphere
variable rel equal vx[1]-vx[2]
variable gap equal x[2]-x[1]
""" + _epilogue(steps, tag)


def _prologue(box: float, contact_lines: str, neighbor: float, dt: float) -> str:
    # The box shrink-wraps (boundary m, at least the box given): a fixed one lets a sphere leave it,
    # and LIGGGHTS drops such an atom without a word, its velocity then reading 0 (make fuzz found
    # eps = 0.239 reported for a contact of eps 0.871, the lighter sphere gone after a deep overlap);
    # one as large as the whole run's travel would make neighbour bins without end on long runs
    return f"""
atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
region box block {-box!r} {box!r} {-box!r} {box!r} {-box!r} {box!r} units box
{contact_lines}
neighbor {neighbor!r} bin
neigh_modify delay 0
timestep {dt!r}"""


def _epilogue(steps: int, tag: int) -> str:
    """Run, then print the variables rel and gap and the atom count before and after."""
    return f"""variable n equal atoms
variable n0 equal ${{n}}
thermo {steps}
run {steps}
print "{_MARK} {tag} ${{rel}} ${{gap}} ${{n0}} ${{n}}"
clear
"""


def _ends(pair: Pair, cases: list, timeout: float) -> list[tuple]:
    return [(rel, centres - pair.R1 - pair.R2) for rel, centres in liggghts_states(pair, cases, timeout)]


#: How LIGGGHTS runs collisions (restitution.dem.engine.EngineProcess): its eps_runs is the runner
#: form every engine's has (restitution.dem.engine.Engine.runner), LIGGGHTS' cases already in it
PROCESS = EngineProcess("LIGGGHTS", "(contact_lines, g, dt, t_run[, types])", 1, _ends, program="liggghts")
liggghts_eps_runs = eps_runs = PROCESS.eps_runs
available = PROCESS.available


def liggghts_states(pair: Pair, cases: list, timeout: float = 600.0) -> list[tuple]:
    """(relative velocity v1 - v2, centre distance) at the end of each case (contact_lines, g, dt,
    t_run[, types]), in one LIGGGHTS process; ``types``: the two spheres' atom types when
    contact_lines (starting with create_box N) define more than two.

    Parameters
    ----------
    pair, cases, timeout
        The two spheres, the cases as :data:`PROCESS` describes them (``types``: the two
        spheres' atom types when the contact lines define more), and the seconds LIGGGHTS may take.

    Returns
    -------
    list of tuple
        (v1 - v2, centre distance) per run, as LIGGGHTS holds them at the run's last step.

    Raises
    ------
    RuntimeError
        Where LIGGGHTS stops on the lines.

    Examples
    --------
    >>> pair = Pair.spheres(0.0025, 0.0025, 2500.0)
    >>> lines = liggghts_pair_style(model="hertz", E=5e6, nu=0.45, e=0.9, limit_force=False)
    >>> ((rel, gap),) = liggghts_states(pair, [(lines, 1.0, 3e-7, 1e-3)])  # doctest: +SKIP
    >>> round(-rel, 2), gap > 0.005  # doctest: +SKIP
    (0.9, True)
    """
    return _run([_run_block(pair, case[0], case[1], case[2], int(math.ceil(case[3] / case[2])), i, *case[4:])
                 for i, case in enumerate(cases)], timeout)


def _wall_line(contact_lines: str, wall_type: int) -> str:
    """A flat wall at z = 0 of atom type ``wall_type`` with the contact model of the deck's
    ``pair_style gran`` line: its model_type/name pairs first, the plane, then the model keywords
    (limitForce, ...), the order fix wall/gran demands."""
    words = next((ln.split()[2:] for ln in contact_lines.splitlines() if ln.startswith("pair_style gran")), None)
    if words is None:
        raise ValueError("the contact lines have no pair_style gran line: the wall's model is unknown")
    k = 0
    while k + 1 < len(words) and words[k] in LIGGGHTS_MODEL_TYPES:
        k += 2
    return (f"fix wall all wall/gran {' '.join(words[:k])} primitive type {wall_type} zplane 0.0 "
            + " ".join(words[k:])).rstrip()


def _wall_block(radius: float, density: float, contact_lines: str, g: float, dt: float, steps: int, tag: int,
                atom_type: int, wall_type: int, wall: str | None = None) -> str:
    # a resting type-1 sphere out of reach where the falling one has another type (types must start
    # from 1, see _run_block); the falling one starts touching the plane
    bystander = "" if atom_type == 1 else f"""
create_atoms 1 single {4 * radius!r} {4 * radius!r} {4 * radius!r} units box
set atom 2 diameter {radius!r} density {density!r}"""
    return _prologue(8.0 * radius, contact_lines, 0.5 * radius, dt) + f"""
{_wall_line(contact_lines, wall_type) if wall is None else wall}
create_atoms {atom_type} single 0 0 {radius!r} units box
set atom 1 diameter {2 * radius!r} density {density!r}{bystander}
set atom 1 vz {-g!r}
fix integr all nve/sphere
variable rel equal vz[1]
variable gap equal z[1]
""" + _epilogue(steps, tag)


def liggghts_wall_eps_runs(radius: float, density: float, cases: list, timeout: float = 600.0,
                           wall: str | None = None, files: dict | None = None) -> list[float]:
    """eps = (speed after) / g of a sphere falling head-on at speed g onto a flat wall, for each case
    (contact_lines, g, dt, t_run, atom_type, wall_type) in one LIGGGHTS process: contact_lines are a
    scene's (create_box N and its fix property/global and pair_style lines), the wall has atom type
    wall_type and the deck's contact model. ``wall``: the wall's lines instead (a deck's own, a
    flat surface at z = 0 with the fix ID wall), ``files``: {name: text} they read (a mesh).

    Parameters
    ----------
    radius, density : float
        The sphere's.
    cases : list of tuple
        (contact_lines, g, dt, t_run, atom_type, wall_type) per run.
    timeout : float, optional
        Seconds LIGGGHTS may take.
    wall : str, optional
        The deck's own wall lines instead of a wall of type wall_type.
    files : dict, optional
        {name: text} of the files the wall lines read.

    Returns
    -------
    list of float
        The sphere's eps on the wall (speed after / g), per run.

    Raises
    ------
    RuntimeError
        Where LIGGGHTS stops.
    ArithmeticError
        Where the sphere has not left the wall.

    Examples
    --------
    >>> lines = liggghts_pair_style(model="hertz", E=5e6, nu=0.45, e=0.9, limit_force=False, E2=5e6, nu2=0.45)
    >>> [round(e, 2) for e in liggghts_wall_eps_runs(0.0025, 2500.0, [(lines, 1.0, 1e-7, 1e-3, 1, 2)])]  # doctest: +SKIP
    [0.9]
    """
    states = _run([_wall_block(radius, density, case[0], case[1], case[2], int(math.ceil(case[3] / case[2])), i,
                               case[4], case[5], wall) for i, case in enumerate(cases)], timeout, files)
    if any(z <= radius for _, z in states):
        raise ArithmeticError("the sphere had not left the wall at the end of the LIGGGHTS run")
    return [v / case[1] for case, (v, _) in zip(cases, states)]


#: Open MPI's singleton start can fail before LIGGGHTS reads a line, when many processes start at
#: once (make fuzz saw it once in some 500 runs); such a run is started again, this many times.
MPI_START_RETRIES = 2
MPI_NOT_STARTED = "Unable to start a daemon on the local node"


def _run(blocks: list[str], timeout: float, files: dict | None = None) -> list[tuple]:
    """Run the blocks in one LIGGGHTS process, ``files`` ({name: text}) beside the input; each
    block's printed (rel, gap)."""
    # errors="replace": a failing LIGGGHTS can print stray bytes; its message must still reach the user
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in (files or {}).items():
            (Path(tmp) / name).write_text(text)
        path = Path(tmp) / "in.collide"
        path.write_text("".join(blocks))
        # line-buffered: LIGGGHTS ends an error with MPI_Abort, which drops what a pipe still
        # buffers, its ERROR line among it (coreutils' stdbuf; without it the message is the abort's)
        line = ["stdbuf", "-oL"] if shutil.which("stdbuf") else []
        for _ in range(1 + MPI_START_RETRIES):
            proc = subprocess.run([*line, "liggghts", "-in", str(path), "-echo", "none", "-log", "none"],
                                  cwd=tmp, capture_output=True, text=True, errors="replace", timeout=timeout,
                                  stdin=subprocess.DEVNULL)
            if not (proc.returncode and MPI_NOT_STARTED in proc.stdout + proc.stderr):
                break
    found, lost = {}, []
    for ln in proc.stdout.splitlines():
        if ln.startswith(_MARK):
            _, tag, rel, gap, before, after = ln.split()
            found[int(tag)] = (float(rel), float(gap))
            if float(after) != float(before):
                lost.append(int(tag))
    if lost:
        raise RuntimeError(f"liggghts lost atoms from the box in run(s) {lost}: no eps from them")
    if proc.returncode != 0 or len(found) != len(blocks):
        raise RuntimeError(f"liggghts failed (status {proc.returncode}): {(proc.stdout + proc.stderr).strip()[-2000:]}")
    return [found[i] for i in range(len(blocks))]


def liggghts_eps_extrapolated(pair: Pair, contact_lines: str, speeds, t_c: dict, gamma, steps: int = 2000) -> dict:
    """{g: (eps extrapolated to dt = 0, eps at t_c/steps, /2, /4)} for one setting at each speed,
    all in one LIGGGHTS process; t_c maps each speed to its contact time, gamma is the damping
    exponent (the extrapolation's orders, see restitution.dem.extrapolate).

    Parameters
    ----------
    pair : Pair
        The two spheres.
    contact_lines : str
        The setting's lines (:func:`liggghts_pair_style`).
    speeds : iterable of float
        Approach speeds.
    t_c : dict
        {g: contact time}: the runs' steps are t_c / steps, / 2 steps and / 4 steps.
    gamma
        The damping exponent.
    steps : int, optional
        Steps per contact of the coarsest run.

    Returns
    -------
    dict
        {g: (eps at dt = 0, LIGGGHTS' eps at the three steps)}.

    Examples
    --------
    >>> pair = Pair.spheres(0.0025, 0.0025, 2500.0)
    >>> lines = liggghts_pair_style(model="hertz", E=5e6, nu=0.45, e=0.9, limit_force=False)
    >>> round(liggghts_eps_extrapolated(pair, lines, [1.0], {1.0: 6.4515e-4}, "1/4")[1.0][0], 4)  # doctest: +SKIP
    0.9
    """
    return eps_extrapolated(liggghts_eps_runs, pair, contact_lines, speeds, t_c, gamma, steps)
