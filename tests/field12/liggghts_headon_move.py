"""Field round 12: head-on in LIGGGHTS 3.8.0 through a deck's own set-up, with type 1 under nve/sphere and
type 2 under a given `fix move ...` line (the round-10 referee always integrates every atom with nve/sphere, so
it cannot hold such a deck's integrators). No import from the project.

The deck's lines up to its first `create_atoms` (box, materials, pair style) are LIGGGHTS' own; then two
spheres r 3 mm, density 2500, types 1 and 2, touch at t = 0 with relative speed 1 m/s (momentum zero); eps is
the relative separation speed / 1 at the first step without overlap, at contact time / 1000 .. 8000,
extrapolated to dt -> 0 (Richardson on the two finest).
usage: python liggghts_headon_move.py DECK "fix mv t2 move linear NULL NULL NULL" [TC]
"""
import os, subprocess, sys, tempfile

DECK, MOVE = sys.argv[1], sys.argv[2]
TC = float(sys.argv[3]) if len(sys.argv) > 3 else 8.6e-4
SETUP = []
for ln in open(DECK).read().replace("&\n", " ").splitlines():
    if ln.split()[:1] == ["create_atoms"]:
        break
    SETUP.append(ln)
HEADON = """create_atoms 1 single -0.003 0 0 units box
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
        text = "\n".join(SETUP) + "\n" + HEADON.format(move=MOVE, dt=dt, n=n)
        open(os.path.join(tmp, "in.h"), "w").write(text)
        subprocess.run(["liggghts", "-in", "in.h", "-log", "log.h"], cwd=tmp, capture_output=True)
        rows, started = [], False
        for ln in open(os.path.join(tmp, "log.h")):
            p = ln.split()
            if p[:1] == ["Step"]:
                started = True
            elif started and len(p) == 3:
                try:
                    rows.append((int(p[0]), float(p[1]), float(p[2])))
                except ValueError:
                    pass
    for step, d, vr in rows[1:]:
        if d > 0.006:
            return vr
    return None


vals = [one(TC / N, 3 * N) for N in (1000, 2000, 4000, 8000)]
r1 = 2 * vals[2] - vals[1]
r2 = 2 * vals[3] - vals[2]
print(f"{MOVE}: eps {r2:.8f} (wobble {abs(r2 - r1):.1e}; dt->0 from {', '.join('%.8f' % v for v in vals)})")
