"""The eps LIGGGHTS itself measures at a deck's dt with the deck's neighbour lines (and with the usual
`neighbor 0.002 bin` / `neigh_modify delay 0`), two spheres head-on or one sphere dropped on a primitive or mesh floor,
from many starting gaps, read after one continuous run long enough to meet and part (no gravity). Materials: round
14's (fieldkit.liggghts.MAT). No import from the project.

`main` (liggghts_neighbor16.py): the range over the gaps. usage: python liggghts_neighbor16.py SPEC.json (keys: neigh
[lines], g [..], gaps {"lin": [a, b, n]}, t1 t2 r1 r2 rho1 rho2 dt, post (lines after the atoms), wall: "prim" | "mesh"
(then t1 alone falls onto z = 0), stl (the mesh file, for mesh))
`gap_by_gap` (liggghts_gaps17.py): the same, gap by gap (a pass-through, NaN, is printed, not hidden by min/max);
"gaps" a list or {"lin": ..}. usage: python liggghts_gaps17.py SPEC.json
`with_line` (liggghts_meshline17.py, liggghts_wallline17.py): the drop on a mesh or primitive floor with the floor's
fix line given (e.g. with `surface_vel` or a `shear` keyword) beside the plain one, the usual lists, gap by gap.
usage: python liggghts_meshline17.py STL "MESH LINE" G GAP...   python liggghts_wallline17.py "WALL LINE" G GAP...
"""
import json, math

from fieldkit import liggghts

PRIM = "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n"
MESH = "fix cad all mesh/surface file plane0.stl type 3\n"


def deck(s, g, gap, neigh):
    """The deck of spec `s` at speed `g` from `gap` with neighbour lines `neigh`."""
    r1, r2 = s["r1"], s.get("r2", s["r1"])
    rho1, rho2 = s["rho1"], s.get("rho2", s["rho1"])
    n = int((gap / g) / s["dt"]) + s.get("tail_steps", 400)
    txt = liggghts.head("-0.05 0.05 -0.05 0.05 -0.01 0.05") + f"{neigh}\n{liggghts.MAT}"
    if s.get("wall"):
        txt += (PRIM if s["wall"] == "prim" else MESH + "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n")
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
    """The eps of spec `s` at speed `g` from `gap` with neighbour lines `neigh` (NaN: they never parted)."""
    out = liggghts.run(deck(s, g, gap, neigh), "field16-lnb.", "in.n", s["stl"] if s.get("wall") == "mesh" else None)
    return liggghts.printed(out, "F16EPS")


def main(argv):
    """Print, per speed, the range of eps over the gaps with the deck's lists and with the usual ones."""
    s = json.load(open(argv[0]))
    a, b, k = s["gaps"]["lin"]
    gaps = [a + (b - a) * i / (k - 1) for i in range(k)]
    for g in s["g"]:
        dk = [(run(s, g, gap, "\n".join(s["neigh"])), gap) for gap in gaps]
        us = [run(s, g, gap, liggghts.USUAL) for gap in gaps]
        lo, hi = min(dk), max(dk)
        print(f"g {g:g}: {len(gaps)} gaps; deck's lists eps {lo[0]:.6f} (gap {lo[1]:.4g}) .. {hi[0]:.6f} (gap {hi[1]:.4g}); "
              f"usual lists {min(us):.6f} .. {max(us):.6f}", flush=True)


def gap_by_gap(argv):
    """Print the eps of every gap, with the deck's lists and the usual ones."""
    s = json.load(open(argv[0]))
    gp = s["gaps"]
    gaps = [gp["lin"][0] + (gp["lin"][1] - gp["lin"][0]) * i / (gp["lin"][2] - 1) for i in range(gp["lin"][2])] if isinstance(gp, dict) else gp
    for g in s["g"]:
        for gap in gaps:
            a = run(s, g, gap, "\n".join(s["neigh"]))
            b = run(s, g, gap, liggghts.USUAL)
            print(f"g {g:g} gap {gap:.6g}: deck's lists eps {a:.6f}   usual lists eps {b:.6f}", flush=True)


def with_line(line, g, gaps, *, stl=None):
    """Print, gap by gap, the drop's eps with the floor's fix `line` and with the plain floor (a mesh when `stl`)."""
    s = {"r1": 0.002, "rho1": 2500, "wall": "mesh" if stl else "prim", "dt": 1e-5}
    plain, prefix, name, what = (MESH, "field17-ml.", "in.m", "plain mesh") if stl else (PRIM, "field17-wl.", "in.w", "plain floor")
    for gap in gaps:
        out = []
        for fl in (line + "\n", plain):
            txt = deck(s, g, gap, liggghts.USUAL).replace(plain, fl)
            v = [ln.split() for ln in liggghts.run(txt, prefix, name, stl).splitlines() if ln.startswith("F16EPS")]
            out.append(float(v[0][1]) if v and float(v[0][2]) > 0 else float("nan"))
        print(f"g {g:g} gap {gap:g}: with the line {out[0]:.6f}   {what} {out[1]:.6f}", flush=True)
