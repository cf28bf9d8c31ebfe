"""Field round 24: one block per deck folder: engine rc/PROBE lines, audit rc, the last stage's g = 1 rows, stderr notes (cut).
usage: python summ24.py [NAME ...]"""
import json, os, sys
D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
for n in sys.argv[1:] or sorted(os.listdir(D)):
    d = os.path.join(D, n)
    eng = open(os.path.join(d, "ENGINE.txt")).read().strip().replace("\n", " | ") if os.path.exists(os.path.join(d, "ENGINE.txt")) else "?"
    rc = open(os.path.join(d, "audit.rc")).read().strip()
    out = open(os.path.join(d, "audit.out")).read().splitlines()
    err = open(os.path.join(d, "audit.err")).read().splitlines()
    rows, cur = [], None
    for l in out:
        if l.startswith("# stage"):
            rows = []; cur = l[:40]
        elif not l.startswith(" "):
            cur2 = l.split(":")[0]
        elif l.strip().startswith("g 1 "):
            rows.append(f"{cur2}={l.split()[3]}")
    print(f"== {n}  audit rc={rc}\n  ENGINE: {eng[:400]}\n  AUDIT: {' ; '.join(rows)}")
    for l in err:
        if "fix gravity" in l or "steps per contact" in l or "a contact lasts" in l:
            continue
        print("  ERR:", l[:300])
