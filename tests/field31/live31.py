"""Field round 31: the eps LAMMPS (or LIGGGHTS) gives the deck's own live pair, the deck run AS WRITTEN (the tool:
tests/fieldkit/live.py, which says how it works), the step error as the tool says.
usage: python live31.py DECKDIR ..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import live  # noqa: E402

live.main(sys.argv[1:], round=31, var="l31", tag="LIVE31")
