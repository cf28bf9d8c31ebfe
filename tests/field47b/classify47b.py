"""Field round 47b: the outcome table from cmp47b.out (the kit's flags) and judged47b.txt (every folder not flagged ok
or ok(no contact), judged by hand). usage: python classify47b.py > classify47b.out"""
import collections
import os
H = os.path.dirname(os.path.abspath(__file__))
judged = {}
for l in open(os.path.join(H, "judged47b.txt")):
    if l.strip() and not l.startswith("#"):
        n, o = l.split()[:2]; o = o.rstrip(":")
        judged[n] = o + (" " + l.split()[2].rstrip(":") if l.split()[2].isupper() and "-" in l.split()[2] else "")
out = collections.defaultdict(list)
for l in open(os.path.join(H, "cmp47b.out")):
    n, flag = l.split()[0], l.split()[2]
    if n in judged:
        out[judged.pop(n)].append(n)
    elif flag in ("ok", "ok(no"):
        out["CORRECT (kit: " + flag.replace("ok(no", "ok(no contact)") + ")"].append(n)
    else:
        out["UNJUDGED " + flag].append(n)
for k in judged:
    out["JUDGED-NOT-IN-CMP"].append(k)
for k in sorted(out):
    print(f"{k} | {len(out[k])} | {' '.join(sorted(x.split('_')[0] for x in out[k]))}")
print("total |", sum(len(v) for v in out.values()))
