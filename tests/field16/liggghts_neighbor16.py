"""Field round 16: the eps LIGGGHTS itself measures at a deck's dt with the deck's neighbour lines (and with the
usual `neighbor 0.002 bin` / `neigh_modify delay 0`), two spheres head-on or one sphere dropped on a primitive or
mesh floor, from many starting gaps, read after one continuous run long enough to meet and part (no gravity).
Materials: round 14's (E 5e6, nu 0.3, e matrix 0.6 0.5 0.7 / 0.5 0.4 0.45 / 0.7 0.45 0.8, hertz). No import from the
project. usage: python liggghts_neighbor16.py SPEC.json (keys: neigh [lines], g [..], gaps {"lin": [a, b, n]},
t1 t2 r1 r2 rho1 rho2 dt, post (lines after the atoms), wall: "prim" | "mesh" (then t1 alone falls onto z = 0), stl (the mesh file, for mesh))"""
import json, math, os, shutil, subprocess, sys, tempfile

MAT = """fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8
fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
"""


def deck(s, g, gap, neigh):
    r1, r2 = s["r1"], s.get("r2", s["r1"])
    rho1, rho2 = s["rho1"], s.get("rho2", s["rho1"])
    n = int((gap / g) / s["dt"]) + s.get("tail_steps", 400)
    txt = f"""atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.01 0.05 units box
create_box 3 reg
{neigh}
{MAT}"""
    if s.get("wall"):
        txt += ("fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n" if s["wall"] == "prim" else
                "fix cad all mesh/surface file plane0.stl type 3\nfix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n")
        txt += f"""create_atoms {s.get('t1', 1)} single 0 0 {r1 + gap} units box
set atom 1 diameter {2 * r1} density {rho1}
velocity all set 0 0 {-g}
variable e equal vz[1]/{g}
variable sep equal z[1]-{r1}
"""
    else:
        m1, m2 = rho1 * 4 / 3 * math.pi * r1 ** 3, rho2 * 4 / 3 * math.pi * r2 ** 3
        txt += f"""create_atoms {s.get('t1', 1)} single {-r1 - gap / 2} 0 0 units box
create_atoms {s.get('t2', 2)} single {r2 + gap / 2} 0 0 units box
set atom 1 diameter {2 * r1} density {rho1}
set atom 2 diameter {2 * r2} density {rho2}
group a1 id 1
group a2 id 2
velocity a1 set {g * m2 / (m1 + m2)} 0 0
velocity a2 set {-g * m1 / (m1 + m2)} 0 0
variable e equal (vx[2]-vx[1])/{g}
variable sep equal x[2]-x[1]-{r1 + r2}
"""
    txt += "".join(ln + "\n" for ln in s.get("post", []))
    txt += f"timestep {s['dt']}\nfix integr all nve/sphere\nrun {n}\nprint \"F16EPS ${{e}} ${{sep}}\"\n"
    return txt


def run(s, g, gap, neigh):
    with tempfile.TemporaryDirectory(prefix="field16-lnb.") as d:
        open(os.path.join(d, "in.n"), "w").write(deck(s, g, gap, neigh))
        if s.get("wall") == "mesh":
            shutil.copy(s["stl"], os.path.join(d, "plane0.stl"))
        p = subprocess.run(["liggghts", "-in", "in.n", "-log", "none"], cwd=d, capture_output=True, text=True, errors="replace")
    for ln in p.stdout.splitlines():
        if ln.startswith("F16EPS"):
            e, sep = float(ln.split()[1]), float(ln.split()[2])
            return e if sep > 0 else float("nan")
    raise RuntimeError(p.stdout[-1500:])


if __name__ == "__main__":
    s = json.load(open(sys.argv[1]))
    a, b, k = s["gaps"]["lin"]
    gaps = [a + (b - a) * i / (k - 1) for i in range(k)]
    usual = "neighbor 0.002 bin\nneigh_modify delay 0"
    for g in s["g"]:
        dk = [(run(s, g, gap, "\n".join(s["neigh"])), gap) for gap in gaps]
        us = [run(s, g, gap, usual) for gap in gaps]
        lo, hi = min(dk), max(dk)
        print(f"g {g:g}: {len(gaps)} gaps; deck's lists eps {lo[0]:.6f} (gap {lo[1]:.4g}) .. {hi[0]:.6f} (gap {hi[1]:.4g}); "
              f"usual lists {min(us):.6f} .. {max(us):.6f}", flush=True)
