"""Field round 16: the eps LAMMPS measures for a head-on pair approaching from a gap with a deck's neighbour settings (the tool:
tests/fieldkit/neighbor_check.py, which says how it works). usage: python neighbor_check16.py SPEC.json"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import neighbor_check  # noqa: E402

neighbor_check.main(sys.argv[1:])
