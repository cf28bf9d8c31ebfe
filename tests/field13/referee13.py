"""Field round 13: the spec referee: round 10's head-on referee run one check of spec.json at a time (the tool:
tests/fieldkit/spec_referee.py, which says how it works). usage: python referee13.py DECKDIR   (writes DECKDIR/referee.txt)"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import spec_referee  # noqa: E402

if __name__ == "__main__":
    spec_referee.main(sys.argv[1])
