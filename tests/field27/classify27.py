"""Field round 27: the outcome table. judged27.txt (by hand, from the engine's own values) first; the rest from cmp27.out
(the live pair measured in the deck as written agrees with the audit's last stage). usage: python classify27.py"""
import collections, os, re, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402
H = os.path.dirname(os.path.abspath(__file__)); D = os.path.join(H, "decks")
J = classify.judged(os.path.join(H, "judged27.txt"))
ok = set()
for l in open(os.path.join(H, "cmp27.out")):
    p = l.split()
    if len(p) > 2 and p[2] in ("ok", "ok(no"):
        ok.add(p[0])
table = collections.defaultdict(list)
for n in sorted(os.listdir(D)):
    k = classify.key(n)
    if k in J:
        table[J[k]].append(k)
    elif n in ok:
        table["correct, engine-checked (live pair)"].append(k)
    elif n.startswith("X_lig"):
        table["LIGGGHTS tutorial (see FINDINGS)"].append(n[6:])
    else:
        table["UNJUDGED"].append(k)
for cls, names in sorted(table.items(), key=lambda x: (not x[0].startswith(("SIL", "FALSE", "WRONG", "AVOID")), x[0])):
    print(f"| {cls} | {len(names)} | {' '.join(names)} |")
print("total", sum(len(v) for v in table.values()))
