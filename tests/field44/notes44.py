"""Field round 44: per deck folder, cmp44.out's line and the audit's stderr notes other than the usual ones (time-step
ranges, gravity on a wall contact, types with no particle, the stage count, the runs made for real), to judge each
deck by hand into judged44.txt.
usage: python notes44.py [NAME-PREFIX ...] > notes44.out"""
import os
import sys

H = os.path.dirname(os.path.abspath(__file__))
USUAL = ("at the deck's time step", "a gravity on the sphere, which pushes it", "has no particle", "the contact settings change between runs:",
         "made the deck's", "tsuji damping as LAMMPS")
cmp = {l.split()[0]: l.rstrip("\n") for l in open(os.path.join(H, "cmp44.out"))}
for n in sorted(os.listdir(os.path.join(H, "decks"))):
    if sys.argv[1:] and not any(n.startswith(p) for p in sys.argv[1:]):
        continue
    d = os.path.join(H, "decks", n)
    print("########", cmp.get(n, n + " (not in cmp44.out)")[:400])
    print("   ", open(os.path.join(d, "in.deck")).readline().strip()[:300])
    for l in open(os.path.join(d, "audit.err")):
        if "contact law changes" in l or not any(u in l for u in USUAL):
            print("   >", l.strip()[:600])
