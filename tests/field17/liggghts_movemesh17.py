"""Field round 17: the eps LIGGGHTS measures when a mesh plane (fix move/mesh linear, constant velocity V up) meets
a still sphere, from many starting gaps, at a deck's dt with the deck's neighbour lines and with the usual lists
(`neighbor 0.002 bin`, `neigh_modify delay 0`). eps = (sphere's vz after - V) / V ... taken with sign so that a
plain rebound gives the usual eps: relative speed after / before = (vz - V) / V. No gravity. Materials: round 14's
(hertz, typed e; type 1 on type 3 e = 0.7). No import from the project.
usage: python liggghts_movemesh17.py STL V1,V2,.. GAP0 GAP1 N "NEIGH LINE;NEIGH LINE" """
import os, shutil, subprocess, sys, tempfile

MAT = """fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8
fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
"""


def run(stl, v, gap, neigh, r=0.002, dt=1e-5):
    n = int(gap / v / dt) + 400
    deck = f"""atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.01 0.05 units box
create_box 3 reg
{neigh}
{MAT}fix cad all mesh/surface file plane0.stl type 3
fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad
fix mv all move/mesh mesh cad linear 0 0 {v}
create_atoms 1 single 0 0 {r + gap} units box
set atom 1 diameter {2 * r} density 2500
variable e equal (vz[1]-{v})/{v}
variable sep equal z[1]-{r}-{v}*step*{dt}
timestep {dt}
fix integr all nve/sphere
run {n}
print "F17EPS ${{e}} ${{sep}}"
"""
    with tempfile.TemporaryDirectory(prefix="field17-mm.") as d:
        open(os.path.join(d, "in.m"), "w").write(deck)
        shutil.copy(stl, os.path.join(d, "plane0.stl"))
        p = subprocess.run(["liggghts", "-in", "in.m", "-log", "none"], cwd=d, capture_output=True, text=True, errors="replace")
    for ln in p.stdout.splitlines():
        if ln.startswith("F17EPS"):
            e, sep = float(ln.split()[1]), float(ln.split()[2])
            return e if sep > 0 else float("nan")
    raise RuntimeError(p.stdout[-1500:])


if __name__ == "__main__":
    stl, vs, g0, g1, k, neigh = sys.argv[1], [float(x) for x in sys.argv[2].split(",")], float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]), sys.argv[6].replace(";", "\n")
    gaps = [g0 + (g1 - g0) * i / (k - 1) for i in range(k)]
    for v in vs:
        a = [(run(stl, v, gp, neigh), gp) for gp in gaps]
        b = [run(stl, v, gp, "neighbor 0.002 bin\nneigh_modify delay 0") for gp in gaps]
        na = sum(1 for x, _ in a if x != x)
        ok = [x for x in a if x[0] == x[0]]
        print(f"V {v:g}: {k} gaps; deck's lists eps {min(ok)[0]:.6f} (gap {min(ok)[1]:.4g}) .. {max(ok)[0]:.6f} (gap {max(ok)[1]:.4g}), "
              f"{na} without contact; usual lists {min(b):.6f} .. {max(b):.6f}", flush=True)
