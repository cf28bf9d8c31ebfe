"""Field round 28: the outcome table. judged28.txt (by hand, from the engine's own values) first; the rest from cmp28.out
(the live pair measured in the deck as written agrees with the audit's last stage). usage: python classify28.py"""
import collections, os, re
H = os.path.dirname(os.path.abspath(__file__)); D = os.path.join(H, "decks")
J = {}
for line in open(os.path.join(H, "judged28.txt")):
    if line.strip() and not line.startswith("#"):
        cls, names = line.rsplit(" => ", 1)
        for n in names.split():
            J[n] = cls.strip()
ok = set()
for l in open(os.path.join(H, "cmp28.out")):
    p = l.split()
    if len(p) > 2 and p[2] in ("ok", "ok(no"):
        ok.add(p[0])
table = collections.defaultdict(list)
for n in sorted(os.listdir(D)):
    k = n if n.startswith("X_lig") else n.split("_")[0]
    if k in J:
        table[J[k]].append(k)
    elif n in ok:
        table["correct, engine-checked (live pair)"].append(k)
    elif n.startswith("X_lig"):
        table["LIGGGHTS tutorial (see FINDINGS)"].append(n[6:])
    else:
        table["UNJUDGED"].append(k)
ORDER = ("SIL", "ANSWERED", "ROWS", "WRONG", "left out", "FALSE", "AVOID")   # worst first, then the rest by name
rank = lambda c: next((k for k, p in enumerate(ORDER) if c.startswith(p)), len(ORDER))
for cls, names in sorted(table.items(), key=lambda x: (rank(x[0]), x[0])):
    print(f"| {cls} | {len(names)} | {' '.join(names)} |")
print("total", sum(len(v) for v in table.values()))
