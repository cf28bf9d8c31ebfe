"""Field round 26: the audit's stderr notes of deck folders without the routine ones (gravity on a wall contact, steps
per contact of a well-resolved contact, the stage count). usage: python notes26.py DECKDIR ..."""
import os, re, sys
SKIP = ("a gravity on the sphere", "the contact settings change between runs:", "no part in a head-on contact")
for d in sys.argv[1:]:
    print("==", os.path.basename(d.rstrip("/")), open(os.path.join(d, "audit.rc")).read().strip())
    for l in open(os.path.join(d, "audit.err")):
        l = l.strip().replace("restitution deck: ", "")
        if any(s in l for s in SKIP):
            continue
        m = re.search(r"a contact lasts ([\d.]+) steps", l)
        if m and float(m.group(1)) >= 20:
            continue
        print("  ", l[:400])
