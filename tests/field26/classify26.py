"""Field round 26: the outcome table. Each deck folder gets the class judged in FINDINGS.md (the dict J below, written
by hand from the engine's own values: referee logs, ENGINE.txt, state26); folders not in J whose every referee line
agrees within 2.5e-5 (LAMMPS probe26 at dt 1e-8 s) or 1e-4 (LIGGGHTS lprobe26/lprobe26s at dt 1e-7 s, its step error)
are 'correct, engine-checked'. usage: python classify26.py"""
import collections, glob, os, re, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify, referee  # noqa: E402
H = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(H, "decks")
ok, bad = collections.defaultdict(int), collections.defaultdict(int)
for f in glob.glob(os.path.join(H, "*.log")):
    for l in open(f, errors="replace"):
        m = re.match(r"(\S+) (\d) (\d) L?PROBE26 eps (\S+).*\| audit (\S+)", l)
        lig = re.match(r"(\S+) (\d) (\d) LPROBE26 eps (\S+)\s*$", l)
        if m:
            n, e, a = m.group(1), m.group(4), m.group(5)
            try:
                (ok if abs(float(e) - float(a)) <= 2.5e-5 else bad)[n] += 1
            except ValueError:
                bad[n] += 1
        elif lig:
            n, t, u, e = lig.groups()
            rows = referee.audit_rows(os.path.join(D, n, "audit.out"))
            try:
                (ok if abs(float(e) - float(rows.get(f"types {t} {u}"))) <= 1e-4 else bad)[n] += 1
            except (TypeError, ValueError):
                bad[n] += 1
J = classify.judged(os.path.join(H, "judged26.txt"))
table = collections.defaultdict(list)
for n in sorted(os.listdir(D)):
    k = classify.key(n)
    if k in J:
        table[J[k]].append(n)
    elif ok[n] and not bad[n]:  # every referee line of the deck agrees
        table["correct-engine"].append(n)
    else:
        table["UNJUDGED"].append(n)
for cls, names in sorted(table.items()):
    print(f"| {cls} | {len(names)} | {' '.join(x.split('_')[0] if not x.startswith('X_lig') else x[6:] for x in names)} |")
print("total", sum(len(v) for v in table.values()))
