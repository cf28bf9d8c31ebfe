"""Field round 12: head-on in LIGGGHTS 3.8.0 with type 1 under nve/sphere and type 2 under the deck's
`fix move ...` line (the round-10 referee always integrates every atom with nve/sphere, so it cannot hold
this deck's integrators). No import from the project. Two spheres r 3 mm, density 2500, hertz, e(1,2) 0.5,
touching at t = 0, relative speed 1 m/s (momentum zero), eps = relative separation speed / 1 at the first
step without overlap, at contact time / 1000 .. 8000, extrapolated to dt -> 0 (Richardson on the finest two).
usage: python liggghts_headon_move.py "fix mv t2 move linear NULL NULL NULL"
"""
import os, subprocess, sys, tempfile

MOVE = sys.argv[1]
HEAD = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 2 reg
neighbor 0.0006 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.5 0.5 0.4
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
create_atoms 1 single -0.003 0 0 units box
create_atoms 2 single 0.003 0 0 units box
set type 1 diameter 0.006 density 2500
set type 2 diameter 0.006 density 2500
group t1 type 1
group t2 type 2
velocity t1 set 0.5 0 0 units box
velocity t2 set -0.5 0 0 units box
fix integr t1 nve/sphere
{move}
variable d equal x[2]-x[1]
variable vr equal vx[2]-vx[1]
timestep {dt}
thermo_style custom step v_d v_vr
thermo 1
thermo_modify format float %.17g norm no
run {n}
"""

def one(dt, n):
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "in.h"), "w").write(HEAD.format(move=MOVE, dt=dt, n=n))
        subprocess.run(["liggghts", "-in", "in.h", "-log", "log.h"], cwd=tmp, capture_output=True)
        rows = []
        started = False
        for ln in open(os.path.join(tmp, "log.h")):
            p = ln.split()
            if p[:1] == ["Step"]:
                started = True
                continue
            if started and len(p) == 3:
                try:
                    rows.append((int(p[0]), float(p[1]), float(p[2])))
                except ValueError:
                    pass
    for step, d, vr in rows[1:]:
        if d > 0.006:
            return vr, step
    return None, None

tc = 8.6e-4
vals = []
for N in (1000, 2000, 4000, 8000):
    e, s = one(tc / N, 3 * N)
    vals.append(e)
r1 = 2 * vals[2] - vals[1]; r2 = 2 * vals[3] - vals[2]
print(f"{MOVE}: eps {r2:.8f} (wobble {abs(r2 - r1):.1e}; dt->0 from {', '.join('%.8f' % v for v in vals)})")
