"""Field round 17: the eps LIGGGHTS measures for a sphere hitting a sphere that no fix integrates (it never moves),
head-on, touching at t = 0, at contact time / (1000, 2000, 4000, 8000), extrapolated to dt -> 0 (Richardson on the
two finest; wobble = change between the two triples). Materials: round 14's (hertz, typed e). No import from the
project. usage: python liggghts_still17.py T1 R1 RHO1 T2 R2 RHO2 G [VX VY VZ: a velocity the still partner holds]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts  # noqa: E402  (the head, materials, run and readers rounds 15-19 share)
from fieldkit.liggghts import MAT  # noqa: E402



def run(t1, r1, rho1, t2, r2, rho2, g, dt, nmax, v2=(0, 0, 0)):
    deck = liggghts.head() + f"""neighbor 0.002 bin
neigh_modify delay 0
{MAT}create_atoms {t1} single {-r1} 0 0 units box
create_atoms {t2} single {r2} 0 0 units box
set atom 1 diameter {2 * r1} density {rho1}
set atom 2 diameter {2 * r2} density {rho2}
group a1 id 1
group a2 id 2
velocity a1 set {g} 0 0 units box
velocity a2 set {v2[0]} {v2[1]} {v2[2]} units box
variable d equal x[2]-x[1]-{r1 + r2}
variable v equal vx[1]
fix integr a1 nve/sphere
timestep {dt}
thermo_style custom step v_d v_v
thermo 1
thermo_modify format float %.17g norm no
run {nmax}
"""
    return liggghts.parting(liggghts.run(deck, "field17-still.", "in.s"), g, dt)


if __name__ == "__main__":
    t1, r1, rho1, t2, r2, rho2, g = sys.argv[1:8]
    v2 = [float(x) for x in sys.argv[8:11]] or [0.0, 0.0, 0.0]
    t1, t2, r1, rho1, r2, rho2, g = int(t1), int(t2), float(r1), float(rho1), float(r2), float(rho2), float(g)
    _, tc = run(t1, r1, rho1, t2, r2, rho2, g, 1e-7, 200000, v2)
    e = [run(t1, r1, rho1, t2, r2, rho2, g, tc / n, 3 * n, v2)[0] for n in liggghts.LADDER]
    x1, x2 = liggghts.richardson(e)
    print(f"types {t1} {t2} still partner holding velocity {v2}, g {g:g}: eps {x2:.8f} (wobble {abs(x2 - x1):.1e}; from {' '.join(f'{v:.8f}' for v in e)}) tc {tc:.4g}")
