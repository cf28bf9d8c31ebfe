"""Field round 21: one compact block per deck folder: rc, the engine's runs and PROBE lines, per stage the rows at the
speed nearest 1 (model cut short, eps), and the stderr notes other than the usual gravity / unused-type / stage-count ones.
usage: python brief21.py DECKDIR ..."""
import json, os, sys
SKIP = ("fix gravity (grav", "has no particle", "the contact settings change between runs", "at the deck's time step",
        "tsuji damping as LAMMPS", "no part in a head-on contact: tangential")
for d in sys.argv[1:]:
    d = d.rstrip("/")
    rc = open(os.path.join(d, "audit.rc")).read().strip()
    eng = open(os.path.join(d, "ENGINE.txt")).read().splitlines() if os.path.exists(os.path.join(d, "ENGINE.txt")) else []
    print(f"######## {os.path.basename(d)} rc={rc} | " + " / ".join(l.strip() for l in eng if l.startswith(("engine", "PROBE")) or "ERROR" in l)[:400])
    try:
        a = json.load(open(os.path.join(d, "audit.json")))
    except Exception:
        a = {}
    for k, st in enumerate(a.get("stages") or [a]):
        rows = []
        for r in st.get("pairs", []) + st.get("walls", []):
            lab = ("p" + "".join(map(str, r["types"]))) if "wall" not in r else f"w{r['wall']}{r['types']}"
            sp = [abs(x - 1.0) for x in r["speeds"]]
            e = r["eps"][sp.index(min(sp))]
            rows.append(f"{lab}={'None' if e is None else '%.5f' % e}" + (f"[{r.get('sizes')}]" if r.get("sizes") else ""))
        print(f"  s{k+1}: " + " ".join(rows)[:500])
        ms = sorted({r["model"][:80] for r in st.get("pairs", []) + st.get("walls", [])})
        print("     models: " + " || ".join(ms)[:400])
    for ln in open(os.path.join(d, "audit.err")):
        if not any(s in ln for s in SKIP):
            print("  ERR " + ln.strip()[:300])
