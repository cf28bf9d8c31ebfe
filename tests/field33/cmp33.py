"""Field round 33: the live pair's eps (live*.log, the deck run as written) beside the audit's rows for that pair in every
stage (audit.out); flags where the last stage differs by more than 0.004 (the tool: tests/fieldkit/cmp.py, `live`,
which says how it works). usage: python cmp33.py"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import cmp  # noqa: E402

cmp.live(os.path.dirname(os.path.abspath(__file__)), tag="LIVE33", pair=lambda n: open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks", n, "PAIR")).read().strip() if os.path.exists(os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks", n, "PAIR")) else "types 1 2")
