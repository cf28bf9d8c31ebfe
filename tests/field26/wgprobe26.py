"""Field round 26: the eps LAMMPS gives a sphere on any wall of a deck (the tool: tests/fieldkit/wprobe.py, which says how it works).
usage: python wgprobe26.py DECKDIR T D RHO GRAVID X Y Z NX NY NZ [G] [DT]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import wprobe  # noqa: E402

wprobe.any_wall(sys.argv[1:], round=26, var="f26", tag="PROBE26")
