"""Field round 25: the eps LIGGGHTS gives a head-on pair with the contact settings a deck leaves it holding (the tool: tests/fieldkit/lprobe.py, which says how it works).
usage: python lprobe25.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [Z]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import lprobe  # noqa: E402

lprobe.pair(sys.argv[1:], round=25, var="f24", tag="LPROBE25")
