"""Field round 28: the eps LAMMPS gives a head-on pair with the contact settings a deck leaves it holding (the tool: tests/fieldkit/probe.py, which says how it works).
usage: python probe28.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [Z] [XC] [DT]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import probe  # noqa: E402

probe.pair(sys.argv[1:], round=28, var="f24", tag="PROBE26")
