"""Referee for a sphere meeting a LIGGGHTS floor mesh moved by `fix move/mesh ... linear/variable`
with vz = A w sin(w t): eps from the normal speed relative to the floor before and after the contact.
Independent of the project's code.

Usage: python vibrating_face.py DECKDIR --A 0.05 --w 1000 --t0 0.0 --g 0.1 --dt 1e-7
(t0: the time at which the sphere is released just above the floor)
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import tempfile

ap = argparse.ArgumentParser()
ap.add_argument("deckdir")
ap.add_argument("--V", type=float, default=0.05, help="velocity amplitude of the floor")
ap.add_argument("--w", type=float, default=1000.0)
ap.add_argument("--t0", type=float, nargs="+", default=[0.0])
ap.add_argument("--g", type=float, default=0.1)
ap.add_argument("--dt", type=float, default=1e-7)
o = ap.parse_args()
r, rho, dt = 0.002, 2500.0, o.dt
for t0 in o.t0:
    n0 = int(round(t0 / dt))
    # floor height at t0: z_w = V/w (1 - cos(w t0)); release the sphere just above it
    zw0 = o.V / o.w * (1 - math.cos(o.w * n0 * dt))
    deck = f"""atom_style granular
atom_modify map array sort 0 0.0
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.03 0.1 units box
create_box 2 reg
neighbor 0.001 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.e7 5.e7
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m4 all property/global coefficientFriction peratomtypepair 2 0.0 0.0 0.0 0.0
pair_style gran model hertz tangential history
pair_coeff * *
timestep {dt}
fix floor all mesh/surface file floor.stl type 2
fix wall all wall/gran model hertz tangential history mesh n_meshes 1 meshes floor
variable zero equal 0
variable vz equal {o.V}*sin({o.w}*time)
fix shake all move/mesh mesh floor linear/variable v_zero v_zero v_vz
run {n0}
create_atoms 1 single 0 0 {zw0 + r + 1e-7} units box
set atom 1 diameter {2*r} density {rho}
group g1 id 1
variable vw equal {o.V}*sin({o.w}*time)
velocity g1 set 0 0 {-o.g + o.V*math.sin(o.w*n0*dt)} units box
fix integr all nve/sphere
variable pz equal z[1]
variable uz equal vz[1]
thermo 1
thermo_style custom step v_pz v_uz
thermo_modify format float "%.16g"
run {int(2e-3/dt)}
"""
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(o.deckdir, "floor.stl"), tmp)
        open(os.path.join(tmp, "in.vib"), "w").write(deck)
        out = subprocess.run(["liggghts", "-log", "none", "-in", "in.vib"], cwd=tmp, capture_output=True, text=True, errors="replace").stdout
    rows = [tuple(map(float, m.groups())) for m in
            re.finditer(r"^\s*(\d+)\s+([-0-9.eE+]+)\s+([-0-9.eE+]+)\s*$", out, re.M)]
    rows = [x for x in rows if x[0] > n0]
    data = []
    for step, z, vz in rows:
        t = step * dt
        zw = o.V / o.w * (1 - math.cos(o.w * t))   # floor displacement (integral of vz)
        vw = o.V * math.sin(o.w * t)
        data.append((z - zw < r, vz - vw))
    inside = [k for k, (c, _) in enumerate(data) if c]
    if not inside:
        print(out[-1500:])
        continue
    f, l = inside[0], inside[-1]
    vin = data[f - 1][1] if f > 0 else data[0][1]
    print(f"t0 {t0:g}: contact steps {len(inside)}, rel. in {vin:.6g}, out {data[l+1][1]:.6g}, eps {-data[l+1][1]/vin:.6f}")
