"""Field round 15: per stage, the sphere size and mass the audit used (from its wall rows: overlap limit = r;
hooke mass_velocity D1 = k/m with the wall's k given, default 2000) beside the sizes LAMMPS holds after that
stage's run (engine_stages.json, from engine_stages.py). A first screen only: every eps called right or wrong
in FINDINGS.md is then refereed head-on. usage: python compare_sizes.py [--k K] DECKDIR ..."""
import json, os, sys

args = sys.argv[1:]
k = 2000.0
if args and args[0] == "--k":
    k = float(args[1]); args = args[2:]
for d in args:
    d = d.rstrip("/")
    try:
        a = json.load(open(d + "/audit.json"))
        e = json.load(open(d + "/engine_stages.json"))
    except Exception as ex:
        print("#", os.path.basename(d), "no data", ex); continue
    st = a.get("stages") or [{"pairs": a["pairs"], "walls": a["walls"]}]
    print("#", os.path.basename(d), f"audit stages {len(st)} engine stages {len(e)}")
    for i, s in enumerate(st):
        aud = {}
        for r in s["walls"]:
            t = r["types"][0]
            aud.setdefault(str(t), set()).add((round(r["overlap_limit"], 9), round(k / r["D1"], 12) if r.get("D1") else None,
                                               bool(r.get("beside"))))
        es = e[i]["state"] if i < len(e) and "state" in e[i] else None
        if len(e) != len(st) and i == len(st) - 1:
            es = e[-1].get("state")
        line = f"  st{i+1}"
        for t in sorted(set(aud) | set(es or {})):
            au = "; ".join(f"r {x:.6g} m {y:.6g}{' [beside]' if b else ''}" for x, y, b in sorted(aud.get(t, []), key=str))
            en = "; ".join(f"r {x:.6g} m {y:.6g}" for x, y in (es or {}).get(t, []))
            ok = ""
            if es and t in es and t in aud and len(es[t]) == 1 and len(aud[t]) == 1:
                (x, y, _), (ex_, ey) = list(aud[t])[0], es[t][0]
                ok = "OK" if abs(x - ex_) < 1e-9 * max(1, ex_) + 1e-12 and y and abs(y - ey) < 1e-6 * ey else "DIFF"
            line += f" | t{t} audit {au or '-'} engine {en or '-'} {ok}"
        print(line)
