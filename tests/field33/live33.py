"""Field round 33: the eps LAMMPS (or LIGGGHTS) gives the deck's own live pair, the deck run AS WRITTEN (the tool:
tests/fieldkit/live.py, which says how it works), the step error as the tool says. Two changes of this round's: a
folder's GROUPS file names the two groups to print (default lv1 lv2: a sphere made again at a new ID is put in a group
of its own by the deck), and a LIGGGHTS deck is printed by those groups (vcm, xcm) rather than by atoms 1 and 2; an AXIS file names the axis the pair meets along (default x).
usage: python live32.py DECKDIR ..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import live  # noqa: E402

_orig = live._tail


def _tail(d, var, tag):
    lig, tail = _orig(d, var, tag)
    gf = os.path.join(d, "GROUPS")
    a, b = open(gf).read().split() if os.path.exists(gf) else ("lv1", "lv2")
    if "WALL" in open(os.path.join(d, "LIVE")).read():
        return lig, tail
    if lig:
        sep = float(open(os.path.join(d, "SEP")).read()) if os.path.exists(os.path.join(d, "SEP")) else 0.005
        tail = (f"\nvariable {var}e equal vcm({b},x)-vcm({a},x)\nvariable {var}g equal xcm({b},x)-xcm({a},x)-{sep}\n"
                f"print \"{tag} eps ${{{var}e}} gap ${{{var}g}} n $(atoms)\"\n")
    else:
        tail = tail.replace("(lv1,", f"({a},").replace("(lv2,", f"({b},")
    if os.path.exists(os.path.join(d, "AXIS")):    # the pair meets along this axis (round 33: z, across a bin face)
        ax = open(os.path.join(d, "AXIS")).read().strip()
        tail = tail.replace(",x)", f",{ax})")
    return lig, tail


live._tail = _tail
live.main(sys.argv[1:], round=33, var="l33", tag="LIVE33")
