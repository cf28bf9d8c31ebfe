"""Wall probes in LAMMPS: the eps LAMMPS itself gives one sphere on a deck's wall with the contact settings the deck
leaves it holding. The deck is run to its end in a scratch copy, its atoms deleted, its gravity fix (ID given)
removed, one sphere of the type asked for made touching the wall, run at dt 1e-8 s (DT for `any_wall`) until it
leaves. No import from the project.

`floor` (wprobeNN.py): the zplane-0 floor, the sphere touching z = 0 from above at -g, until it leaves (z > r).
usage: python wprobeNN.py DECKDIR T D RHO GRAVID [G]

`curved` (wcprobe24.py): a curved wall (wall/gran zcylinder, wall/gran/region on a cylinder or sphere), the sphere made
touching it at (X, Y, Z), moving along x at speed G with sign S (+1 outward into a concave wall, -1 onto a convex one);
eps = -vx_after / vx_before.
usage: python wcprobeNN.py DECKDIR T D RHO GRAVID X Y Z S [G]

`any_wall` (wgprobeNN.py): any wall, the sphere made at X Y Z (where it just touches the wall, the caller computes it)
moving at speed G along -N (N the wall's normal into the domain, unit), until its centre is back past X Y Z along N
(step > 10); eps = v.N / G. GRAVID - removes none. PROBE_PRE, PROBE_MID, PROBE_FILE (env) as for probe.pair.
usage: python wgprobeNN.py DECKDIR T D RHO GRAVID X Y Z NX NY NZ [G] [DT]

`round`, `var` and `tag` as in fieldkit.probe; `steps` the run's length (rounds 21 and 22: 2e7).
"""
import os
import shutil

from fieldkit import scratch


def _finish(d, t, tmp, deck, top, tag, first=None):
    p = scratch.run("lmp", tmp, deck)
    print(scratch.name(d), "wall", t, *[l for l in p.stdout.splitlines() if l.startswith(tag) or "ERROR" in l][:first])
    shutil.rmtree(top)


def floor(argv, *, round, var, tag, steps="3000000"):
    """Run the floor probe for command line `argv` (see the module's usage) and print its line."""
    d, t, dia, rho, grav = argv[0:5]
    g = float(argv[5]) if len(argv) > 5 else 1.0
    deck, top, tmp = scratch.copy(d, round, "wprobe")
    v = var
    r = float(dia) / 2
    tail = scratch.one_sphere(grav, t, f"0.02 0.02 {r}", v, dia, rho) + f"""velocity all set 0 0 {-g}
variable {v}s equal (xcm({v}a,z)>{r})&&(step>10)
fix {v}h all halt 1 v_{v}s == 1 error continue
timestep 1e-8
thermo 0
run {steps}
print "{tag} wall eps $(vcm({v}a,z)/{g}:%.6f) steps $(step)"
"""
    scratch.append(tmp, deck, tail)
    _finish(d, t, tmp, deck, top, tag)


def curved(argv, *, round, var, tag):
    """Run the curved-wall probe for command line `argv` (see the module's usage) and print its line."""
    d, t, dia, rho, grav, x, y, z, s = argv[0:9]
    g = float(argv[9]) if len(argv) > 9 else 1.0
    deck, top, tmp = scratch.copy(d, round, "wcprobe")
    w = var
    v = float(s) * g
    tail = scratch.one_sphere(grav, t, f"{x} {y} {z}", w, dia, rho) + f"""velocity all set {v} 0 0 units box
variable {w}s equal ({float(s)}*(xcm({w}a,x)-{x})<0)&&(step>10)
fix {w}h all halt 1 v_{w}s == 1 error continue
timestep 1e-8
thermo 0
run 3000000
print "{tag} wall eps $(-vcm({w}a,x)/{v}:%.6f) steps $(step)"
"""
    scratch.append(tmp, deck, tail)
    _finish(d, t, tmp, deck, top, tag)


def any_wall(argv, *, round, var, tag):
    """Run the any-wall probe for command line `argv` (see the module's usage) and print its line."""
    d, t, dia, rho, grav, x, y, z, nx, ny, nz = argv[0:11]
    g = float(argv[11]) if len(argv) > 11 else 1.0
    dt = argv[12] if len(argv) > 12 else "1e-8"
    deck, top, tmp = scratch.copy(d, round, "wgprobe")
    v = var
    tail = "\n" + ("" if grav == "-" else f"unfix {grav}\n") + scratch.commands("PROBE_PRE") + f"""
delete_atoms group all
create_atoms {t} single {x} {y} {z} units box
group {v}a type {t}
set group {v}a diameter {dia} density {rho}
""" + scratch.commands("PROBE_MID") + f"""
velocity all set {-g * float(nx)} {-g * float(ny)} {-g * float(nz)} units box
variable {v}p equal (xcm({v}a,x)-({x}))*({nx})+(xcm({v}a,y)-({y}))*({ny})+(xcm({v}a,z)-({z}))*({nz})
variable {v}s equal (v_{v}p>0)&&(step>10)
fix {v}h all halt 1 v_{v}s == 1 error continue
timestep {dt}
thermo 0
run {os.environ.get("PROBE_STEPS", "3000000")}
print "{tag} wall eps $((vcm({v}a,x)*({nx})+vcm({v}a,y)*({ny})+vcm({v}a,z)*({nz}))/{g}:%.6f) steps $(step)"
"""
    scratch.append(tmp, os.environ.get("PROBE_FILE", deck), tail)
    _finish(d, t, tmp, deck, top, tag, first=3)
