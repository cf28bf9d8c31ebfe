"""Field round 18: the eps LIGGGHTS measures for a sphere hitting a primitive wall from inside a zcylinder (moving
radially, along x) and, for comparison, the same sphere hitting a zplane; touching at t = 0, contact time / (1000,
2000, 4000, 8000), Richardson on the two finest (wobble = change between the two triples). Materials: G36's
hertz/stiffness lines (or G05's hertz with a typed e). No import from the project.
usage: python liggghts_cyl18.py MODEL R_CYL r rho g       MODEL = hertzstiffness | hertz"""
import os, subprocess, sys, tempfile

MAT = {"hertzstiffness": """fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3
fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5
fix m5 all property/global gamman peratomtypepair 3 30000 30000 30000 30000 30000 30000 30000 30000 30000
fix m6 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5
fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50
pair_style gran model hertz/stiffness tangential history
pair_coeff * *
""", "hertz": """fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8
fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
"""}
WMODEL = {"hertzstiffness": "hertz/stiffness", "hertz": "hertz"}


def run(model, kind, R, r, rho, g, dt, nmax):
    if kind == "cyl":
        wall = f"fix w all wall/gran model {WMODEL[model]} tangential history primitive type 3 zcylinder {R} 0. 0."
        pos, vel, dvar, vvar = f"{R - r} 0 0", f"{g} 0 0", f"{R}-x[1]-{r}", "vx[1]"
    else:
        wall = f"fix w all wall/gran model {WMODEL[model]} tangential history primitive type 3 zplane 0.0"
        pos, vel, dvar, vvar = f"0 0 {r}", f"0 0 {-g}", f"z[1]-{r}", "-vz[1]"
    deck = f"""atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box
create_box 3 reg
neighbor {0.2 * r} bin
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
    with tempfile.TemporaryDirectory(prefix="field18-cyl.") as d:
        open(os.path.join(d, "in.c"), "w").write(deck)
        p = subprocess.run(["liggghts", "-in", "in.c", "-log", "none"], cwd=d, capture_output=True, text=True, errors="replace")
    rows = []
    for ln in p.stdout.splitlines():
        f = ln.split()
        if len(f) == 3 and f[0].isdigit():
            try:
                rows.append((int(f[0]), float(f[1]), float(f[2])))
            except ValueError:
                pass
    for s, dd, v in rows:
        if s > 0 and dd > 0:
            return -v / g, s * dt
    raise RuntimeError(p.stdout[-800:])


if __name__ == "__main__":
    model, R, r, rho, g = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    for kind in ("cyl", "plane"):
        _, tc = run(model, kind, R, r, rho, g, 1e-7, 400000)
        e = [run(model, kind, R, r, rho, g, tc / n, 3 * n)[0] for n in (1000, 2000, 4000, 8000)]
        x1, x2 = 2 * e[2] - e[1], 2 * e[3] - e[2]
        print(f"{model} {kind} R {R:g} r {r:g} rho {rho:g} g {g:g}: eps {x2:.8f} (wobble {abs(x2 - x1):.1e}; from "
              f"{' '.join(f'{v:.8f}' for v in e)}) tc {tc:.4g}", flush=True)
