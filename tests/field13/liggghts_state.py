"""Field round 13: what LIGGGHTS holds at a deck's end (the tool: tests/fieldkit/liggghts_state.py, which says how it works).
usage: python liggghts_state.py DECKDIR DECK"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts_state  # noqa: E402

liggghts_state.main(sys.argv[1:])
