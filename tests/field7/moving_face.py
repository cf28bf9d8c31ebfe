"""Referee for a sphere meeting a face of a LIGGGHTS floor mesh (the deck folder's floor.stl, z = 0)
that `fix move/mesh` moves, formed from LIGGGHTS' per-step position and velocity: eps is the normal
speed relative to the face point under the sphere after the contact over the one before. Independent
of the project's code.

  rotate:  the floor turns about the x axis through (0, 0, -d) with period P; the sphere starts just
           above the origin at t = 0.
  vibrate: the floor moves by `linear/variable` with vz = V sin(w t); the sphere is released just
           above it at each time t0 of the cycle given.

Usage: python moving_face.py DECKDIR rotate --d 0.02 --P 0.2 --g 0.1 --dt 4e-7 1e-7 [--mu 0.5]
       python moving_face.py DECKDIR vibrate --V 0.05 --w 1000 --t0 0 0.0008 --g 0.1 --dt 4e-7
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import tempfile

R, RHO = 0.002, 2500.0


def header(dt, mu, motion):
    """The deck up to the floor's motion: hertz, e = 0.5, E = 5e7, two types (floor type 2)."""
    return f"""atom_style granular
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
fix m4 all property/global coefficientFriction peratomtypepair 2 {mu} {mu} {mu} {mu}
pair_style gran model hertz tangential history
pair_coeff * *
timestep {dt}
fix floor all mesh/surface file floor.stl type 2
fix wall all wall/gran model hertz tangential history mesh n_meshes 1 meshes floor
{motion}
"""


def sphere(z0, vz0, columns):
    """One sphere at (0, 0, z0) moving at vz0, and thermo of step and the columns asked."""
    names = " ".join(f"v_{c}" for c in columns)
    return f"""create_atoms 1 single 0 0 {z0} units box
set atom 1 diameter {2*R} density {RHO}
group g1 id 1
velocity g1 set 0 0 {vz0} units box
fix integr all nve/sphere
variable py equal y[1]
variable pz equal z[1]
variable uy equal vy[1]
variable uz equal vz[1]
thermo 1
thermo_style custom step {names}
thermo_modify format float "%.16g"
"""


def run(deckdir, text, ncols):
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(deckdir, "floor.stl"), tmp)
        open(os.path.join(tmp, "in.face"), "w").write(text)
        out = subprocess.run(["liggghts", "-log", "none", "-in", "in.face"], cwd=tmp,
                             capture_output=True, text=True, errors="replace").stdout
    num = r"\s+([-0-9.eE+]+)"
    return [tuple(map(float, m.groups())) for m in re.finditer(r"^\s*(\d+)" + num * ncols + r"\s*$", out, re.M)]


def eps_of(data):
    """data: (in contact, normal relative speed) per step: the first contact's eps."""
    inside = [k for k, (c, _) in enumerate(data) if c]
    f = l = inside[0]
    while l + 1 < len(data) and data[l + 1][0]:
        l += 1
    vin = data[f - 1][1] if f > 0 else data[0][1]
    return l - f + 1, vin, data[l + 1][1], -data[l + 1][1] / vin


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("deckdir")
    ap.add_argument("mode", choices=["rotate", "vibrate"])
    ap.add_argument("--g", type=float, default=0.1)
    ap.add_argument("--dt", type=float, nargs="+", default=[1e-7])
    ap.add_argument("--mu", type=float, default=0.0)
    ap.add_argument("--d", type=float, default=0.02)
    ap.add_argument("--P", type=float, default=0.2)
    ap.add_argument("--V", type=float, default=0.05, help="the floor's velocity amplitude")
    ap.add_argument("--w", type=float, default=1000.0)
    ap.add_argument("--t0", type=float, nargs="+", default=[0.0])
    o = ap.parse_args()
    if o.mode == "rotate":
        w = 2 * math.pi / o.P
        for dt in o.dt:
            motion = f"fix shake all move/mesh mesh floor rotate origin 0. 0. {-o.d} axis 1. 0. 0. period {o.P}"
            text = header(dt, o.mu, motion) + sphere(R + 1e-7, -o.g, ["py", "pz", "uy", "uz"])
            text += f"run {int((1e-7 / o.g + 4e-3) / dt)}\n"
            data = []
            for step, y, z, vy, vz in run(o.deckdir, text, 4):
                th = w * step * dt
                ny, nz = -math.sin(th), math.cos(th)          # the face's normal, turned about x
                dist = ny * y + nz * (z + o.d) - o.d          # the centre's distance from the face
                cy, cz = y - R * ny, z - R * nz               # the face point under the sphere
                fy, fz = -w * (cz + o.d), w * cy              # its velocity: omega x (c - axis point)
                data.append((dist < R, ny * (vy - fy) + nz * (vz - fz)))
            n, vin, vout, eps = eps_of(data)
            print(f"rotate P {o.P:g} dt {dt:g}: contact steps {n}, vn in {vin:.6g}, out {vout:.6g}, eps {eps:.6f}")
    else:
        dt = o.dt[0]
        for t0 in o.t0:
            n0 = int(round(t0 / dt))
            zw0 = o.V / o.w * (1 - math.cos(o.w * n0 * dt))   # the floor's height at t0
            motion = (f"variable zero equal 0\nvariable vz equal {o.V}*sin({o.w}*time)\n"
                      "fix shake all move/mesh mesh floor linear/variable v_zero v_zero v_vz")
            text = header(dt, o.mu, motion) + f"run {n0}\n"
            text += sphere(zw0 + R + 1e-7, -o.g + o.V * math.sin(o.w * n0 * dt), ["pz", "uz"])
            text += f"run {int(2e-3 / dt)}\n"
            data = []
            for step, z, vz in run(o.deckdir, text, 2):
                if step <= n0:
                    continue
                t = step * dt
                data.append((z - o.V / o.w * (1 - math.cos(o.w * t)) < R, vz - o.V * math.sin(o.w * t)))
            n, vin, vout, eps = eps_of(data)
            print(f"vibrate t0 {t0:g}: contact steps {n}, rel. in {vin:.6g}, out {vout:.6g}, eps {eps:.6f}")


if __name__ == "__main__":
    main()
