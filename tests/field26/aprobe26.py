"""Field round 26: the eps LAMMPS gives a pair approaching from a gap at the deck's own time step (the tool: tests/fieldkit/probe.py, which says how it works).
usage: python aprobe26.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [GAP] [STEPS] [Z]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import probe  # noqa: E402

probe.approach(sys.argv[1:], round=26, var="f26", tag="APROBE26")
