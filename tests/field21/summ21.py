"""Field round 21: one line per audited row of each deck, the rc and the stderr notes (the tool: tests/fieldkit/summary.py, which says how it works).
usage: python summ21.py DECKDIR ..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import summary  # noqa: E402

summary.by_row(sys.argv[1:], detail=True)
