"""Field round 25: the eps LAMMPS gives a sphere on a deck's zplane-0 floor (the tool: tests/fieldkit/wprobe.py, which says how it works).
usage: python wprobe25.py DECKDIR T D RHO GRAVID [G]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import wprobe  # noqa: E402

wprobe.floor(sys.argv[1:], round=25, var="f24", tag="PROBE25")
