"""Field round 13: one screen per audited deck: rc, the audit's stderr lines (cut), and its rows per stage
(types, model, sizes/at, overlap limit, D1, D2, eps at the middle speed). usage: python summary.py DECKDIR ..."""
import json, os, sys
for d in sys.argv[1:]:
    d = d.rstrip("/")
    print("#####", os.path.basename(d), "rc", open(d + "/audit.rc").read().strip())
    for ln in open(d + "/audit.err").read().splitlines():
        print("  ERR", ln[:int(os.environ.get("W", 330))])
    try:
        a = json.load(open(d + "/audit.json"))
    except Exception:
        continue
    for i, s in enumerate(a.get("stages", [])):
        for r in s["pairs"] + s["walls"]:
            k = len(r["eps"]) // 2
            print(f"  st{i+1} {'wall ' + str(r.get('wall')) if 'wall' in r else 'pair'} {r['types']} {r['model'][:70]} "
                  f"{r.get('sizes','')} {r.get('at','')} lim {r.get('overlap_limit')} D1 {r.get('D1', 0):.6g} D2 {r.get('D2', 0):.6g} "
                  f"g {r['speeds'][k]:.3g} eps {r['eps'][k]} at_dt {(r.get('eps_at_dt') or [None]*9)[k]}")
