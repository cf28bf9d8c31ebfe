"""Field round 20: eps of one head-on collision in LAMMPS at given time steps (the tool: tests/fieldkit/dtcheck.py).
usage: python dtcheck20.py DT [DT ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import dtcheck  # noqa: E402

dtcheck.main(sys.argv[1:])
