"""Field round 27: the live pair's eps (live*.log, the deck run as written) beside the audit's rows for that pair in every
stage (audit.out); flags where the last stage differs by more than 0.004 (the tool: tests/fieldkit/cmp.py, `live`,
which says how it works). usage: python cmp27.py"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import cmp  # noqa: E402

# impact=False: cmp27.out was made with the wall decks' live speed unnormalised; judged27.txt divides it by the impact
# speed by hand (W01 W03 W09, CHECK here, ok with impact=True).
cmp.live(os.path.dirname(os.path.abspath(__file__)), tag="LIVE27", impact=False)
