"""Field round 26: lprobe26.py run in chunks of 10 steps until the pair parts (the tool: tests/fieldkit/lprobe.py, which says how it works).
usage: python lprobe26s.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [Z]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import lprobe  # noqa: E402

lprobe.pair(sys.argv[1:], round=26, var="f24", tag="LPROBE26", chunks=True)
