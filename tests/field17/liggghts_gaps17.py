"""Field round 17: round 16's liggghts_neighbor16.py, gap by gap (a pass-through, NaN, is printed, not hidden by
min/max). usage: python liggghts_gaps17.py SPEC.json (keys as liggghts_neighbor16.py; "gaps" a list or {"lin": ..})"""
import importlib.util, json, os, sys

_s = importlib.util.spec_from_file_location("ln16", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "field16",
                                                                  "liggghts_neighbor16.py"))
LN = importlib.util.module_from_spec(_s)
_s.loader.exec_module(LN)

if __name__ == "__main__":
    s = json.load(open(sys.argv[1]))
    gp = s["gaps"]
    gaps = [gp["lin"][0] + (gp["lin"][1] - gp["lin"][0]) * i / (gp["lin"][2] - 1) for i in range(gp["lin"][2])] if isinstance(gp, dict) else gp
    usual = "neighbor 0.002 bin\nneigh_modify delay 0"
    for g in s["g"]:
        for gap in gaps:
            a = LN.run(s, g, gap, "\n".join(s["neigh"]))
            b = LN.run(s, g, gap, usual)
            print(f"g {g:g} gap {gap:.6g}: deck's lists eps {a:.6f}   usual lists eps {b:.6f}", flush=True)
