"""The engine as referee of a deck's own pair, the deck run AS WRITTEN (rounds 27, 28): nothing is put into the deck but
a print after its last line. No import from the project: the engine decides.

`main` (liveNN.py): the deck makes two spheres (groups lv1 on the left, lv2 on the right, along x, far above any wall)
approaching at relative speed 1 m/s from a gap timed so that they meet in the run named in the deck's LIVE file; the
line printed is (vx(lv2) - vx(lv1)) / 1 and the gap then (positive: they parted; SEP the touching distance, default
5 mm). A LIVE file naming WALL: one sphere (group lv1) on the floor z = 0, printed as the speed it left the floor
with, from its speed and height at the end (energy under gravity 9.81). LIVE_FILE (env): the file the print is
appended to (default the deck). Resolution: the decks use dt 1e-6 s, 360-900 steps per contact; the rounds'
controls give the step error.
usage: python liveNN.py DECKDIR ...

`public` (publiveNN.py, round 28): the deck's own pair in a public restitution deck (its PUBLIVE file: groups a b,
axis), LAMMPS only: prints (v_axis(b) - v_axis(a)) / 2, their approach speed at the start in in.restitution.
usage: python publiveNN.py DECKDIR ...

`round` names the scratch folder (/tmp/fieldNN-live.*, /tmp/fieldNN-pub.*), `var` the prefix of the variables the
print adds, `tag` the first word of the printed line.
"""
import os
import shutil

from fieldkit import scratch


def _tail(d, var, tag):
    """The print put after the deck's last line: the live pair's eps (or the floor sphere's speed) and its gap."""
    lig = os.path.exists(os.path.join(d, "LIGGGHTS"))
    sep = float(open(os.path.join(d, "SEP")).read()) if os.path.exists(os.path.join(d, "SEP")) else 0.005
    if "WALL" in open(os.path.join(d, "LIVE")).read():
        return lig, ('\nprint "' + tag + ' eps $(sqrt(vcm(lv1,z)^2+2*9.81*(xcm(lv1,z)-0.002)):%.6f) vz $(vcm(lv1,z):%.6f)'
                     ' h $(xcm(lv1,z)-0.002:%.6f) n $(count(all)) step $(step)"\n')
    if lig:
        return lig, (f'\nvariable {var}e equal vx[2]-vx[1]\nvariable {var}g equal x[2]-x[1]-{sep}\n'
                     f'print "{tag} eps ${{{var}e}} gap ${{{var}g}} n $(atoms)"\n')
    return lig, (f'\nprint "{tag} eps $(vcm(lv2,x)-vcm(lv1,x):%.6f) gap $(xcm(lv2,x)-xcm(lv1,x)-{sep}:%.6f)'
                 f' n $(count(all)) step $(step)"\n')


def main(argv, *, round, var, tag):
    """Run each deck folder of `argv` as written with the live pair's print appended; print its lines."""
    for d in argv:
        deck, top, tmp = scratch.copy(d, round, "live")
        lig, tail = _tail(d, var, tag)
        scratch.append(tmp, os.environ.get("LIVE_FILE", deck), tail)
        p = scratch.run("liggghts" if lig else "lmp", tmp, deck, errors="replace", timeout=900)
        out = [l for l in p.stdout.splitlines() if l.startswith(tag) or "ERROR" in l][:3]
        print(scratch.name(d), *out, flush=True)
        shutil.rmtree(top)


def public(argv, *, round, tag="PUBLIVE"):
    """Run each public deck folder of `argv` as written with its own pair's print appended; print its lines."""
    for d in argv:
        a, b, ax = open(os.path.join(d, "PUBLIVE")).read().split()
        deck, top, tmp = scratch.copy(d, round, "pub")
        scratch.append(tmp, deck, f'\nprint "{tag} eps $((vcm({b},{ax})-vcm({a},{ax}))/2:%.6f) types $(count({a})) step $(step)"\n')
        p = scratch.run("lmp", tmp, deck, errors="replace", timeout=1800)
        out = [l for l in p.stdout.splitlines() if l.startswith(tag) or "ERROR" in l][:3]
        print(scratch.name(d), *out, flush=True)
        shutil.rmtree(top)
