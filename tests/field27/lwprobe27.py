"""Field round 27: the eps LIGGGHTS gives a sphere on a deck's zplane-0 wall (the tool: tests/fieldkit/lprobe.py, which says how it works).
usage: python lwprobe27.py DECKDIR T D RHO GRAVID [G]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import lprobe  # noqa: E402

lprobe.wall(sys.argv[1:], round=27, var="f26", tag="LPROBE26")
