"""Field round 16: the sizes and masses LAMMPS holds after each run of a deck (the tool: tests/fieldkit/engine_stages.py, which says how it works).
usage: python engine_stages.py DECKDIR [DECK]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import engine_stages  # noqa: E402

engine_stages.main(sys.argv[1:], round=16)
