"""Field round 26: one line per deck folder: audit rc, engine's line, last-stage g = 1 rows (pair=eps), the first words
of the audit's stderr when it refuses. usage: python summ26.py DECKDIR ..."""
import os, sys
for d in sys.argv[1:]:
    n = os.path.basename(d.rstrip("/"))
    try:
        rc = open(os.path.join(d, "audit.rc")).read().strip()
    except OSError:
        print(n, "not audited"); continue
    eng = open(os.path.join(d, "ENGINE.txt")).readline().strip() if os.path.exists(os.path.join(d, "ENGINE.txt")) else "no engine"
    rows, name = {}, None
    for l in open(os.path.join(d, "audit.out")):
        if l.startswith("# stage"):
            rows = {}
        elif not l.startswith(" ") and not l.startswith("#"):
            name = l.split(":")[0].split(" [")[0].replace("types ", "").replace("type ", "t").replace(" on wall ", "@")
        elif l.split()[:2] == ["g", "1"]:
            rows[name] = l.split()[3][:8]
    err = open(os.path.join(d, "audit.err")).read()
    print(n, "rc", rc, "|", eng, "|", " ".join(f"{k}={v}" for k, v in rows.items()), "|", err.strip().splitlines()[-1][:200] if rc != "0" and err.strip() else "")
