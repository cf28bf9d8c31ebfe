"""Field round 17: round 16's LIGGGHTS drop on a primitive floor with the floor's fix line given (the tool: tests/fieldkit/liggghts_neighbor.py).
usage: python liggghts_wallline17.py "WALL LINE" G GAP..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts_neighbor  # noqa: E402

liggghts_neighbor.with_line(sys.argv[1], float(sys.argv[2]), [float(x) for x in sys.argv[3:]])
