"""Field round 37: every audited deck's --json against its text rows (the tool: tests/fieldkit/jsoncheck.py, which says how it works).
usage: python jsoncheck37.py"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import jsoncheck  # noqa: E402

jsoncheck.main(os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks"))
