"""Sweep 32: markdown lists of the folders of some outcomes (summarize.py's output) with the engine's value, the
new last-stage rows of the live pair, the refusal's first words and the judgement.
usage: python lists.py OUTCOME_FILE COPYDIR 'outcome' ...
"""
import os
import re
import sys


def main(argv):
    out, C, want = argv[0], argv[1], argv[2:]
    rows = {}
    for r in (27, 28, 29, 30, 31):
        f = os.path.join(C, f"sweep{r}.tsv")
        if os.path.exists(f):
            for l in open(f):
                p = l.rstrip("\n").split("\t")
                rows[(p[0], p[1])] = p
    for w in want:
        print(f"\n### {w}\n")
        for l in open(out):
            m = re.match(r"(\d+) (\S+) => (.*?) \| (.*)", l)
            if not m or m.group(3) != w:
                continue
            r, n, _, why = m.groups()
            p = rows.get((r, n))
            rest = p[6].lstrip("| ") if p else ""
            parts = [x.strip() for x in rest.split(" | ")]
            live = parts[0] if parts else ""
            e = re.search(r"LIVE\d+ eps (\S+)", live)
            now = parts[1] if len(parts) > 1 else ""
            d = os.path.join(C, f"field{r}", "decks", n)
            rc = open(os.path.join(d, "audit.rc")).read().strip()
            ref = ""
            if rc == "2":
                err = [x for x in open(os.path.join(d, "audit.err")).read().splitlines() if x.startswith("restitution:")]
                ref = "; refusal: " + (err[-1][13:160] if err else "?")
            eng = e.group(1)[:9] if e else (live[:40] or "-")
            print(f"- {r} {n}: engine {eng}; now rc {rc}, {now}{ref} || {why[:400]}")


if __name__ == "__main__":
    main(sys.argv[1:])
