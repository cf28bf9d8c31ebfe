"""Field round 22: one block per deck folder: engine lines, audit rc, the last stage's g = 1 rows, stderr notes (the tool: tests/fieldkit/summary.py, which says how it works).
usage: python summ22.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import summary  # noqa: E402

summary.by_block(sys.argv[1:], decks=os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks"))
