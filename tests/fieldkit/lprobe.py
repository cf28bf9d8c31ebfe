"""Probes in LIGGGHTS: the eps LIGGGHTS itself gives with the contact settings a deck leaves it holding. The deck is
run to its end in a scratch copy (byte for byte), its atoms deleted, then the probe's spheres made and run at dt
1e-7 s. Needs `atom_modify map array` in the deck. No import from the project.

`pair` (lprobeNN.py): two spheres made touching far above the walls at relative speed G along x, run 20000 steps
(they part long before), eps = (vx2 - vx1)/G. With ``chunks=True`` (lprobeNNs.py) the run is made in chunks of 10
steps until they part (at most 20000). PROBE_FILE (env): the file the probe is appended to (default the deck).
usage: python lprobeNN.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [Z]

`wall` (lwprobeNN.py): the deck's zplane-0 wall: its gravity fix (ID given) removed, one sphere of the type asked for
made touching z = 0 from above moving at -G, run 20000 steps (it leaves long before), eps = vz / G.
usage: python lwprobeNN.py DECKDIR T D RHO GRAVID [G]

`round`, `var` and `tag` as in fieldkit.probe.
"""
import os
import shutil

from fieldkit import scratch


def _finish(d, words, tmp, deck, top, tag):
    p = scratch.run("liggghts", tmp, deck, errors="replace")
    print(scratch.name(d), *words, *[l for l in p.stdout.splitlines() if l.startswith(tag) or "ERROR" in l][:3])
    shutil.rmtree(top)


def pair(argv, *, round, var, tag, chunks=False):
    """Run the LIGGGHTS head-on probe for command line `argv` (see the module's usage) and print its line."""
    d, t1, t2, d1, r1, d2, r2 = argv[0:7]
    g = float(argv[7]) if len(argv) > 7 else 1.0
    z = argv[8] if len(argv) > 8 else "0.1"
    deck, top, tmp = scratch.copy(d, round, "lprobe")
    v = var
    m1 = float(r1) * float(d1) ** 3; m2 = float(r2) * float(d2) ** 3
    v1, v2 = g * m2 / (m1 + m2), -g * m1 / (m1 + m2)
    run = "run 20000\n"
    if chunks:  # stop at parting: a long run on would let the deck's walls or fixes touch them again
        run = f"""variable f26d equal x[2]-x[1]-{(float(d1) + float(d2)) / 2}
variable f26n loop 2000
label f26l
run 10
if "${{f26d}} > 0" then "jump SELF f26out"
next f26n
jump SELF f26l
label f26out
"""
    tail = f"""
delete_atoms group all
create_atoms {t1} single {-float(d1) / 2} 0 {z} units box
create_atoms {t2} single {float(d2) / 2} 0 {z} units box
group {v}a1 id 1
group {v}a2 id 2
set group {v}a1 diameter {d1} density {r1}
set group {v}a2 diameter {d2} density {r2}
velocity {v}a1 set {v1} 0 0
velocity {v}a2 set {v2} 0 0
timestep 1e-7
thermo 0
{run}variable {v}e equal (vx[2]-vx[1])/{g}
print "{tag} eps ${{{v}e}}"
"""
    scratch.append(tmp, os.environ.get("PROBE_FILE", deck), tail)  # PROBE_FILE: where the deck ends, a file it jumps to
    _finish(d, (t1, t2), tmp, deck, top, tag)


def wall(argv, *, round, var, tag):
    """Run the LIGGGHTS floor probe for command line `argv` (see the module's usage) and print its line."""
    d, t, dia, rho, grav = argv[0:5]
    g = float(argv[5]) if len(argv) > 5 else 1.0
    deck, top, tmp = scratch.copy(d, round, "lwprobe")
    v = var
    r = float(dia) / 2
    tail = scratch.one_sphere(grav, t, f"0 0 {r}", v, dia, rho, group="id 1") + f"""velocity {v}a set 0 0 {-g}
timestep 1e-7
thermo 0
run 20000
variable {v}e equal vz[1]/{g}
print "{tag} wall eps ${{{v}e}}"
"""
    scratch.append(tmp, deck, tail)
    _finish(d, ("wall", t), tmp, deck, top, tag)
