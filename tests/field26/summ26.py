"""Field round 26: one line per deck folder: audit rc, engine's line, last-stage g = 1 rows, the refusal (the tool: tests/fieldkit/summary.py, which says how it works).
usage: python summ26.py DECKDIR ..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import summary  # noqa: E402

summary.by_line(sys.argv[1:])
