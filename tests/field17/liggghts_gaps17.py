"""Field round 17: round 16's liggghts_neighbor16.py gap by gap (the tool: tests/fieldkit/liggghts_neighbor.py).
usage: python liggghts_gaps17.py SPEC.json"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts_neighbor  # noqa: E402

liggghts_neighbor.gap_by_gap(sys.argv[1:])
