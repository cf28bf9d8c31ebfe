"""Field round 24: probe24 with the spheres GAP apart (env GAP, default 0.002), found by the deck's neighbor settings (the tool: tests/fieldkit/probe.py, which says how it works).
usage: python gprobe24.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [Z] [XC] [DT]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import probe  # noqa: E402

probe.pair(sys.argv[1:], round=24, var="f24", tag="PROBE24", gap=True)
