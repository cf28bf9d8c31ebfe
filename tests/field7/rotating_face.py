"""Referee for a sphere meeting a face of a LIGGGHTS mesh that `fix move/mesh ... rotate` turns.

The floor z = 0 (the deck's floor.stl) rotates about the x axis through (0, 0, -d) with period P; a
sphere (type 1) starts just above the origin moving down at g. From LIGGGHTS' per-step position and
velocity, the normal relative speed against the face point under the sphere is formed before and
after the contact: eps = -vn_out / vn_in. Independent of the project's code.

Usage: python rotating_face.py DECKDIR --d 0.02 --P 0.05 --g 0.1 --dt 1e-7 [--mu 0.5]
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
ap.add_argument("--d", type=float, default=0.02)
ap.add_argument("--P", type=float, default=0.05)
ap.add_argument("--g", type=float, default=0.1)
ap.add_argument("--dt", type=float, nargs="+", default=[1e-7])
ap.add_argument("--mu", type=float, default=0.0)
ap.add_argument("--E", type=float, default=5e7)
ap.add_argument("--e", type=float, default=0.5)
o = ap.parse_args()
r, rho = 0.002, 2500.0
w = 2 * math.pi / o.P
for dt in o.dt:
    gap = 1e-7
    nsteps = int((gap / o.g + 4e-3) / dt)
    deck = f"""atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.03 0.1 units box
create_box 2 reg
neighbor 0.001 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype {o.E} {o.E}
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 2 {o.e} {o.e} {o.e} {o.e}
fix m4 all property/global coefficientFriction peratomtypepair 2 {o.mu} {o.mu} {o.mu} {o.mu}
pair_style gran model hertz tangential history
pair_coeff * *
timestep {dt}
fix floor all mesh/surface file floor.stl type 2
fix wall all wall/gran model hertz tangential history mesh n_meshes 1 meshes floor
fix shake all move/mesh mesh floor rotate origin 0. 0. {-o.d} axis 1. 0. 0. period {o.P}
create_atoms 1 single 0 0 {r + gap} units box
set atom 1 diameter {2*r} density {rho}
group g1 id 1
velocity g1 set 0 0 {-o.g} units box
fix integr all nve/sphere
variable py equal y[1]
variable pz equal z[1]
variable uy equal vy[1]
variable uz equal vz[1]
thermo 1
thermo_style custom step v_py v_pz v_uy v_uz
thermo_modify format float "%.16g"
run {nsteps}
"""
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(o.deckdir, "floor.stl"), tmp)
        open(os.path.join(tmp, "in.rot"), "w").write(deck)
        out = subprocess.run(["liggghts", "-log", "none", "-in", "in.rot"], cwd=tmp, capture_output=True, text=True, errors="replace").stdout
    rows = [tuple(map(float, m.groups())) for m in
            re.finditer(r"^\s*(\d+)\s+([-0-9.eE+]+)\s+([-0-9.eE+]+)\s+([-0-9.eE+]+)\s+([-0-9.eE+]+)\s*$", out, re.M)]
    data = []
    for step, y, z, vy, vz in rows:
        t = step * dt
        th = w * t
        ny, nz = -math.sin(th), math.cos(th)          # the face's normal, rotated about x
        dist = ny * y + nz * (z + o.d) - o.d          # centre's distance from the face
        cy, cz = y - r * ny, z - r * nz               # the face point under the sphere
        fy, fz = -w * (cz + o.d), w * cy              # its velocity: omega x (c - axis point)
        vn = ny * (vy - fy) + nz * (vz - fz)          # normal relative velocity (away from face > 0)
        data.append((dist < r, vn))
    inside = [k for k, (c, _) in enumerate(data) if c]
    f, l = inside[0], inside[-1]
    print(f"dt {dt:g}: contact steps {len(inside)}, vn in {data[f-1][1]:.6g}, out {data[l+1][1]:.6g}, "
          f"eps {-data[l+1][1]/data[f-1][1]:.6f}")
