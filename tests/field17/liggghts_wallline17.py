"""Field round 17: round 16's LIGGGHTS drop on a primitive floor (liggghts_neighbor16.py) with the floor's fix line
given here (e.g. with a `shear` keyword), the usual lists, gap by gap. usage: python liggghts_wallline17.py "WALL LINE" G GAP..."""
import importlib.util, os, subprocess, sys, tempfile

_s = importlib.util.spec_from_file_location("ln16", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "field16",
                                                                  "liggghts_neighbor16.py"))
LN = importlib.util.module_from_spec(_s)
_s.loader.exec_module(LN)
PLAIN = "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n"

if __name__ == "__main__":
    line, g, gaps = sys.argv[1], float(sys.argv[2]), [float(x) for x in sys.argv[3:]]
    s = {"r1": 0.002, "rho1": 2500, "wall": "prim", "dt": 1e-5}
    for gap in gaps:
        out = []
        for wl in (line + "\n", PLAIN):
            txt = LN.deck(s, g, gap, "neighbor 0.002 bin\nneigh_modify delay 0").replace(PLAIN, wl)
            with tempfile.TemporaryDirectory(prefix="field17-wl.") as d:
                open(os.path.join(d, "in.w"), "w").write(txt)
                p = subprocess.run(["liggghts", "-in", "in.w", "-log", "none"], cwd=d, capture_output=True, text=True, errors="replace")
            v = [ln.split() for ln in p.stdout.splitlines() if ln.startswith("F16EPS")]
            out.append(float(v[0][1]) if v and float(v[0][2]) > 0 else float("nan"))
        print(f"g {g:g} gap {gap:g}: with the line {out[0]:.6f}   plain floor {out[1]:.6f}", flush=True)
