"""Field round 28: the audit's g-1 rows of each stage of a deck folder (audit.out) for a pair or wall name; a range (rows
'smallest'/'largest' over the sizes present) is printed lo..hi; '*' marks a row flagged 'does not happen here'.
usage: python rows28.py DECKDIR [NAME=types 1 2] [G=1]"""
import re, sys
d = sys.argv[1]; want = sys.argv[2] if len(sys.argv) > 2 else "types 1 2"; G = sys.argv[3] if len(sys.argv) > 3 else "1"
st, name, res, stages = 0, None, {}, 0
for l in open(d + "/audit.out"):
    if l.startswith("# stage"):
        st += 1
        stages = int(l.split()[4].rstrip(":")) if l.split()[3] == "of" else stages
    elif not l.startswith(" "):
        m = re.match(r"(types \d+ \d+|type \d+ on wall [^:\s]+)", l)
        name = (m.group(1) + ("*" if "does not happen" in l else "")) if m else None
    elif l.split()[:2] == ["g", G] and name and name.rstrip("*") == want:
        res.setdefault(st, []).append(l.split()[3] + ("*" if name.endswith("*") else ""))
last = max(stages, st)
print(" ".join(f"s{k}:{'..'.join(v)}" for k, v in res.items()) or "-", f"(stages {last})")
