"""Field round 30: the deck's own pair in a public restitution variant (PUBLIVE: groups a b, axis), the deck run AS
WRITTEN in LAMMPS (the tool: tests/fieldkit/live.py, `public`, which says how it works).
usage: python publive30.py DECKDIR ..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import live  # noqa: E402

live.public(sys.argv[1:], round=30)
