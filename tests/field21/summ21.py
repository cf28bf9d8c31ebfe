"""Field round 21: one line per audited row of each deck (from audit.json), the rc, and stderr lines other than
the usual time-step, tsuji-version and gravity notes. usage: python summ21.py DECKDIR ..."""
import json, os, sys
SKIP = ("at the deck's time step", "tsuji damping as LAMMPS", "fix gravity (grav): a gravity on the sphere")
for d in sys.argv[1:]:
    d = d.rstrip("/")
    rc = open(os.path.join(d, "audit.rc")).read().strip()
    print(f"######## {os.path.basename(d)} rc={rc}")
    try:
        a = json.load(open(os.path.join(d, "audit.json")))
    except Exception:
        a = {}
    stages = a.get("stages") or [a]
    for k, st in enumerate(stages):
        for r in st.get("pairs", []) + st.get("walls", []):
            lab = ("pair " + " ".join(map(str, r["types"]))) if "wall" not in r else f"wall {r['wall']} t{r['types']}"
            eps = ", ".join(f"{g:g}:{'' if e is None else '%.8f' % e}" for g, e in zip(r["speeds"], r["eps"]))
            extra = f" sizes={r.get('sizes')}" if r.get("sizes") else ""
            print(f"  s{k+1} {lab}: {r['model'][:90]} | {r.get('end')} | D1={r.get('D1')} D2={r.get('D2')} a={r.get('alpha')} g={r.get('gamma')} dt={r.get('dt')} | {eps}{extra}"[:600])
    for ln in open(os.path.join(d, "audit.err")):
        if not any(s in ln for s in SKIP):
            print("  ERR " + ln.strip()[:420])
