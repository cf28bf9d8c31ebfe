"""Field round 15, L15: the eps LIGGGHTS itself measures for deck L15's types 1 2 (hertz, e 0.5, r 2 and 3 mm, densities
2500 and 1500) at the deck's dt 1e-5, the spheres approaching at 1 m/s from gaps of 0.2 ... 1.8 mm, with the deck's
neighbour settings (`neighbor 1e-5 bin`, `neigh_modify delay 0 every 200 check no`) and with the usual
`neighbor 0.002 bin`, `neigh_modify delay 0`. eps = relative normal speed after / before, read after 600 steps
(the contact over, no gravity). No import from the project. usage: python liggghts_neighbor_check.py"""
import math, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts  # noqa: E402  (the head, materials, run and readers rounds 15-19 share)
from fieldkit.liggghts import MAT  # noqa: E402



def run(gap, neigh):
    r1, r2 = 0.002, 0.003
    m1, m2 = 2500 * 4 / 3 * math.pi * r1 ** 3, 1500 * 4 / 3 * math.pi * r2 ** 3
    deck = liggghts.head("-0.05 0.05 -0.05 0.05 -0.05 0.05") + f"""{neigh}
{MAT}create_atoms 1 single {-r1 - gap / 2} 0 0 units box
create_atoms 2 single {r2 + gap / 2} 0 0 units box
set atom 1 diameter {2 * r1} density 2500
set atom 2 diameter {2 * r2} density 1500
group a1 id 1
group a2 id 2
velocity a1 set {m2 / (m1 + m2)} 0 0
velocity a2 set {-m1 / (m1 + m2)} 0 0
timestep 1e-5
fix integr all nve/sphere
run 600
variable e equal vx[2]-vx[1]
print "F15EPS ${{e}}"
"""
    for ln in liggghts.run(deck, "field15-lnb.", "in.n").splitlines():
        if ln.startswith("F15EPS"):
            return float(ln.split()[1])
    return float("nan")


if __name__ == "__main__":
    deck = "neighbor 1e-5 bin\nneigh_modify delay 0 every 200 check no"
    usual = "neighbor 0.002 bin\nneigh_modify delay 0"
    for gap in (0.0002, 0.0006, 0.001, 0.0014, 0.0018):
        print(f"gap {gap:.4f} m: deck's lists eps {run(gap, deck):.6f}   usual lists eps {run(gap, usual):.6f}")


def run_wall(gap, neigh):
    """Type 1 (r 2 mm, rho 2500) dropped at 1 m/s on deck L15's primitive floor (e 0.7 for 1 with 3) from a gap."""
    r1 = 0.002
    deck = liggghts.head("-0.05 0.05 -0.05 0.05 -0.01 0.05") + f"""{neigh}
{MAT}fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0
create_atoms 1 single 0 0 {r1 + gap} units box
set atom 1 diameter {2 * r1} density 2500
velocity all set 0 0 -1
timestep 1e-5
fix integr all nve/sphere
run 600
variable e equal vz[1]
print "F15EPS ${{e}}"
"""
    for ln in liggghts.run(deck, "field15-lnb.", "in.n").splitlines():
        if ln.startswith("F15EPS"):
            return float(ln.split()[1])
    return float("nan")


if __name__ == "__main__":
    for gap in (0.0002, 0.001, 0.0018):
        print(f"wall, gap {gap:.4f} m: deck's lists eps {run_wall(gap, deck):.6f}   usual lists eps {run_wall(gap, usual):.6f}")
