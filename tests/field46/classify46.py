"""Field round 46: the outcome table: judged46.txt's outcome for the decks judged by hand, `ok` in cmp46.out for the rest.
usage: python classify45.py > classify46.out"""
import collections
import os

H = os.path.dirname(os.path.abspath(__file__))
names = set(os.listdir(os.path.join(H, "decks")))
out = collections.OrderedDict()
judged = {}
for l in open(os.path.join(H, "judged46.txt")):
    if l.strip() and not l.startswith("#"):
        n, o = l.split()[:2]; o = o.rstrip(":")
        judged[n] = o + (" " + l.split()[2].rstrip(":") if o in ("SILENTLY-WRONG", "AVOIDABLE-REFUSAL", "BOTH-STOP-WRONG-REASON", "WRONG-NOTE") else "")
for l in open(os.path.join(H, "cmp46.out")):
    n = l.split()[0]
    if n not in names:
        continue
    o = judged.get(n) or ("CORRECT (engine-checked)" if (" ok " in l or " ok(no contact) " in l) else "UNJUDGED " + l.split()[2])
    out.setdefault(o, []).append(n.split("_")[0])
tot = 0
for o, ns in sorted(out.items()):
    print(f"{o:45s} {len(ns):3d}  {' '.join(ns)}")
    tot += len(ns)
print(f"{'total':45s} {tot:3d}")
