"""Field round 19: LIGGGHTS head-on against a held partner (L26: nve/sphere on type 1 only). A type-1 sphere (r1, rho1)
moves at g onto a type-2 sphere (r2, rho2) that no fix integrates, touching at t = 0; eps = -v1 after / g at the first
step the two no longer overlap; dt = tc/1000 ... tc/8000, Richardson on the two finest (as round 10's referee).
No import from the project. usage: python liggghts_held19.py G"""
import math, os, subprocess, sys, tempfile
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts  # noqa: E402  (the head and the Richardson step rounds 15-19 share)

g = float(sys.argv[1])
r1, rho1, r2, rho2 = 0.002, 2500.0, 0.003, 1500.0
HEAD = liggghts.head() + """neighbor 0.0004 bin
fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3
fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8
pair_style gran model hertz tangential history
pair_coeff * *
"""


def run(dt, n):
    txt = HEAD + (f"create_atoms 1 single {-r1} 0 0 units box\ncreate_atoms 2 single {r2} 0 0 units box\n"
                  f"set atom 1 diameter {2*r1} density {rho1}\nset atom 2 diameter {2*r2} density {rho2}\n"
                  "group a1 id 1\n" f"velocity a1 set {g} 0 0 units box\n"
                  "variable d equal x[2]-x[1]\nvariable v equal vx[1]\nfix integr a1 nve/sphere\n"
                  f"timestep {dt}\nthermo_style custom step v_d v_v\nthermo 1\nthermo_modify format float %.17g norm no\nrun {n}\n")
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "in.h"), "w").write(txt)
        subprocess.run(["liggghts", "-in", "in.h", "-log", "log.h"], cwd=tmp, capture_output=True)
        log = open(os.path.join(tmp, "log.h")).read().splitlines()
    rows, on = [], False
    for ln in log:
        if ln.strip().startswith("Step"):
            on = True; continue
        p = ln.split()
        if on and len(p) == 3:
            try: rows.append((int(p[0]), float(p[1]), float(p[2])))
            except ValueError: pass
    for s, d, v in rows[1:]:
        if d > r1 + r2:
            return -v / g, s
    return None, None


e, s = run(1e-7, 200000)
tc = s * 1e-7
vals = [run(tc / N, 40 * N)[0] for N in liggghts.LADDER]
a, b = liggghts.richardson(vals)
print(f"g {g}: LIGGGHTS held partner eps {b:.8f} (wobble {abs(b-a):.1e}; from {', '.join('%.8f' % v for v in vals)}) tc {tc:.4g}")
