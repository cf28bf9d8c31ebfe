"""Field round 16: the eps LIGGGHTS measures from many starting gaps with a deck's neighbour lines (the tool:
tests/fieldkit/liggghts_neighbor.py, which says how it works). usage: python liggghts_neighbor16.py SPEC.json"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts_neighbor  # noqa: E402

if __name__ == "__main__":
    liggghts_neighbor.main(sys.argv[1:])
