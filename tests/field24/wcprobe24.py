"""Field round 24: the eps LAMMPS gives a sphere on a curved wall of a deck (the tool: tests/fieldkit/wprobe.py, which says how it works).
usage: python wcprobe24.py DECKDIR T D RHO GRAVID X Y Z S [G]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import wprobe  # noqa: E402

wprobe.curved(sys.argv[1:], round=24, var="f24", tag="PROBE24")
