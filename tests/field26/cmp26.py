"""Field round 26: the referee lines (referee26.py output) where the engine's eps and the audit's differ by more than 2e-5
(or either is missing). usage: python cmp24.py referee*.log"""
import re, sys
for f in sys.argv[1:]:
    for l in open(f):
        m = re.match(r"(\S+) (\d) (\d) PROBE26 eps (\S+) .*\| audit (\S+)", l)
        if not m:
            print("?", l.strip()[:220]); continue
        n, t, u, e, a = m.groups()
        try:
            ok = abs(float(e) - float(a)) <= 2e-5
        except ValueError:
            ok = False
        print(("ok  " if ok else "DIFF"), n, t, u, "engine", e, "audit", a)
