"""Field round 17: round 16's LIGGGHTS drop on a mesh floor with the mesh's fix line given (the tool: tests/fieldkit/liggghts_neighbor.py).
usage: python liggghts_meshline17.py STL "MESH LINE" G GAP..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import liggghts_neighbor  # noqa: E402

liggghts_neighbor.with_line(sys.argv[2], float(sys.argv[3]), [float(x) for x in sys.argv[4:]], stl=sys.argv[1])
