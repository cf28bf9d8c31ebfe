"""Two spheres colliding head-on, or a sphere and a flat wall, in the real LAMMPS engine
(``pip install restitution[dem]``).

Used to check the dictionary of :mod:`restitution.dem.engines.lammps.contact` and the library's eps against the
engine DEM users run. LAMMPS advances contacts with velocity Verlet and evaluates the damping with
the half-step velocity, so its eps is first order in dt; :func:`lammps_eps_extrapolated` runs three
steps and removes the first- and second-order terms.

Its Examples need LAMMPS (``pip install restitution[dem]``), so the doctests skip them; the case
they run is hertz with tsuji damping (e = 0.5, limit_damping), whose eps is 0.6458 at g = 1.
"""

from __future__ import annotations

import ctypes
import math
import os
import sys

from ...extrapolate import richardson
from ...pair import Pair

__all__ = ["available", "lammps_eps", "eps_runs", "lammps_eps_extrapolated", "lammps_wall_eps", "lammps_cylinder_eps"]


def _load():
    """The PyPI wheel links against MPICH's libmpi from the ``mpich`` wheel, installed into the
    environment's lib/ where the loader does not look; loading it first by path makes the symbols
    available without LD_LIBRARY_PATH."""
    lib = os.path.join(sys.prefix, "lib", "libmpi.so.12")
    if os.path.exists(lib):
        ctypes.CDLL(lib, mode=ctypes.RTLD_GLOBAL)
    import lammps
    return lammps


def available() -> bool:
    """Whether LAMMPS' Python module and its shared library load (the ``dem`` extra).

    Returns
    -------
    bool
        True where ``import lammps`` succeeds (after the MPI library beside it is loaded).

    Examples
    --------
    >>> import importlib.util
    >>> available() <= (importlib.util.find_spec("lammps") is not None)
    True
    """
    try:
        _load()
    except (ImportError, OSError):
        return False
    return True


def _run(box: float, ntypes: int, bodies: str, contact: str, neighbor: float, dt: float, t_run: float,
         apart: str, units: str = "si"):
    """One run of atom_style sphere (in ``units``, SI by default) in a fixed box of half-width
    ``box``: ``bodies`` creates the atoms and sets their sizes and velocities, ``contact`` the
    granular lines; returns (x, v).

    The run ends at the first step at which the equal-style expression ``apart`` is positive (the
    bodies no longer touch, so no force changes a velocity after it), or after ``t_run``. Run on, a
    body that leaves fast would leave the fixed box, and LAMMPS would stop on a lost atom (make fuzz:
    spheres of 0.08 and 0.1 m radius meeting at 115 m/s); a box that grows with the run would make
    neighbour bins without end instead."""
    lammps = _load()
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.commands_string(f"""
units {units}
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block {-box} {box} {-box} {box} {-box} {box} units box
create_box {ntypes} box
{bodies}
{contact}
neighbor {neighbor!r} bin
neigh_modify every 1 delay 0 check no
fix integrate all nve/sphere
variable apart equal "{apart}"
fix apart all halt 1 v_apart > 0.0 error continue message no
timestep {dt!r}
""")
        lmp.command(f"run {int(math.ceil(t_run / dt))} post no")
        return lmp.numpy.extract_atom("x").copy(), lmp.numpy.extract_atom("v").copy()
    finally:
        lmp.close()


def lammps_eps(pair: Pair, pair_coeff: str, g: float, dt: float, t_run: float, types: tuple = (1, 1),
               ntypes: int = 1, style: str = "granular", units: str = "si") -> float:
    """eps = -(relative speed after) / g for one head-on collision at approach speed g.

    The spheres start touching (zero overlap) so that no partial first step biases the result;
    ``t_run`` must exceed the contact time (the run stops as soon as they have separated).
    ``pair_coeff`` may be a whole scene's lines for ``ntypes`` atom types, the two spheres of
    atom types ``types`` (a pair without its own line is left to LAMMPS' mixing). ``style``: the
    pair_style line's arguments (an older style such as gran/hooke/history with its coefficients).

    Parameters
    ----------
    pair : Pair
        The two spheres.
    pair_coeff : str
        The contact's LAMMPS lines (a pair_coeff line, or a scene's lines).
    g : float
        The approach speed.
    dt, t_run : float
        The time step and the longest run.
    types : tuple of int, optional
        The two spheres' atom types.
    ntypes : int, optional
        How many atom types the lines define.
    style : str, optional
        The pair_style line's arguments.
    units : str, optional
        LAMMPS' unit style of the run (sizes, speeds and times in it).

    Returns
    -------
    float
        eps as LAMMPS gives it at this dt (first order in dt).

    Raises
    ------
    RuntimeError
        Where LAMMPS stops on the lines.
    ArithmeticError
        Where the spheres have not separated by t_run.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> line = "pair_coeff * * hertz 1e6 0.5 damping tsuji tangential linear_nohistory 0 0 limit_damping"
    >>> round(lammps_eps(pair, line, 1.0, 1e-7, 6e-4), 3)  # doctest: +SKIP
    0.646
    """
    gap = pair.R1 + pair.R2
    rho = [m / (4.0 / 3.0 * math.pi * r ** 3) for m, r in ((pair.m1, pair.R1), (pair.m2, pair.R2))]
    v1 = g * pair.m2 / (pair.m1 + pair.m2)     # centre-of-mass frame
    v2 = -g * pair.m1 / (pair.m1 + pair.m2)
    x1 = -pair.R1 * 1.0
    x2 = x1 + gap
    x, v = _run(4.0 * gap, ntypes, f"""
create_atoms {types[0]} single {x1!r} 0 0 units box
create_atoms {types[1]} single {x2!r} 0 0 units box
set atom 1 diameter {2 * pair.R1!r} density {rho[0]!r}
set atom 2 diameter {2 * pair.R2!r} density {rho[1]!r}
velocity all set 0 0 0 units box
set atom 1 vx {v1!r}
set atom 2 vx {v2!r}""", f"pair_style {style}\n{pair_coeff}", 0.5 * gap, dt, t_run, f"x[2] - x[1] - {gap!r}",
             units)
    if x[1, 0] - x[0, 0] <= gap:
        raise ArithmeticError("the spheres had not separated at the end of the run")
    return float(-(v[0, 0] - v[1, 0]) / g)


def eps_runs(pair: Pair, cases: list) -> list[float]:
    """eps of each case (pair_coeff line, g, dt, t_run): the runner form every engine's has.

    Parameters
    ----------
    pair, cases
        The two spheres, and (pair_coeff lines, g, dt, t_run) per run: the form
        :attr:`restitution.dem.engine.Engine.runner` promises (:func:`lammps_eps` runs each).

    Returns
    -------
    list of float
        LAMMPS' eps of each run, in order.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> line = "pair_coeff * * hertz 1e6 0.5 damping tsuji tangential linear_nohistory 0 0 limit_damping"
    >>> [round(e, 3) for e in eps_runs(pair, [(line, 1.0, 1e-7, 6e-4), (line, 1.0, 2e-7, 6e-4)])]  # doctest: +SKIP
    [0.646, 0.646]
    """
    return [lammps_eps(pair, pair_coeff, g, dt, t_run) for pair_coeff, g, dt, t_run in cases]


def lammps_wall_eps(radius: float, density: float, lines: str, g: float, dt: float, t_run: float,
                    atom_type: int = 1, ntypes: int = 1, units: str = "si") -> float:
    """eps = (speed after) / g for one sphere of atom type ``atom_type`` hitting a flat wall at
    z = 0 head-on at speed g, starting at zero overlap. ``lines``: the pair style and coefficients
    and the wall's lines (a ``fix wall/gran`` at zplane 0.0 on a group holding the type), as a
    scene writes them.

    Parameters
    ----------
    radius, density : float
        The sphere's.
    lines : str
        The pair style, its coefficients and the wall's lines.
    g, dt, t_run
        As :func:`lammps_eps` takes them.
    atom_type, ntypes : int, optional
        The sphere's atom type and how many types the lines define.
    units : str, optional
        LAMMPS' unit style of the run.

    Returns
    -------
    float
        The sphere's z velocity over g at the first step it no longer touches the plane: eps as
        LAMMPS gives it at this dt.

    Raises
    ------
    RuntimeError
        Where LAMMPS stops on the lines.
    ArithmeticError
        Where after t_run the sphere's centre is still within one radius of the plane z = 0.

    Examples
    --------
    >>> line = "pair_coeff * * hertz 1e6 0.5 damping tsuji tangential linear_nohistory 0 0 limit_damping"
    >>> wall = (f"pair_style granular\\n{line}\\ngroup all_ type 1\\n"
    ...         f"fix floor all_ wall/gran granular {line.split(maxsplit=3)[3]} zplane 0.0 NULL")
    >>> 0.0 < lammps_wall_eps(0.001, 2500.0, wall, 1.0, 1e-7, 6e-4) < 1.0  # doctest: +SKIP
    True
    """
    x, v = _run(8.0 * radius, ntypes, f"""
create_atoms {atom_type} single 0 0 {radius!r} units box
set atom 1 diameter {2 * radius!r} density {density!r}
velocity all set 0 0 {-g!r} units box""", lines, 0.5 * radius, dt, t_run, f"z[1] - {radius!r}", units)
    if x[0, 2] <= radius:
        raise ArithmeticError("the sphere had not left the wall at the end of the run")
    return float(v[0, 2] / g)


def lammps_cylinder_eps(radius: float, density: float, lines: str, g: float, dt: float, t_run: float,
                        cylinder: float, outside: bool = False) -> float:
    """eps = (speed after) / g for one sphere of atom type 1 inside a ``fix wall/gran ... zcylinder
    R`` (R = ``cylinder``, its axis the z axis), hitting it head-on at speed g: the sphere starts
    touching it at zero overlap, at x = R - radius, moving outward along x. With ``outside``, at
    x = R + radius moving inward (onto a region's outer surface, as ``side out`` has it).

    Parameters
    ----------
    radius, density : float
        The sphere's (radius < cylinder).
    lines : str
        The pair style, its coefficients and the wall's lines.
    g, dt, t_run
        As :func:`lammps_eps` takes them.
    cylinder : float
        The zcylinder's radius, as the wall's line gives it (or the distance of any surface the
        sphere meets on the x axis).
    outside : bool, optional
        The sphere starts outside, moving toward the axis.

    Returns
    -------
    float
        Minus the sphere's x velocity over g at the first step it no longer touches the cylinder:
        eps as LAMMPS gives it at this dt.

    Raises
    ------
    RuntimeError
        Where LAMMPS stops on the lines.
    ArithmeticError
        Where after t_run the sphere's centre is still at x >= R - radius (touching the cylinder).

    Examples
    --------
    >>> line = "pair_coeff * * hertz/material 1e7 3e4 0.3 tangential linear_nohistory 0 0"
    >>> wall = (f"pair_style granular\\n{line}\\n"
    ...         f"fix drum all wall/gran granular {line.split(maxsplit=3)[3]} zcylinder 0.0075")
    >>> 0.0 < lammps_cylinder_eps(0.005, 2500.0, wall, 1.0, 1e-7, 3e-3, 0.0075) < 1.0  # doctest: +SKIP
    True
    """
    sign = -1.0 if outside else 1.0
    start = cylinder - sign * radius
    x, v = _run(max(2.0 * cylinder, cylinder + 3.0 * radius) if outside else 2.0 * cylinder, 1, f"""
create_atoms 1 single {start!r} 0 0 units box
set atom 1 diameter {2 * radius!r} density {density!r}
velocity all set {sign * g!r} 0 0 units box""", lines, 0.5 * radius, dt, t_run, f"{sign * start!r} - {sign!r} * x[1]")
    if sign * x[0, 0] >= sign * start:
        raise ArithmeticError("the sphere had not left the wall at the end of the run")
    return float(-sign * v[0, 0] / g)


def lammps_eps_extrapolated(pair: Pair, pair_coeff: str, g: float, t_c: float, steps: int = 4000,
                            types: tuple = (1, 1), ntypes: int = 1, style: str = "granular",
                            units: str = "si") -> tuple:
    """(eps extrapolated to dt = 0, the runs' eps at t_c/steps, /2 steps, /4 steps).

    eps(dt) = eps0 + a dt + b dt^2 (first order from the half-step damping, and a second-order
    part that dominates where the damping is weak at small overlap, e.g. tsuji's delta^(1/4)):
    two Richardson levels remove both. Overlap-rule tsuji contacts also carry a fractional-order
    term (the delta^(1/4) damping where the contact ends at delta = 0): 4000 steps keep it below 1e-6.

    Parameters
    ----------
    pair, pair_coeff, g
        As :func:`lammps_eps` takes them.
    t_c : float
        The contact time: the runs' steps are t_c / steps, / 2 steps and / 4 steps, each run 1.5 t_c.
    steps : int, optional
        Steps per contact of the coarsest run.
    types, ntypes, style, units
        As :func:`lammps_eps` takes them.

    Returns
    -------
    tuple of float
        (eps at dt = 0, the three runs' eps).

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> line = "pair_coeff * * hertz 1e6 0.5 damping tsuji tangential linear_nohistory 0 0 limit_damping"
    >>> round(lammps_eps_extrapolated(pair, line, 1.0, 4.1338e-4)[0], 5)  # doctest: +SKIP
    0.64584
    """
    dt = t_c / steps
    e1, e2, e4 = (lammps_eps(pair, pair_coeff, g, dt / k, 1.5 * t_c, types, ntypes, style, units) for k in (1, 2, 4))
    return richardson(e1, e2, e4, 1), e1, e2, e4     # orders dt and dt^2
