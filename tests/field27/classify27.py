"""Field round 27: the outcome table. judged27.txt (by hand, from the engine's own values) first; the rest from cmp27.out
(the live pair measured in the deck as written agrees with the audit's last stage). usage: python classify27.py"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

# the silent, false, wrong and avoidable classes first, alike; then the rest by name
classify.outcome(os.path.dirname(os.path.abspath(__file__)), round=27, order=(("SIL", "FALSE", "WRONG", "AVOID"),))
