"""Field round 47a: each P/R folder's referee eps (live3/live4.log, the last line for it) beside the audit's row for
the live pair (LIVE below) at the referee's speed (the first --g of the folder's G), the range the audit's time-step
note gives at the deck's dt ("eps there A to B"), and its gravity note's value where it gives one. Flag: ok where the
referee lies in [A - 0.002, B + 0.002] (or within 0.002 of the row where no range is given), else CHECK.
usage: python cmp47.py DECKDIR ...   (from tests/field47a)"""
import os
import re
import sys

LIVE = {"P02": "type 1 on wall zwalls1", "P04": "type 1 on wall zwalls1", "P06": "type 1 on wall granwalls",
        "P11": "type 1 on wall plug", "P13": "type 1 on wall zwall", "P15": "type 1 on wall zwall1",
        "P23": "type 1 on wall zwalls1", "P25": "type 1 on wall zwall1", "P26": "types 1 2", "P28": "types 1 2", "P29": "types 1 2", "P30": "type 1 on wall cylwalls", "P31": "type 1 on wall cylwalls", "P08": "types 1 2", "P16": "types 1 2", "P17": "types 2 2",
        "P10": "types 2 2", "P19": "types 1 2"}
ref = {}
for log in ("live3.log", "live4.log", "live6.log", "live7.log", "live8.log", "live9.log"):
    for l in open(log):
        m = re.search(r"PUB47 eps (\S+)", l)
        ref[l.split(" | ")[0]] = float(m.group(1)) if m else l.strip().split(" | ", 1)[1][:90]
for d in sys.argv[1:]:
    n = os.path.basename(d.rstrip("/"))
    live = LIVE.get(n[:3], "types 1 1")
    g = open(os.path.join(d, "G")).read().split()[0]
    rc = open(os.path.join(d, "audit.rc")).read().strip()
    rows, rng, grav = [], None, None
    head = None
    for l in open(os.path.join(d, "audit.out")):
        if not l.startswith(" "):
            head = l.strip()
        elif head.startswith(live) and l.split()[:2] == ["g", g]:
            rows.append(l.split()[3] if l.split()[2] == "eps" else " ".join(l.split()[2:4]))
    for l in open(os.path.join(d, "audit.err")):
        if l.startswith("restitution deck: " + live):
            m = re.search(r"(?:at g = " + re.escape(g) + r"|at every speed given) \(eps there (\S+) to (\S+)", l)
            if m and rng is None:
                rng = (float(m.group(1)), float(m.group(2)))
            m = re.search(r"gravity \S+ into it\): (\S+) at g = " + re.escape(g) + r" ", l)
            if m and grav is None:
                grav = float(m.group(1))
    r = ref.get(n)
    flag = "-"
    if isinstance(r, float) and rows:
        try:
            row = float(rows[0])
            lo, hi = rng if rng else (row, row)
            flag = "ok" if lo - 0.002 <= r <= hi + 0.002 else "CHECK"
        except ValueError:
            flag = "CHECK"
    print(f"{n:38s} rc {rc} | ref {r if not isinstance(r, float) else f'{r:.6f}'} | {live}: row {','.join(rows) or '-'}"
          f" | dt range {rng or '-'} | gravity {grav or '-'} | {flag}")
