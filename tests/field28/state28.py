"""Field round 28: the atoms LAMMPS holds at a deck's end (the tool: tests/fieldkit/state.py, which says how it works).
usage: python state28.py DECKDIR"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import state  # noqa: E402

state.main(sys.argv[1:], round=28, var="f24", tag="STATE24")
