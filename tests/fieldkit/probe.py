"""Head-on pair probes in LAMMPS: the eps LAMMPS itself gives a pair with the contact settings a deck leaves it holding.

`pair` (probeNN.py; gprobe24.py with ``gap=True``): the deck is run to its end in a scratch copy (nested so ../ stays
inside), then its atoms are deleted, two spheres of the types asked for are made far above any wall, touching, at
relative speed g along x, and run at dt = 1e-8 s until they part (at most PROBE_STEPS, default the round's `steps`,
3e6 = 0.03 s from round 23: 20 times the longest contact there; a pair still together then has stuck) (gravity moves
both alike; fixes of the deck stay). No import from the project: the engine decides. Resolution: at dt = 1e-8 s a
4 mm hooke contact (~5e-4 s) lasts ~5e4 steps, so the step error in eps is below 1e-4.
PROBE_MID (env): commands put after the two spheres are made (e.g. group t2 type 2, so a deck's fix on group t2 acts on them).
PROBE_FILE (env): the file the probe is appended to (default the deck; a file the deck jumps to and ends in).
PROBE_PRE (env): commands, ;-separated, put before the probe (e.g. unfix p for a fix pour that forbids a timestep change).
With ``gap=True`` (round 24's gprobe) the spheres start GAP apart (env GAP, default 0.002), so the pair must be found by
the deck's neighbor settings; parted = moving apart with no overlap; eps -1 = passed through.
usage: python probeNN.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [Z] [XC] [DT]

`approach` (aprobeNN.py): a pair that APPROACHES from a gap at the deck's own time step and neighbour settings (the
touching start of `pair` hides neighbour lists built late): two spheres GAP apart (centre line along x, far above the
walls), approaching at relative speed G; run STEPS steps at the deck's dt; eps = relative speed after / G, with the gap
then (positive: they parted).
usage: python aprobeNN.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [GAP] [STEPS] [Z]

Each round names its own: `round` (the scratch folder /tmp/fieldNN-probe.*), `var` (the prefix of the variables and
groups added to the deck, chosen not to meet the deck's own names) and `tag` (the first word of the printed line).
"""
import os
import shutil
import sys

from fieldkit import scratch


def _push(v, g):
    """The lines that set the pair (groups v+a1, v+a2) moving at relative speed g along x, centre of mass still."""
    return f"""variable {v}m1 equal mass({v}a1)
variable {v}m2 equal mass({v}a2)
velocity all set 0 0 0 units box
velocity {v}a1 set $({g}*v_{v}m2/(v_{v}m1+v_{v}m2)) 0 0 units box
velocity {v}a2 set $(-{g}*v_{v}m1/(v_{v}m1+v_{v}m2)) 0 0 units box
"""


def pair(argv, *, round, var, tag, steps="3000000", gap=False):
    """Run the head-on probe for command line `argv` (see the module's usage) and print its line."""
    d, t1, t2, d1, r1, d2, r2 = argv[0:7]
    g = float(argv[7]) if len(argv) > 7 else 1.0
    z = argv[8] if len(argv) > 8 else "0.05"
    xc = float(argv[9]) if len(argv) > 9 else 0.02
    dt = argv[10] if len(argv) > 10 else "1e-8"
    deck, top, tmp = scratch.copy(d, round, "probe")
    v = var
    x1, x2 = -float(d1) / 2, float(d2) / 2
    # parted: with a gap, moving apart with no overlap (a pass-through shows as eps -1); touching, apart after step 10
    parted = f"(v_{v}d>0)&&(step>10)"
    if gap:
        x2 += float(os.environ.get('GAP', '0.002'))
        parted = f"(v_{v}d>0)&&(vcm({v}a2,x)-vcm({v}a1,x)>0)"
    tail = "\n" + scratch.commands("PROBE_PRE") + f"""
delete_atoms group all
create_atoms {t1} single {xc + x1} {xc} {z} units box
create_atoms {t2} single {xc + x2} {xc} {z} units box
variable {v}n equal count(all)
variable {v}i1 equal $(v_{v}n-1)
variable {v}i2 equal $(v_{v}n)
group {v}a1 id ${{{v}i1}}
group {v}a2 id ${{{v}i2}}
set group {v}a1 diameter {d1} density {r1}
set group {v}a2 diameter {d2} density {r2}
""" + scratch.commands("PROBE_MID") + "\n" + _push(v, g) + f"""variable {v}d equal xcm({v}a2,x)-xcm({v}a1,x)-({float(d1) / 2 + float(d2) / 2})
variable {v}s equal {parted}
fix {v}h all halt 1 v_{v}s == 1 error continue
timestep {dt}
thermo 0
run {os.environ.get("PROBE_STEPS", steps)}
print "{tag} eps $((vcm({v}a2,x)-vcm({v}a1,x))/{g}:%.6f) steps $(step) m $(v_{v}m1) $(v_{v}m2)"
"""
    scratch.append(tmp, os.environ.get("PROBE_FILE", deck), tail)  # PROBE_FILE: where the deck ends, a file it jumps to
    if os.path.exists(os.path.join(d, "LIGGGHTS")):
        sys.exit("LAMMPS only")
    p = scratch.run("lmp", tmp, deck)
    out = [l for l in p.stdout.splitlines() if l.startswith(tag) or "ERROR" in l]
    print(scratch.name(d), t1, t2, *out)
    shutil.rmtree(top)


def approach(argv, *, round, var, tag):
    """Run the approaching-pair probe for command line `argv` (see the module's usage) and print its line."""
    d, t1, t2, d1, r1, d2, r2 = argv[0:7]
    g = float(argv[7]) if len(argv) > 7 else 1.0
    gap = float(argv[8]) if len(argv) > 8 else 0.002
    steps = argv[9] if len(argv) > 9 else "2000"
    z = argv[10] if len(argv) > 10 else "0.05"
    deck, top, tmp = scratch.copy(d, round, "aprobe")
    v = var
    x1 = 0.02 - float(d1) / 2 - gap / 2; x2 = 0.02 + float(d2) / 2 + gap / 2
    tail = "\n" + scratch.commands("PROBE_PRE") + f"""
delete_atoms group all
create_atoms {t1} single {x1} 0.02 {z} units box
create_atoms {t2} single {x2} 0.02 {z} units box
variable {v}n equal count(all)
group {v}a1 id $(v_{v}n-1)
group {v}a2 id $(v_{v}n)
set group {v}a1 diameter {d1} density {r1}
set group {v}a2 diameter {d2} density {r2}
""" + _push(v, g) + f"""thermo 0
run {steps}
print "{tag} eps $((vcm({v}a2,x)-vcm({v}a1,x))/{g}:%.6f) gap $(xcm({v}a2,x)-xcm({v}a1,x)-{(float(d1) + float(d2)) / 2}:%.6f)"
"""
    scratch.append(tmp, deck, tail)
    p = scratch.run("lmp", tmp, deck)
    print(scratch.name(d), t1, t2, *[l for l in p.stdout.splitlines() if l.startswith(tag) or "ERROR" in l][:3])
    shutil.rmtree(top)
