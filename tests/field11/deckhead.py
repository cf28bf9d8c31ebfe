"""Head-on check through the deck itself (LAMMPS): the deck's lines up to its first
`run` are run by LAMMPS as written (so read_data, offsets, labels, includes are the
engine's), then its atoms are deleted and two spheres of the types asked are made
head-on, touching, with the sizes and densities given, and run at contact time / N
for N in 1000..8000; eps = relative normal velocity after / before, extrapolated to
dt -> 0 (Richardson, first order, on the two finest).
usage: python deckhead.py DECKDIR DECK T1 D1 RHO1 T2 D2 RHO2 G TC_GUESS
"""
import math, os, shutil, sys, tempfile
import lammps

def one(lines, t1, d1, r1, t2, d2, r2, g, dt, nmax):
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    for c in lines:
        l.command(c)
    m1 = math.pi / 6 * d1 ** 3 * r1; m2 = math.pi / 6 * d2 ** 3 * r2
    lo = l.extract_box()[0]; hi = l.extract_box()[1]
    cx = [(a + b) / 2 for a, b in zip(lo, hi)]
    cmds = ["delete_atoms group all", "atom_modify sort 0 0",
            f"create_atoms {t1} single {cx[0]-d1/2} {cx[1]} {cx[2]} units box",
            f"create_atoms {t2} single {cx[0]+d2/2} {cx[1]} {cx[2]} units box",
            "variable i1 equal 0", "group ga id 1", "group gb id 2",
            f"set group ga diameter {d1} density {r1}", f"set group gb diameter {d2} density {r2}",
            "velocity all set 0 0 0", f"velocity ga set {g*m2/(m1+m2)} 0 0", f"velocity gb set {-g*m1/(m1+m2)} 0 0",
            "unfix grav" if l.has_id("fix", "grav") else "print x", f"timestep {dt}",
            "variable d equal xcm(gb,x)-xcm(ga,x)", f"variable st equal v_d>{(d1+d2)/2}",
            "fix h all halt 1 v_st == 1 error continue", "thermo 0", f"run {nmax}"]
    for c in cmds:
        l.command(c)
    v = l.numpy.extract_atom("v"); ids = l.numpy.extract_atom("id")
    vx = {int(i): v[k][0] for k, i in enumerate(ids)}
    n = l.get_thermo("step"); l.close()
    return (vx[2] - vx[1]) / g, n

def main():
    d, deck, t1, d1, r1, t2, d2, r2, g, tc = sys.argv[1:]
    t1, t2 = int(t1), int(t2); d1, r1, d2, r2, g, tc = map(float, (d1, r1, d2, r2, g, tc))
    tmp = tempfile.mkdtemp(); shutil.copytree(d, tmp, dirs_exist_ok=True); cwd = os.getcwd(); os.chdir(tmp)
    lines = []
    for ln in open(deck).read().replace("&\n", " ").splitlines():
        if ln.split()[:1] == ["run"]:
            break
        lines.append(ln)
    vals = []
    for N in (1000, 2000, 4000, 8000):
        e, n = one(lines, t1, d1, r1, t2, d2, r2, g, tc / N, 40 * N); vals.append(e)
    os.chdir(cwd); shutil.rmtree(tmp)
    r1x = 2 * vals[2] - vals[1]; r2x = 2 * vals[3] - vals[2]
    print(f"types {t1} {t2} g {g}: engine through the deck {r2x:.8f} (wobble {abs(r2x-r1x):.1e}; from {', '.join('%.8f' % v for v in vals)})")

main()
