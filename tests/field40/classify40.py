"""Field round 40: the outcome table from cmp40.out (engine-checked rows) and judged40.txt (decks judged by hand).
usage: python classify40.py > classify40.out"""
import collections
import os

HERE = os.path.dirname(os.path.abspath(__file__))
judged = {}
for l in open(os.path.join(HERE, "judged40.txt")):
    if l.strip() and not l.startswith("#"):
        n, c = l.split()[:2]
        judged[n] = c
out = collections.defaultdict(list)
for l in open(os.path.join(HERE, "cmp40.out")):
    name = l.split()[0]
    key = next((k for k in judged if name == k or name.startswith(k + "_")), None)
    if key:
        out[judged[key]].append(name.split("_")[0] if key == name.split("_")[0] else key)
    elif " ok " in l or " ok(no contact)" in l:
        out["CORRECT (engine-checked)"].append(name.split("_")[0] if not name.startswith("C0") else name)
    else:
        out["UNJUDGED"].append(name)
tot = 0
for c in sorted(out):
    print(f"{c:28s} {len(out[c]):3d}  {' '.join(out[c])}")
    tot += len(out[c])
print(f"{'total':28s} {tot:3d}")
