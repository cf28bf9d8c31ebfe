"""Field round 46: per deck folder, cmp46.out's line and the audit's stderr notes other than the usual ones (time-step
ranges, gravity on a wall contact, types with no particle, the stage count, the runs made for real), to judge each
deck by hand into judged46.txt.
usage: python notes45.py [NAME-PREFIX ...] > notes46.out"""
import os
import sys

H = os.path.dirname(os.path.abspath(__file__))
USUAL = ("at the deck's time step", "a gravity on the sphere, which pushes it", "has no particle", "the contact settings change between runs:",
         "made the deck's", "tsuji damping as LAMMPS")
cmp = {l.split()[0]: l.rstrip("\n") for l in open(os.path.join(H, "cmp46.out"))}
for n in sorted(os.listdir(os.path.join(H, "decks"))):
    if sys.argv[1:] and not any(n.startswith(p) for p in sys.argv[1:]):
        continue
    d = os.path.join(H, "decks", n)
    print("########", cmp.get(n, n + " (not in cmp46.out)")[:400])
    deck = open(os.path.join(d, "DECK")).read().strip() if os.path.exists(os.path.join(d, "DECK")) else "in.deck"
    if not n.startswith("P"):     # the public decks' own text is not copied here
        print("   ", open(os.path.join(d, deck), encoding="latin-1").readline().strip()[:300])
    for l in open(os.path.join(d, "audit.err")):
        if "contact law changes" in l or not any(u in l for u in USUAL):
            print("   >", l.strip()[:600])
