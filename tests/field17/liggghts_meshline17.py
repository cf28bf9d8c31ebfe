"""Field round 17: round 16's LIGGGHTS drop on a mesh floor (liggghts_neighbor16.py) with the mesh's fix line given
here (e.g. with `surface_vel`), the usual lists, gap by gap. usage: python liggghts_meshline17.py STL "MESH LINE" G GAP..."""
import importlib.util, os, shutil, subprocess, sys, tempfile

_s = importlib.util.spec_from_file_location("ln16", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "field16",
                                                                  "liggghts_neighbor16.py"))
LN = importlib.util.module_from_spec(_s)
_s.loader.exec_module(LN)
PLAIN = "fix cad all mesh/surface file plane0.stl type 3\n"

if __name__ == "__main__":
    stl, line, g, gaps = sys.argv[1], sys.argv[2], float(sys.argv[3]), [float(x) for x in sys.argv[4:]]
    s = {"r1": 0.002, "rho1": 2500, "wall": "mesh", "dt": 1e-5}
    for gap in gaps:
        out = []
        for ml in (line + "\n", PLAIN):
            txt = LN.deck(s, g, gap, "neighbor 0.002 bin\nneigh_modify delay 0").replace(PLAIN, ml)
            with tempfile.TemporaryDirectory(prefix="field17-ml.") as d:
                open(os.path.join(d, "in.m"), "w").write(txt)
                shutil.copy(stl, os.path.join(d, "plane0.stl"))
                p = subprocess.run(["liggghts", "-in", "in.m", "-log", "none"], cwd=d, capture_output=True, text=True, errors="replace")
            v = [ln.split() for ln in p.stdout.splitlines() if ln.startswith("F16EPS")]
            out.append(float(v[0][1]) if v and float(v[0][2]) > 0 else float("nan"))
        print(f"g {g:g} gap {gap:g}: with the line {out[0]:.6f}   plain mesh {out[1]:.6f}", flush=True)
