"""Field round 17: the eps LIGGGHTS measures when a mesh plane (fix move/mesh linear, constant velocity V up) meets
a still sphere, from many starting gaps, at a deck's dt with the deck's neighbour lines and with the usual lists
(`neighbor 0.002 bin`, `neigh_modify delay 0`). eps = (sphere's vz after - V) / V ... taken with sign so that a
plain rebound gives the usual eps: relative speed after / before = (vz - V) / V. No gravity. Materials: round 14's
(hertz, typed e; type 1 on type 3 e = 0.7). No import from the project.
usage: python liggghts_movemesh17.py STL V1,V2,.. GAP0 GAP1 N "NEIGH LINE;NEIGH LINE" """
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts  # noqa: E402  (the head, materials, run and readers rounds 15-19 share)
from fieldkit.liggghts import MAT  # noqa: E402



def run(stl, v, gap, neigh, r=0.002, dt=1e-5):
    n = int(gap / v / dt) + 400
    deck = liggghts.head("-0.05 0.05 -0.05 0.05 -0.01 0.05") + f"""{neigh}
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
    return liggghts.printed(liggghts.run(deck, "field17-mm.", "in.m", stl), "F17EPS")


if __name__ == "__main__":
    stl, vs, g0, g1, k, neigh = sys.argv[1], [float(x) for x in sys.argv[2].split(",")], float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]), sys.argv[6].replace(";", "\n")
    gaps = [g0 + (g1 - g0) * i / (k - 1) for i in range(k)]
    for v in vs:
        a = [(run(stl, v, gp, neigh), gp) for gp in gaps]
        b = [run(stl, v, gp, liggghts.USUAL) for gp in gaps]
        na = sum(1 for x, _ in a if x != x)
        ok = [x for x in a if x[0] == x[0]]
        print(f"V {v:g}: {k} gaps; deck's lists eps {min(ok)[0]:.6f} (gap {min(ok)[1]:.4g}) .. {max(ok)[0]:.6f} (gap {max(ok)[1]:.4g}), "
              f"{na} without contact; usual lists {min(b):.6f} .. {max(b):.6f}", flush=True)
