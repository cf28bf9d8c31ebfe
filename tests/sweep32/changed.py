"""Sweep 32: the deck folders whose audit changed against their round's stored audit, grouped by kind of change
(changes.py's kinds) and by the live pair's flag before -> now (fieldkit.cmp.live).
usage: python changed.py sweepNN.tsv ...
"""
import collections
import sys


def main(argv):
    g = collections.defaultdict(list)
    for f in argv:
        for l in open(f):
            p = l.rstrip("\n").split("\t")
            r, n, rc, flag, kinds = p[0], p[1], p[2], p[3], p[4]
            if kinds == "same":
                continue
            k = kinds if kinds in ("notes", "json-only") else f"{kinds}; {rc}; {flag}"
            g[k].append(f"{r}:{n.split('_')[0]}")
    for k in sorted(g, key=lambda k: (k in ("notes", "json-only"), k)):
        print(f"- {k} ({len(g[k])}): {' '.join(g[k])}")


if __name__ == "__main__":
    main(sys.argv[1:])
