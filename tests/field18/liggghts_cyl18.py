"""Field round 18: the eps LIGGGHTS measures for a sphere hitting a primitive wall from inside a zcylinder (moving
radially, along x) and, for comparison, the same sphere hitting a zplane; touching at t = 0, contact time / (1000,
2000, 4000, 8000), Richardson on the two finest (wobble = change between the two triples). Materials: G36's
hertz/stiffness lines (or G05's hertz with a typed e). No import from the project.
usage: python liggghts_cyl18.py MODEL R_CYL r rho g       MODEL = hertzstiffness | hertz"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts  # noqa: E402  (the head, materials, run and readers rounds 15-19 share)

MAT = {"hertzstiffness": """fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3
fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5
fix m5 all property/global gamman peratomtypepair 3 30000 30000 30000 30000 30000 30000 30000 30000 30000
fix m6 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5
fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50
pair_style gran model hertz/stiffness tangential history
pair_coeff * *
""", "hertz": liggghts.MAT}
WMODEL = {"hertzstiffness": "hertz/stiffness", "hertz": "hertz"}


def run(model, kind, R, r, rho, g, dt, nmax):
    if kind == "cyl":
        wall = f"fix w all wall/gran model {WMODEL[model]} tangential history primitive type 3 zcylinder {R} 0. 0."
        pos, vel, dvar, vvar = f"{R - r} 0 0", f"{g} 0 0", f"{R}-x[1]-{r}", "vx[1]"
    else:
        wall = f"fix w all wall/gran model {WMODEL[model]} tangential history primitive type 3 zplane 0.0"
        pos, vel, dvar, vvar = f"0 0 {r}", f"0 0 {-g}", f"z[1]-{r}", "-vz[1]"
    deck = liggghts.head("-0.1 0.1 -0.1 0.1 -0.1 0.1") + f"""neighbor {0.2 * r} bin
neigh_modify delay 0
{MAT[model]}{wall}
create_atoms 1 single {pos} units box
set atom 1 diameter {2 * r} density {rho}
velocity all set {vel} units box
variable d equal {dvar}
variable v equal {vvar}
fix integr all nve/sphere
timestep {dt}
thermo_style custom step v_d v_v
thermo 1
thermo_modify format float %.17g norm no
run {nmax}
"""
    return liggghts.parting(liggghts.run(deck, "field18-cyl.", "in.c"), g, dt)


if __name__ == "__main__":
    model, R, r, rho, g = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    for kind in ("cyl", "plane"):
        _, tc = run(model, kind, R, r, rho, g, 1e-7, 400000)
        e = [run(model, kind, R, r, rho, g, tc / n, 3 * n)[0] for n in liggghts.LADDER]
        x1, x2 = liggghts.richardson(e)
        print(f"{model} {kind} R {R:g} r {r:g} rho {rho:g} g {g:g}: eps {x2:.8f} (wobble {abs(x2 - x1):.1e}; from "
              f"{' '.join(f'{v:.8f}' for v in e)}) tc {tc:.4g}", flush=True)
