"""Field round 30: the audit's g-1 rows of each stage of a deck folder (audit.out) for a pair or wall name (the tool:
tests/fieldkit/rows.py, which says how it works).
usage: python rows30.py DECKDIR [NAME=types 1 2] [G=1]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import rows  # noqa: E402

rows.main(sys.argv[1:])
