"""Field round 42: the outcome table: judged42.txt's outcome for the decks judged by hand, `ok` in cmp42.out for the rest
(only the deck folders that exist: live1.log and cmp42.out also hold F17_wall_lj93_xhi_mid and F18_wall_harmonic_mid, the
first forms of F17 F18, whose walls LAMMPS refuses in a periodic x; they were made again as region walls).
usage: python classify42.py > classify42.out"""
import collections
import os

H = os.path.dirname(os.path.abspath(__file__))
names = set(os.listdir(os.path.join(H, "decks")))
out = collections.OrderedDict()
judged = {}
for l in open(os.path.join(H, "judged42.txt")):
    if l.strip() and not l.startswith("#"):
        n, o = l.split()[:2]; o = o.rstrip(":")
        judged[n] = o + (" " + l.split()[2].rstrip(":") if o in ("SILENTLY-WRONG", "AVOIDABLE-REFUSAL") else "")
for l in open(os.path.join(H, "cmp42.out")):
    n = l.split()[0]
    if n not in names:
        continue
    o = judged.get(n) or ("CORRECT (engine-checked)" if " ok " in l else "UNJUDGED " + l.split()[2])
    out.setdefault(o, []).append(n.split("_")[0])
tot = 0
for o, ns in sorted(out.items()):
    print(f"{o:45s} {len(ns):3d}  {' '.join(ns)}")
    tot += len(ns)
print(f"{'total':45s} {tot:3d}")
