"""The referee lines (refereeNN.py output, rounds 23-26) where the engine's eps and the audit's differ by more than
2e-5 (or either is missing). usage: python cmpNN.py referee*.log   (`tag`: the round's probe tag, e.g. PROBE26)
"""
import re


def main(argv, *, tag):
    """Print ok/DIFF for each referee line of the log files `argv`."""
    for f in argv:
        for l in open(f):
            m = re.match(rf"(\S+) (\d) (\d) {tag} eps (\S+) .*\| audit (\S+)", l)
            if not m:
                print("?", l.strip()[:220]); continue
            n, t, u, e, a = m.groups()
            try:
                ok = abs(float(e) - float(a)) <= 2e-5
            except ValueError:
                ok = False
            print(("ok  " if ok else "DIFF"), n, t, u, "engine", e, "audit", a)
